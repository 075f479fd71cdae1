// Tests for perlin.h (chapter 09). The bounds below are derived, not measured:
//
// noise(p) = sum over the 8 corners c of w_c(p) g_c . (p - c), with weights w_c the products of
// s(t) or 1 - s(t) per axis (s(t) = t^2 (3 - 2t), t the fractional coordinate), so w_c >= 0 and
// sum w_c = 1.
//
// Range. |g_c . (p - c)| <= |p - c|, so by Jensen |noise| <= sum w_c |p - c|
// <= sqrt(sum w_c |p - c|^2) = sqrt(sum over axes of h(t)), with per axis
// h(t) = (1 - s) t^2 + s (1 - t)^2. With t = 1/2 + x, s = 1/2 + 3x/2 - 2x^3, and
// h = 1/4 - 2x^2 (1 - 2x^2) <= 1/4 for |x| <= 1/2. Hence |noise| <= sqrt(3/4) = sqrt(3)/2.
//
// Lipschitz constant. grad noise = sum w_c g_c + sum (grad w_c) (g_c . (p - c)). The first term
// has length <= sum w_c = 1. In the second, d w_c / dx is +-s'(t) times the other two axes'
// weights, so sum over c of |d w_c / dx| = 2 s'(t) <= 2 * 3/2 = 3, and |g_c . (p - c)| <= sqrt(3):
// each component is at most 3 sqrt(3), the vector at most sqrt(3) * 3 sqrt(3) = 9. So
// |noise(p) - noise(q)| <= 10 |p - q|.
//
// Variance. For random points and independent uniform unit gradients, E[(g . x)^2] = |x|^2 / 3
// and cross terms vanish, so Var = (1/3) E[sum w_c^2 |p - c|^2] = E[B] E[A]^2 with
// A = (1 - s)^2 + s^2 and B = (1 - s)^2 t^2 + s^2 (1 - t)^2 averaged over t in [0, 1]:
// E[A] = 26/35, E[B] = 19/315, Var = 12844/385875 = 0.03329.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "book_values.h"
#include "rt/core/rng.h"
#include "rt/textures/perlin.h"
#include "test_helpers.h"

namespace {

using rt::point3, rt::real, rt::vec3;

constexpr real eps = std::numeric_limits<real>::epsilon();
// The sum of eight products of numbers of size <= 1: a few ulps of 1 of rounding (16 allowed).
constexpr real rounding  = 16 * eps;
const real noise_bound   = std::sqrt(real(3)) / 2;
constexpr real lipschitz = 10;

using rt_test::random_in_cube, rt_test::random_unit, rt_test::uniform;

// Points at every scale the noise meets: near the origin, at +-100, and near +-1e6 (where a
// double still keeps 2^-33 of the fractional part; a float keeps 1/16).
point3 random_point(rt::pcg32& rng, int i) {
    const real reach = i % 3 == 0 ? real(2) : (i % 3 == 1 ? real(100) : real(1e6));
    return random_in_cube(rng, reach);
}

}  // namespace

TEST_CASE("perlin: noise lies within sqrt(3)/2 everywhere, even at its local extremes", "[ch09]") {
    const rt::perlin noise(3);
    rt::pcg32 rng(90, 1);
    real largest = 0;
    int outside  = 0;
    std::vector<std::pair<real, point3>> best;  // the highest sampled points, to climb from
    for (int i = 0; i < 150000; ++i) {
        const point3 p = random_point(rng, i);
        const real n   = noise.noise(p);
        largest        = std::max(largest, std::fabs(n));
        if (!(std::fabs(n) <= noise_bound + rounding)) ++outside;
        best.emplace_back(std::fabs(n), p);
        if (best.size() > 200) {
            std::nth_element(best.begin(), best.begin() + 50, best.end(),
                             [](const auto& a, const auto& b) { return a.first > b.first; });
            best.resize(50);
        }
    }
    INFO("largest |noise| over random points: " << largest);
    CHECK(outside == 0);
    CHECK(largest > real(0.4));  // it does use a good part of its range

    // Random points rarely sit at an extreme: climb |noise| (coordinate steps, halved when no
    // step helps) from 300 random starts and from the highest points sampled, and check the
    // summits too.
    std::vector<point3> starts;
    for (int start = 0; start < 300; ++start) starts.push_back(random_point(rng, start));
    for (const auto& [value, p] : best) starts.push_back(p);
    real highest = 0;
    for (point3 p : starts) {
        real value = std::fabs(noise.noise(p)), step = real(0.25);
        while (step > real(1e-7)) {
            bool moved = false;
            for (int axis = 0; axis < 3; ++axis) {
                for (real sign : {real(-1), real(1)}) {
                    point3 q = p;
                    q[axis] += sign * step;
                    const real v = std::fabs(noise.noise(q));
                    if (v > value) {
                        p     = q;
                        value = v;
                        moved = true;
                    }
                }
            }
            if (!moved) step /= 2;
        }
        highest = std::max(highest, value);
    }
    INFO("highest local maximum of |noise| found: " << highest << " (bound " << noise_bound << ")");
    CHECK(highest <= noise_bound + rounding);
    CHECK(highest > largest);  // the climb rises above every sampled value
}

TEST_CASE("perlin: noise is 0 at every lattice point", "[ch09]") {
    // There t = 0 on every axis: the corner's own weight is 1 and its offset p - c is 0.
    const rt::perlin noise(5);
    rt::pcg32 rng(91, 2);
    int nonzero = 0;
    for (int i = 0; i < 10000; ++i) {
        const int range = i % 2 ? 300 : 1000000;
        auto integer    = [&] {
            return real(int(rng.next_u32() % std::uint32_t(2 * range + 1)) - range);
        };
        const real x = integer(), y = integer();
        if (noise.noise(point3(x, y, integer())) != 0) ++nonzero;
    }
    CHECK(nonzero == 0);
    CHECK(noise.noise(point3(0, 0, 0)) == 0);
    CHECK(noise.noise(point3(-1, 255, 256)) == 0);  // where the lattice indices wrap
}

TEST_CASE("perlin: noise is continuous, with Lipschitz constant 10, also across cell faces",
          "[ch09]") {
    const rt::perlin noise(6);
    rt::pcg32 rng(92, 3);
    int steep = 0, steep_across = 0;
    real steepest = 0;
    for (int i = 0; i < 50000; ++i) {
        const point3 p = random_point(rng, i);
        // Steps from 1e-6 (the brief's d: a bound of 1e-5) to 0.5.
        const real length = std::pow(real(10), uniform(rng, -6, real(-0.3)));
        const point3 q    = p + length * random_unit(rng);
        const real moved  = (q - p).length();  // what the rounding of q left of the step
        const real change = std::fabs(noise.noise(q) - noise.noise(p));
        if (moved > 0) steepest = std::max(steepest, change / moved);
        if (change > lipschitz * moved + 2 * rounding) ++steep;

        // Just either side of an integer plane x = k (or y, z): both sides use different corners
        // and must agree in the limit. k includes negatives and the wrap at 256.
        const int axis = i % 3;
        const real k   = i % 7 == 0 ? real(256) : std::floor(p[axis]);
        point3 below = p, above = p;
        below[axis]    = std::nextafter(k, -rt::infinity);
        above[axis]    = std::nextafter(k, rt::infinity);
        const real gap = above[axis] - below[axis];
        if (std::fabs(noise.noise(above) - noise.noise(below)) > lipschitz * gap + 2 * rounding)
            ++steep_across;
    }
    INFO("steepest slope seen: " << steepest);
    CHECK(steep == 0);
    CHECK(steep_across == 0);
    CHECK(steepest > real(0.5));  // the bound is not met trivially by a flat function
}

TEST_CASE("perlin: a seed gives the same noise every time, another seed other noise", "[ch09]") {
    const rt::perlin a(7), b(7), c(8), default_seed, zero(0);
    rt::pcg32 rng(93, 4);
    int differ_same = 0, differ_other = 0, differ_default = 0;
    for (int i = 0; i < 2000; ++i) {
        const point3 p = random_point(rng, i);
        if (a.noise(p) != b.noise(p)) ++differ_same;
        if (a.noise(p) != c.noise(p)) ++differ_other;
        if (default_seed.noise(p) != zero.noise(p)) ++differ_default;
    }
    CHECK(differ_same == 0);
    CHECK(differ_default == 0);
    CHECK(differ_other > 1900);  // equal only by chance (a lattice point, or a rare tie)
}

TEST_CASE("perlin: noise has mean 0 and the variance gradient noise must have", "[ch09]") {
    // Var = 12844/385875 = 0.03329 (see the top of this file). It does not depend on how
    // isotropic the 256 gradients happen to be: by symmetry E[(p - c)(p - c)^T] is a multiple
    // of I, so only the trace of sum g g^T, exactly 256 for unit vectors, enters. What remains
    // is sampling error (sd of a variance of 1e5 samples ~ 0.5%) and the few corners that share
    // a gradient (about 1%): 5% allows for both. Gradients of another length (Perlin's 12 edge
    // vectors have length sqrt(2): twice the variance) or linear weights instead of the
    // smoothstep (0.0296, 11% less) fall outside.
    const real expected_variance = real(12844.0 / 385875.0);
    for (std::uint32_t seed : {1u, 2u, 3u}) {
        const rt::perlin noise(seed);
        rt::pcg32 rng(94, seed);
        double sum = 0, sum_squares = 0;
        const int n = 100000;
        for (int i = 0; i < n; ++i) {
            const double v = double(noise.noise(random_point(rng, 1)));
            sum += v;
            sum_squares += v * v;
        }
        const double mean = sum / n, variance = sum_squares / n - mean * mean;
        INFO("seed " << seed << ": mean " << mean << ", variance " << variance);
        // The mean of 1e5 samples with standard deviation 0.18: standard error 6e-4; 5 of them.
        CHECK(std::fabs(mean) < 5 * std::sqrt(variance / n));
        CHECK(variance == Approx(expected_variance).epsilon(0.05));
    }
}

TEST_CASE("perlin: turbulence is a sum of octaves, between 0 and 2", "[ch09]") {
    // |sum_{i<7} 0.5^i noise(2^i p)| <= sqrt(3)/2 (2 - 2^-6) = 1.718 < 2.
    const rt::perlin noise(11);
    const real bound = noise_bound * (2 - std::ldexp(real(1), -6));
    rt::pcg32 rng(95, 5);
    int outside = 0, wrong_single = 0;
    for (int i = 0; i < 30000; ++i) {
        const point3 p = random_point(rng, i);
        const real t   = noise.turbulence(p);
        if (!(t >= 0 && t <= bound + 2 * rounding)) ++outside;
        // One octave is |noise|; no octave is 0; two add the half-size octave at 2p.
        if (noise.turbulence(p, 1) != std::fabs(noise.noise(p))) ++wrong_single;
        if (noise.turbulence(p, 0) != 0) ++wrong_single;
        const real two = std::fabs(noise.noise(p) + real(0.5) * noise.noise(2 * p));
        if (noise.turbulence(p, 2) != two) ++wrong_single;
    }
    CHECK(outside == 0);
    CHECK(wrong_single == 0);
}

TEST_CASE("perlin: the default tables are the book's, drawn first in its program", "[ch09]") {
    // Printed by the book's own perlin (RayTracing/raytracing.github.io, v4.0.0-alpha.1
    // sources, src/TheNextWeek/perlin.h, built with g++ 12 -O2 on x86-64), constructed before
    // anything else draws, as in its two Perlin spheres and simple light scenes. Uniform
    // gradients on the sphere, or x drawn before z, give other values.
    const rt::perlin noise;
    CHECK(noise.noise({0.5, 0.25, 0.75}) == book_value(-0.091847037353872271));
    CHECK(noise.turbulence({0.5, 0.25, 0.75}) == book_value(0.22936348434608533));
    CHECK(noise.noise({3.3, -1.7, 12.1}) == book_value(-0.18954890970837915));
    CHECK(noise.turbulence({3.3, -1.7, 12.1}) == book_value(0.21512444769113404));
    CHECK(noise.noise({-20.4, 7.9, 0.3}) == book_value(-0.15038126510256922));
    CHECK(noise.turbulence({100.1, -50.6, 7.7}) == book_value(0.12429307560229221));
}
