// Exact optics: mirror reflection, Snell refraction, total internal reflection, Schlick.
#include <catch2/catch.hpp>
#include <cmath>

#include "common/optics.h"

using rt::real, rt::vec3;

namespace {
// A few ulps of the unit vectors involved; every formula here is a handful of operations.
constexpr double tight = 1e-6;
}  // namespace

TEST_CASE("optics: reflect mirrors about the normal", "[ch04]") {
    vec3 r = rt::reflect(vec3(1, -1, 0), vec3(0, 1, 0));
    CHECK(r.x() == 1);
    CHECK(r.y() == 1);
    CHECK(r.z() == 0);
    // Straight down comes straight back up; the length is kept.
    vec3 back = rt::reflect(vec3(0, -2, 0), vec3(0, 1, 0));
    CHECK(back.y() == 2);
    vec3 oblique(0.3, -0.8, 0.52);
    CHECK(rt::reflect(oblique, rt::unit_vector(vec3(0.1, 1, 0.2))).length() ==
          Approx(oblique.length()).epsilon(tight));
}

TEST_CASE("optics: refract at normal incidence goes straight on", "[ch05]") {
    for (real eta : {real(1) / real(1.5), real(1), real(1.5)}) {
        vec3 t = rt::refract(vec3(0, -1, 0), vec3(0, 1, 0), eta);
        CHECK(t.x() == Approx(0).margin(tight));
        CHECK(t.y() == Approx(-1).epsilon(tight));
        CHECK(t.z() == Approx(0).margin(tight));
    }
}

TEST_CASE("optics: index ratio 1 passes straight through at any angle", "[ch05]") {
    for (real angle : {real(0.1), real(0.7), real(1.3), real(1.55)}) {
        vec3 in(std::sin(angle), -std::cos(angle), 0);
        vec3 t = rt::refract(in, vec3(0, 1, 0), 1);
        CHECK(t.x() == Approx(in.x()).margin(tight));
        CHECK(t.y() == Approx(in.y()).margin(tight));
        CHECK_FALSE(rt::total_internal_reflection(std::cos(angle), 1));
    }
}

TEST_CASE("optics: refraction obeys Snell's law", "[ch05]") {
    const real eta = real(1) / real(1.5);  // air into glass
    for (real angle : {real(0.2), real(0.6), real(1.0), real(1.4)}) {
        vec3 in(std::sin(angle), -std::cos(angle), 0);
        vec3 t = rt::refract(in, vec3(0, 1, 0), eta);
        CHECK(t.length() == Approx(1).epsilon(tight));
        // sin(theta_t) = eta sin(theta_i), read off the tangential component.
        CHECK(t.x() == Approx(eta * std::sin(angle)).epsilon(tight));
        CHECK(t.y() < 0);
    }
}

TEST_CASE("optics: at and past the critical angle there is no NaN", "[ch05][hardcase]") {
    const real eta      = real(1.5);  // glass into air
    const real critical = std::asin(1 / eta);
    // Just inside the critical angle: still refracts, grazing the surface.
    real before = critical * (1 - real(1e-6));
    CHECK_FALSE(rt::total_internal_reflection(std::cos(before), eta));
    vec3 t = rt::refract(vec3(std::sin(before), -std::cos(before), 0), vec3(0, 1, 0), eta);
    CHECK(std::isfinite(t.x()));
    CHECK(std::isfinite(t.y()));
    CHECK(t.length() == Approx(1).epsilon(1e-5));
    // Past it: total internal reflection is reported...
    for (real past : {critical * (1 + real(1e-6)), critical + real(0.1), real(1.5)}) {
        CHECK(rt::total_internal_reflection(std::cos(past), eta));
        // ...and even a caller that refracted anyway gets a finite direction, not a NaN.
        vec3 forced = rt::refract(vec3(std::sin(past), -std::cos(past), 0), vec3(0, 1, 0), eta);
        CHECK(std::isfinite(forced.x()));
        CHECK(std::isfinite(forced.y()));
    }
}

TEST_CASE("optics: Schlick gives R0 head-on and 1 at grazing", "[ch05]") {
    // R0 = ((1 - 1.5) / (1 + 1.5))^2 = 0.04, the same from either side.
    CHECK(rt::schlick_reflectance(1, real(1) / real(1.5)) == Approx(0.04).epsilon(tight));
    CHECK(rt::schlick_reflectance(1, real(1.5)) == Approx(0.04).epsilon(tight));
    CHECK(rt::schlick_reflectance(0, real(1.5)) == Approx(1).epsilon(tight));
    CHECK(rt::schlick_reflectance(0, real(1) / real(1.5)) == Approx(1).epsilon(tight));
    // Monotonic in between: more reflection at more grazing angles.
    real previous = 0;
    for (real c = 1; c >= 0; c -= real(0.125)) {
        real r = rt::schlick_reflectance(c, real(1.5));
        CHECK(r >= previous);
        previous = r;
    }
}
