// The optics of chapter 04 (rt/materials/optics.h): mirror reflection r = v - 2 (v.n) n.
// (Refraction and the Fresnel reflectance are chapter 05's.)
#include <catch2/catch.hpp>
#include <cmath>

#include "rt/materials/optics.h"

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

TEST_CASE("optics: reflecting twice gives the direction back, and the angle is kept", "[ch04]") {
    // A mirror is its own inverse, and the angle to the normal changes sign only.
    const vec3 n = rt::unit_vector(vec3(real(0.1), 1, real(0.2)));
    for (const vec3& v :
         {vec3(real(0.3), real(-0.8), real(0.52)), vec3(-1, real(-0.1), 0), vec3(0, -1, 0)}) {
        const vec3 once = rt::reflect(v, n), twice = rt::reflect(once, n);
        CAPTURE(v, once, twice);
        CHECK((twice - v).length() <= tight);
        CHECK(dot(once, n) == Approx(-dot(v, n)).margin(tight));
        // The tangential part is unchanged.
        CHECK((once - dot(once, n) * n - (v - dot(v, n) * n)).length() <= tight);
    }
}
