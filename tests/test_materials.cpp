// Metal and dielectric scattering, and the clear errors for bad material parameters.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>

#include "common/dielectric.h"
#include "common/error.h"
#include "common/lambertian.h"
#include "common/metal.h"
#include "common/optics.h"
#include "common/sphere.h"

using rt::color, rt::point3, rt::real, rt::vec3;

namespace {

// The hit of ray r on a unit sphere at the origin made of `mat`.
rt::hit_record hit_unit_sphere(const std::shared_ptr<rt::material>& mat, const rt::ray& r) {
    rt::sphere ball(point3(0, 0, 0), 1, mat);
    rt::hit_record rec;
    REQUIRE(ball.hit(r, rt::interval(0, rt::infinity), rec));
    return rec;
}

}  // namespace

TEST_CASE("metal: fuzz 0 is a perfect mirror weighted by the albedo", "[ch04]") {
    auto mirror = std::make_shared<rt::metal>(color(0.9, 0.5, 0.1), 0);
    rt::ray in(point3(-2, 2, 0), vec3(1, -1, 0));
    auto rec = hit_unit_sphere(mirror, in);
    rt::sampler s(3);
    s.start_pixel_sample(0, 0, 0);
    color attenuation;
    rt::ray out;
    REQUIRE(mirror->scatter(in, rec, s, attenuation, out));
    vec3 expected = rt::unit_vector(rt::reflect(in.direction(), rec.normal));
    CHECK(rt::unit_vector(out.direction()).x() == Approx(expected.x()).margin(1e-6));
    CHECK(rt::unit_vector(out.direction()).y() == Approx(expected.y()).margin(1e-6));
    CHECK(attenuation.x() == Approx(0.9));
    CHECK(attenuation.z() == Approx(0.1));
}

TEST_CASE("metal: fuzzed rays never leave below the surface", "[ch04]") {
    auto brushed = std::make_shared<rt::metal>(color(1, 1, 1), 1);
    // A grazing ray: many fuzzed directions point into the surface and must be absorbed.
    rt::ray in(point3(-3, 0.999, 0), vec3(1, 0, 0));
    auto rec = hit_unit_sphere(brushed, in);
    rt::sampler s(5);
    int absorbed = 0;
    for (int k = 0; k < 10000; ++k) {
        s.start_pixel_sample(0, 0, k);
        color attenuation;
        rt::ray out;
        if (brushed->scatter(in, rec, s, attenuation, out))
            CHECK(dot(out.direction(), rec.normal) > 0);
        else
            ++absorbed;
    }
    CHECK(absorbed > 0);  // the test would be empty if no ray went below
}

TEST_CASE("dielectric: head-on rays mostly refract, with probability 1 - R0", "[ch05]") {
    auto glass = std::make_shared<rt::dielectric>(1.5);
    rt::ray in(point3(0, 0, 5), vec3(0, 0, -1));
    auto rec = hit_unit_sphere(glass, in);
    rt::sampler s(11);
    const int n   = 100000;
    int reflected = 0;
    for (int k = 0; k < n; ++k) {
        s.start_pixel_sample(0, 0, k);
        color attenuation;
        rt::ray out;
        REQUIRE(glass->scatter(in, rec, s, attenuation, out));
        CHECK(attenuation.x() == 1);
        if (out.direction().z() > 0) ++reflected;
    }
    // Binomial(n, 0.04): standard deviation sqrt(n p (1 - p)) ~ 62; allow 5 of them.
    CHECK(std::abs(reflected - 0.04 * n) < 5 * std::sqrt(n * 0.04 * 0.96));
}

TEST_CASE("dielectric: total internal reflection inside glass reflects, no NaN",
          "[ch05][hardcase]") {
    auto glass = std::make_shared<rt::dielectric>(1.5);
    // From inside the unit sphere towards the surface at 60 degrees (critical angle 41.8).
    vec3 target(0, 1, 0);
    vec3 dir = rt::unit_vector(vec3(std::sin(1.047), std::cos(1.047), 0));
    rt::ray in(target - dir * 0.5, dir);
    auto rec = hit_unit_sphere(glass, in);
    REQUIRE_FALSE(rec.front_face);
    rt::sampler s(2);
    for (int k = 0; k < 1000; ++k) {
        s.start_pixel_sample(0, 0, k);
        color attenuation;
        rt::ray out;
        REQUIRE(glass->scatter(in, rec, s, attenuation, out));
        CHECK(std::isfinite(out.direction().x()));
        CHECK(dot(out.direction(), rec.normal) > 0);  // stays inside: reflected every time
    }
}

TEST_CASE("materials: bad parameters are refused with the value named", "[ch04][ch05]") {
    using Catch::Matchers::Contains;
    const real nan = std::numeric_limits<real>::quiet_NaN();
    CHECK_THROWS_WITH(rt::dielectric(0), Contains("0"));
    CHECK_THROWS_WITH(rt::dielectric(-1.5), Contains("-1.5"));
    CHECK_THROWS_AS(rt::dielectric(nan), rt::user_error);
    CHECK_THROWS_WITH(rt::metal(color(0.5, 0.5, 0.5), -0.1), Contains("-0.1"));
    CHECK_THROWS_WITH(rt::metal(color(0.5, 0.5, 0.5), 1.5), Contains("1.5"));
    CHECK_THROWS_AS(rt::metal(color(0.5, 0.5, 0.5), nan), rt::user_error);
    CHECK_THROWS_WITH(rt::metal(color(1.2, 0.5, 0.5), 0), Contains("1.2"));
    CHECK_THROWS_AS(rt::lambertian(color(-0.1, 0.5, 0.5)), rt::user_error);
    CHECK_NOTHROW(rt::metal(color(1, 1, 1), 1));
    CHECK_NOTHROW(rt::dielectric(1.0 / 1.5));  // an air bubble in glass is legal
}
