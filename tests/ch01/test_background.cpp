// background (rt/scene/background.h): what a ray that hits nothing sees, a vertical blend from
// bottom (straight down) to top (straight up), and sky_only, chapter 01's whole renderer.
// Chapter 01.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "rt/core/rng.h"
#include "rt/integrators/sky_only.h"
#include "rt/samplers/independent_sampler.h"
#include "rt/scene/background.h"
#include "test_helpers.h"

using rt::color;
using rt::point3;
using rt::real;
using rt::vec3;

namespace {

// Bit-for-bit equality of colors (rt_test::exactly), under the name the checks read best with.
bool (&equal)(const vec3&, const vec3&) = rt_test::exactly;

}  // namespace

TEST_CASE("background: straight up is top, straight down is bottom", "[background][ch01]") {
    const rt::background sky = rt::background::sky();
    // d.y / |d| is exactly +-1 for a vertical d of any length, so the blend weight is exactly 0
    // or 1 and the ends come out bit for bit.
    for (real length : {real(1), real(0.001), real(3), real(1e6)}) {
        CAPTURE(length);
        CHECK(equal(sky.radiance(vec3(0, length, 0)), sky.top));
        CHECK(equal(sky.radiance(vec3(0, -length, 0)), sky.bottom));
    }
    // The book's sky: white at the bottom, light blue (0.5, 0.7, 1.0) at the top.
    CHECK(equal(sky.bottom, color(1, 1, 1)));
    CHECK(equal(sky.top, color(real(0.5), real(0.7), real(1.0))));
}

TEST_CASE("background: a horizontal direction gives the average", "[background][ch01]") {
    const rt::background sky{color(real(0.2), real(0.4), real(0.6)), color(1, real(0.5), 0)};
    const color average = real(0.5) * (sky.bottom + sky.top);
    // y = 0 gives the blend weight 1/2 exactly; the blend itself rounds once or twice, so each
    // channel is within 2 eps of the exact average (all channels here are at most 1).
    const real tol = 2 * std::numeric_limits<real>::epsilon();
    for (vec3 d : {vec3(1, 0, 0), vec3(0, 0, -1), vec3(-3, 0, 4), vec3(real(0.1), 0, real(-7))}) {
        const color L = sky.radiance(d);
        CAPTURE(d, L);
        CHECK(std::fabs(L.x() - average.x()) <= tol);
        CHECK(std::fabs(L.y() - average.y()) <= tol);
        CHECK(std::fabs(L.z() - average.z()) <= tol);
    }
    // Halfway up (45 degrees) the weight is (sin 45 + 1) / 2 ~ 0.854 towards the top.
    const real a = (std::sqrt(real(0.5)) + 1) / 2;
    // a itself carries about four roundings (sqrt, divide, add, halve): 8 eps covers it and the
    // blend.
    const color up45 = sky.radiance(vec3(1, 1, 0));
    CHECK(std::fabs(up45.x() - ((1 - a) * real(0.2) + a * 1)) <= 4 * tol);
    CHECK(std::fabs(up45.z() - ((1 - a) * real(0.6) + a * 0)) <= 4 * tol);
}

TEST_CASE("background: uniform() is the same in every direction", "[background][ch01]") {
    const color c(real(0.7), real(0.3), real(0.9));
    const rt::background uniform = rt::background::uniform(c);
    CHECK(equal(uniform.bottom, c));
    CHECK(equal(uniform.top, c));
    // Bit for bit, so that a furnace test sees exactly the radiance it put in.
    rt::pcg32 rng(8, 8);
    int differ = 0;
    for (int i = 0; i < 10000; ++i) {
        const real length = 1 + 10 * rng.uniform();
        const vec3 d      = length * rt_test::random_unit(rng);
        if (!equal(uniform.radiance(d), c)) {
            UNSCOPED_INFO("direction " << d << " gives " << uniform.radiance(d));
            ++differ;
        }
    }
    CHECK(differ == 0);
}

TEST_CASE("background: sky_only sees the background along every ray and draws nothing",
          "[background][ch01]") {
    const rt::background sky{color(real(0.2), real(0.4), real(0.6)), color(1, real(0.5), 0)};
    const rt::sky_only estimator(sky);
    rt::pcg32 rng(3, 9);
    int differ = 0, drew = 0;
    for (int k = 0; k < 1000; ++k) {
        const point3 origin = rt_test::random_in_cube(rng, 100);
        const real length   = 1 + 10 * rng.uniform();
        const vec3 d        = length * rt_test::random_unit(rng);
        rt::independent_sampler s(5);
        s.start_pixel_sample(k, 0, 0);
        // Only the direction matters (nothing to hit), whatever the origin and the depth.
        const color L = estimator.radiance(rt::ray(origin, d), s, 1 + k % 3);
        if (!equal(L, sky.radiance(d))) {
            UNSCOPED_INFO("direction " << d << " gives " << L << ", the sky " << sky.radiance(d));
            ++differ;
        }
        // The next number is the sampler's first: the estimator drew none.
        if (s.next_1d() != rt_test::next_after_draws(5, k, 0, 0, 0)) ++drew;
    }
    CHECK(differ == 0);
    CHECK(drew == 0);
}
