// Tests for power_heuristic (mis_tracer.h, chapter 15): Veach's weight
// w = p_taken^2 / (p_taken^2 + p_other^2) of a sample drawn by one strategy when another could
// have drawn it too. A strategy the other cannot match gets all the weight; one that could not
// have drawn the sample gets none; the two weights of one sample always sum to 1; and 0,
// infinite and huge densities give no NaN.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "rt/core/rng.h"
#include "rt/integrators/mis_tracer.h"
#include "test_helpers.h"

namespace {

using rt::power_heuristic;
using rt::real;

const real inf  = std::numeric_limits<real>::infinity();
const real huge = std::numeric_limits<real>::max();
const real tiny = std::numeric_limits<real>::denorm_min();

}  // namespace

TEST_CASE("power_heuristic: p^2 / (p^2 + q^2) for ordinary densities", "[ch15]") {
    CHECK(power_heuristic(1, 1) == Approx(0.5));
    CHECK(power_heuristic(3, 1) == Approx(0.9));
    CHECK(power_heuristic(1, 3) == Approx(0.1));
    CHECK(power_heuristic(real(0.2), real(0.1)) == Approx(0.8));
}

TEST_CASE("power_heuristic: a density the other lacks takes all, one that is 0 takes none",
          "[ch15]") {
    for (real p : {real(1e-30), real(0.5), real(1), real(7), real(1e30)}) {
        INFO("p = " << p);
        CHECK(power_heuristic(p, 0) == 1);
        CHECK(power_heuristic(0, p) == 0);
        // A delta (infinite density) against a finite one.
        CHECK(power_heuristic(inf, p) == 1);
        CHECK(power_heuristic(p, inf) == 0);
    }
    CHECK(power_heuristic(0, 0) == 0);
    CHECK(power_heuristic(inf, 0) == 1);
    CHECK(power_heuristic(0, inf) == 0);
    // Two deltas: each gets half, so the pair still sums to 1.
    CHECK(power_heuristic(inf, inf) + power_heuristic(inf, inf) == 1);
}

TEST_CASE("power_heuristic: the weights of one sample sum to 1, at any scale", "[ch15]") {
    rt::pcg32 rng(3, 8);
    int off = 0, outside = 0;
    for (int k = 0; k < 100000; ++k) {
        const real p = rt_test::log_uniform(rng, -30, 30);
        const real q = rt_test::log_uniform(rng, -30, 30);
        const real a = power_heuristic(p, q), b = power_heuristic(q, p);
        outside += !(a >= 0 && a <= 1 && b >= 0 && b <= 1);
        off += !(std::fabs(a + b - 1) <= 4 * std::numeric_limits<real>::epsilon());
    }
    CHECK(outside == 0);
    CHECK(off == 0);
}

TEST_CASE("power_heuristic: huge, tiny and infinite densities give no NaN", "[ch15][hardcase]") {
    // Squaring a density above 1e154 (float: 1e19) overflows to infinity and inf / inf is NaN;
    // below 1e-154 it underflows to 0 and 0 / 0 is NaN. The weight must stay in [0, 1].
    const real values[] = {0, tiny, real(1e-40), real(1e-20), 1, real(1e20), real(1e30), huge, inf};
    int bad             = 0;
    for (real p : values) {
        for (real q : values) {
            const real w = power_heuristic(p, q);
            if (!(w >= 0 && w <= 1)) {
                UNSCOPED_INFO("power_heuristic(" << p << ", " << q << ") = " << w);
                ++bad;
            }
            // Equal densities share equally (both zero: neither could draw it, weight 0).
            if (p == q && p > 0 && w != real(0.5)) {
                UNSCOPED_INFO("power_heuristic(" << p << ", " << p << ") = " << w);
                ++bad;
            }
        }
    }
    CHECK(bad == 0);
    CHECK(power_heuristic(huge, huge) == real(0.5));
    CHECK(power_heuristic(huge, 1) == 1);
    CHECK(power_heuristic(1, huge) == 0);
    CHECK(power_heuristic(tiny, tiny) == real(0.5));
}
