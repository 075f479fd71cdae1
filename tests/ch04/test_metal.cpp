// Tests for metal.h (chapter 04): a mirror reflection weighted by the albedo, blurred by fuzz
// and absorbed when the blur points under the surface; 3 sampler dimensions per scatter; and
// the clear errors for bad parameters.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>

#include "rt/core/error.h"
#include "rt/geometry/sphere.h"
#include "rt/materials/metal.h"
#include "rt/materials/optics.h"
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

TEST_CASE("metal: fuzz 0 is a perfect mirror weighted by the albedo", "[ch04]") {
    auto mirror = std::make_shared<rt::metal>(color(0.9, 0.5, 0.1), 0);
    rt::ray in(point3(-2, 2, 0), vec3(1, -1, 0));
    auto rec = hit_unit_sphere(mirror, in);
    rt::independent_sampler s(3);
    s.start_pixel_sample(0, 0, 0);
    const auto sample = mirror->scatter(in, rec, s);
    REQUIRE(sample);
    const rt::ray& out       = sample->scattered;
    const color& attenuation = sample->weight;
    vec3 expected            = rt::unit_vector(rt::reflect(in.direction(), rec.normal));
    CHECK(rt::unit_vector(out.direction()).x() == Approx(expected.x()).margin(1e-6));
    CHECK(rt::unit_vector(out.direction()).y() == Approx(expected.y()).margin(1e-6));
    CHECK(attenuation.x() == Approx(0.9));
    CHECK(attenuation.z() == Approx(0.1));
    // Spawned off the surface on the side it leaves by.
    CHECK(rt_test::exactly(out.origin(), rec.p + rec.p_error * rec.normal));
}

TEST_CASE("metal: fuzzed rays never leave below the surface", "[ch04]") {
    auto brushed = std::make_shared<rt::metal>(color(1, 1, 1), 1);
    // A grazing ray: many fuzzed directions point into the surface and must be absorbed.
    rt::ray in(point3(-3, 0.999, 0), vec3(1, 0, 0));
    auto rec = hit_unit_sphere(brushed, in);
    rt::independent_sampler s(5);
    int absorbed = 0;
    for (int k = 0; k < 10000; ++k) {
        s.start_pixel_sample(0, 0, k);
        if (const auto sample = brushed->scatter(in, rec, s))
            CHECK(dot(sample->scattered.direction(), rec.normal) > 0);
        else
            ++absorbed;
    }
    CHECK(absorbed > 0);  // the test would be empty if no ray went below
}

TEST_CASE("metal: scatter draws exactly 3 sampler dimensions, even as a perfect mirror",
          "[ch04][draw-order]") {
    // The material's part of the sampler's layout (sampler.h): a point in the unit ball, drawn
    // whatever the fuzz, so that changing the fuzz never moves the samples of a later bounce.
    rt::ray in(point3(-2, 2, 0), vec3(1, -1, 0));
    int wrong = 0;
    for (real fuzz : {real(0), real(0.3), real(1)}) {
        auto mat = std::make_shared<rt::metal>(color(0.5, 0.5, 0.5), fuzz);
        auto rec = hit_unit_sphere(mat, in);
        for (int k = 0; k < 100; ++k) {
            rt::independent_sampler s(8);
            s.start_pixel_sample(k, 0, 0);
            (void)mat->scatter(in, rec, s);
            if (s.next_1d() != rt_test::next_after_draws(8, k, 0, 0, 3)) ++wrong;
        }
    }
    CHECK(wrong == 0);
}

TEST_CASE("metal: bad parameters are refused with the value named", "[ch04]") {
    using Catch::Matchers::Contains;
    const real nan = std::numeric_limits<real>::quiet_NaN();
    CHECK_THROWS_WITH(rt::metal(color(0.5, 0.5, 0.5), rt::real(-0.1)),
                      Contains("metal fuzz") && Contains("-0.1"));
    CHECK_THROWS_WITH(rt::metal(color(0.5, 0.5, 0.5), 1.5),
                      Contains("metal fuzz") && Contains("1.5"));
    CHECK_THROWS_AS(rt::metal(color(0.5, 0.5, 0.5), nan), rt::user_error);
    CHECK_THROWS_WITH(rt::metal(color(1.2, 0.5, 0.5), 0),
                      Contains("metal albedo") && Contains("1.2"));
    CHECK_THROWS_AS(rt::metal(color(0.5, -0.5, 0.5), 0), rt::user_error);
    CHECK_NOTHROW(rt::metal(color(1, 1, 1), 1));
    CHECK_NOTHROW(rt::metal(color(0, 0, 0), 0));
}
