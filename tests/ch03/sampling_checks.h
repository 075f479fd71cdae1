// The checks every warp of rt/samplers/sampling.h is held to (chapter 03 on; included as
// "ch03/sampling_checks.h"): every sample lies in its domain, a chi-square test of warped samples
// against expected counts integrated from the pdf over each bin, and the pdf function integrated
// numerically over the same bins (they must sum to 1). A binning (disk_bins in test_sampling.cpp,
// say) gives count(), index(point), probability(bin): the closed-form integral of the pdf formula
// over the bin, and integrate_pdf(bin): the pdf *function* integrated numerically over the same
// bin in the natural coordinates (r, theta), so that the two meet only if the function is the
// density.
#pragma once

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "rt/core/rng.h"
#include "rt/core/vec3.h"
#include "rt/samplers/sampler.h"
#include "statistics.h"

namespace rt_test::sampling_checks {

using rt::real;
using rt::sample2;
using rt::vec3;

inline constexpr double pi     = 3.14159265358979323846;
inline constexpr double two_pi = 2 * pi;
inline constexpr real eps      = std::numeric_limits<real>::epsilon();
inline constexpr double alpha  = 0.01;

// Bins of [0, 1); a coordinate that rounds to 1 (or a hair beyond) goes into the last bin, and a
// NaN into the first, since the domain checks, not the histogram, police the boundary.
inline std::size_t cell(double t, int n) {
    if (!(t > 0)) return 0;
    if (t >= 1) return std::size_t(n - 1);
    return std::size_t(t * n);
}

// Azimuth of (x, y) as a fraction of a turn, in [0, 1).
inline double azimuth01(const vec3& p) {
    double phi = std::atan2(double(p.y()), double(p.x())) / two_pi;
    return phi < 0 ? phi + 1 : phi;
}

// Composite Simpson rule with m (even) steps: error (b - a) h^4 max|f''''| / 180, which for the
// smooth integrands below (r, r^2, sin, sin cos over one bin) is below 1e-9 of the bin's integral.
template <class F>
double simpson(F f, double a, double b, int m = 64) {
    double h = (b - a) / m, sum = f(a) + f(b);
    for (int k = 1; k < m; ++k) sum += (k % 2 ? 4 : 2) * f(a + k * h);
    return sum * h / 3;
}

inline sample2 next_sample2(rt::pcg32& rng) {
    real u = rng.uniform();
    return {u, rng.uniform()};
}

// Bins `samples` warped points and compares them with the binning's expected counts.
template <class Bins, class Warp>
rt_test::chi_square_result chi_square(const Bins& bins, Warp warp, int samples,
                                      std::uint64_t sequence) {
    std::vector<double> observed(std::size_t(bins.count()), 0), expected(observed.size());
    rt::pcg32 rng(sequence, 1);
    for (int i = 0; i < samples; ++i) observed[bins.index(warp(rng))] += 1;
    for (std::size_t b = 0; b < expected.size(); ++b) expected[b] = samples * bins.probability(b);
    return rt_test::chi_square_test(observed, expected, alpha);
}

// The numeric integral of the pdf over each bin matches the closed form the chi-square test
// used, and the bins together hold probability 1. Simpson's error is below 1e-9 of each bin
// (see simpson) and the pdf functions return `real`, so they are exact only to about one
// rounding of 1/pi and one of cos(theta): 1e-8 + 2 eps relative (2.4e-7 in a float build) is
// tight enough to catch any wrong constant or wrong power.
template <class Bins>
void check_pdf_matches_bins(const Bins& bins) {
    const double tolerance = 1e-8 + 2 * double(eps);
    double total           = 0;
    int mismatches         = 0;
    for (std::size_t b = 0; b < std::size_t(bins.count()); ++b) {
        double numeric = bins.integrate_pdf(b), closed = bins.probability(b);
        if (!(std::fabs(numeric - closed) <= tolerance * closed)) {
            UNSCOPED_INFO("bin " << b << ": numeric " << numeric << " vs closed form " << closed);
            ++mismatches;
        }
        total += numeric;
    }
    CHECK(mismatches == 0);
    CHECK(std::fabs(total - 1) <= tolerance);
}

// Corner and edge inputs, where a warp divides by zero or leaves its domain if it ever does:
// 0, the centre and either side of it, and the largest value below 1 (what uniform() returns at
// most in a float build; larger than anything it returns in double).
inline std::vector<real> edge_inputs() {
    return {0,          real(1e-7),
            real(0.25), std::nextafter(real(0.5), real(0)),
            real(0.5),  std::nextafter(real(0.5), real(1)),
            real(0.75), std::nextafter(real(1), real(0))};
}

// Applies `check` to the warp of every pair of edge inputs and of 1e5 random pairs.
template <class Check>
void for_edge_and_random_samples(Check check) {
    for (real u : edge_inputs()) {
        for (real v : edge_inputs()) check(sample2{u, v});
    }
    rt::pcg32 rng(99, 3);
    for (int i = 0; i < 100000; ++i) check(next_sample2(rng));
}

}  // namespace rt_test::sampling_checks
