// Tests for dielectric.h (chapter 05): each hit reflects or refracts, chosen with the Fresnel
// reflectance (Schlick's, or the exact one) as the probability; clear glass absorbs nothing;
// total internal reflection always reflects; 1 sampler dimension per scatter; and the clear
// error for a bad index.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>

#include "rt/core/error.h"
#include "rt/geometry/sphere.h"
#include "rt/materials/dielectric.h"
#include "rt/materials/optics.h"
#include "rt/materials/refraction.h"
#include "rt/samplers/independent_sampler.h"
#include "test_helpers.h"

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

TEST_CASE("dielectric: head-on rays mostly refract, with probability 1 - R0", "[ch05]") {
    // R0 = 0.04 for both models (test_optics), so 4% of the rays come back.
    for (auto model : {rt::fresnel_model::schlick, rt::fresnel_model::exact}) {
        auto glass = std::make_shared<rt::dielectric>(1.5, model);
        rt::ray in(point3(0, 0, 5), vec3(0, 0, -1));
        auto rec = hit_unit_sphere(glass, in);
        rt::independent_sampler s(11);
        const int n   = 100000;
        int reflected = 0, not_clear = 0;
        for (int k = 0; k < n; ++k) {
            s.start_pixel_sample(0, 0, k);
            const auto sample = glass->scatter(in, rec, s);
            REQUIRE(sample);
            if (!rt_test::exactly(sample->weight, color(1, 1, 1))) ++not_clear;
            if (sample->scattered.direction().z() > 0) ++reflected;
        }
        INFO((model == rt::fresnel_model::exact ? "exact" : "schlick")
             << ": " << reflected << " of " << n << " reflected");
        CHECK(not_clear == 0);
        // Binomial(n, 0.04): standard deviation sqrt(n p (1 - p)) ~ 62; allow 5 of them.
        CHECK(std::abs(reflected - 0.04 * n) < 5 * std::sqrt(n * 0.04 * 0.96));
    }
}

TEST_CASE("dielectric: an oblique ray reflects with the model's probability", "[ch05]") {
    // At 60 degrees into glass Schlick gives 0.0700 and Fresnel 0.0892, about 40 standard errors
    // of a 4e5-ray estimate apart: each model must meet its own value, not the other's.
    const vec3 d(std::sqrt(real(3)) / 2, real(-0.5), 0);  // 60 degrees from the normal (0, 1, 0)
    const rt::ray in(point3(0, 1, 0) - 2 * d, d);
    for (auto model : {rt::fresnel_model::schlick, rt::fresnel_model::exact}) {
        auto glass = std::make_shared<rt::dielectric>(1.5, model);
        auto rec   = hit_unit_sphere(glass, in);
        REQUIRE(rec.front_face);
        const real cos_i = dot(-rt::unit_vector(in.direction()), rec.normal);
        const double p   = double(model == rt::fresnel_model::exact
                                      ? rt::fresnel_reflectance(cos_i, 1 / real(1.5))
                                      : rt::schlick_reflectance(cos_i, 1 / real(1.5)));
        rt::independent_sampler s(12);
        const int n   = 400000;
        int reflected = 0;
        for (int k = 0; k < n; ++k) {
            s.start_pixel_sample(1, 0, k);
            const auto sample = glass->scatter(in, rec, s);
            REQUIRE(sample);
            if (dot(sample->scattered.direction(), rec.normal) > 0) ++reflected;
        }
        INFO("cos_i " << cos_i << ", reflectance " << p << ", " << reflected << " of " << n
                      << " reflected");
        CHECK(std::abs(reflected - p * n) < 5 * std::sqrt(n * p * (1 - p)));
    }
}

TEST_CASE("dielectric: reflectance() is the model's formula", "[ch05]") {
    const rt::dielectric schlick(1.5), exact(1.5, rt::fresnel_model::exact);
    for (real c : {real(0), real(0.1), real(0.5), real(0.75), real(0.9), real(1)}) {
        for (real eta : {1 / real(1.5), real(1.5)}) {
            CAPTURE(c, eta);
            CHECK(schlick.reflectance(c, eta) == rt::schlick_reflectance(c, eta));
            CHECK(exact.reflectance(c, eta) == rt::fresnel_reflectance(c, eta));
        }
    }
}

TEST_CASE("dielectric: total internal reflection inside glass reflects, no NaN",
          "[ch05][hardcase]") {
    for (auto model : {rt::fresnel_model::schlick, rt::fresnel_model::exact}) {
        auto glass = std::make_shared<rt::dielectric>(1.5, model);
        // From inside the unit sphere towards the surface at 60 degrees (critical angle 41.8).
        vec3 target(0, 1, 0);
        vec3 dir = rt::unit_vector(vec3(std::sin(1.047), std::cos(1.047), 0));
        rt::ray in(target - dir * 0.5, dir);
        auto rec = hit_unit_sphere(glass, in);
        REQUIRE_FALSE(rec.front_face);
        rt::independent_sampler s(2);
        for (int k = 0; k < 1000; ++k) {
            s.start_pixel_sample(0, 0, k);
            const auto sample = glass->scatter(in, rec, s);
            REQUIRE(sample);
            CHECK(std::isfinite(sample->scattered.direction().x()));
            CHECK(dot(sample->scattered.direction(), rec.normal) >
                  0);  // stays inside: reflected every time
        }
    }
}

TEST_CASE("dielectric: scatter draws exactly 1 sampler dimension", "[ch05][draw-order]") {
    // The choice between reflection and refraction; drawn even under total internal
    // reflection, so that the layout of later bounces does not depend on the angle.
    auto glass           = std::make_shared<rt::dielectric>(1.5);
    const vec3 dir       = rt::unit_vector(vec3(std::sin(real(1.047)), std::cos(real(1.047)), 0));
    const rt::ray rays[] = {rt::ray(point3(0, 0, 5), vec3(0, 0, -1)),  // entering, head-on
                            rt::ray(vec3(0, 1, 0) - dir * 0.5, dir)};  // inside, TIR
    int wrong            = 0;
    for (const rt::ray& in : rays) {
        auto rec = hit_unit_sphere(glass, in);
        for (int k = 0; k < 100; ++k) {
            rt::independent_sampler s(4);
            s.start_pixel_sample(k, 0, 0);
            (void)glass->scatter(in, rec, s);
            if (s.next_1d() != rt_test::next_after_draws(4, k, 0, 0, 1)) ++wrong;
        }
    }
    CHECK(wrong == 0);
}

TEST_CASE("dielectric: a bad index of refraction is refused with the value named", "[ch05]") {
    using Catch::Matchers::Contains;
    const real nan = std::numeric_limits<real>::quiet_NaN();
    CHECK_THROWS_WITH(rt::dielectric(0), Contains("index of refraction") && Contains("got 0"));
    CHECK_THROWS_WITH(rt::dielectric(-1.5), Contains("index of refraction") && Contains("-1.5"));
    CHECK_THROWS_AS(rt::dielectric(nan), rt::user_error);
    CHECK_THROWS_AS(rt::dielectric(rt::infinity, rt::fresnel_model::exact), rt::user_error);
    CHECK_NOTHROW(rt::dielectric(rt::real(1.0 / 1.5)));  // an air bubble in glass is legal
    CHECK_NOTHROW(rt::dielectric(real(2.4), rt::fresnel_model::exact));
}
