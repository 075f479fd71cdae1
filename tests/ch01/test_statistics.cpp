// The statistical helpers themselves (tests/statistics.h): the tests of every sampler lean on them,
// so they are checked against known values first. Chapter 01, whose RNG is the first to use them.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "rt/core/rng.h"
#include "statistics.h"

using rt_test::chi_square_p_value;
using rt_test::chi_square_test;
using rt_test::regularized_gamma_q;

namespace {

// The continued fraction and the series both stop at a relative step below 1e-16; lgamma and exp
// add a few ulps more for moderate a. 1e-12 relative leaves room and still pins 12 digits.
constexpr double gamma_tolerance = 1e-12;

bool close_relative(double got, double want, double tolerance) {
    return std::fabs(got - want) <= tolerance * std::fabs(want);
}

}  // namespace

TEST_CASE("statistics: Q(a, x) matches closed forms and reference values", "[statistics][ch01]") {
    // Q(1, x) = e^-x and Q(1/2, x) = erfc(sqrt(x)) exercise both branches (x < a+1 and x >= a+1).
    for (double x : {0.01, 0.5, 1.9, 2.1, 7.0, 40.0}) {
        INFO("x = " << x);
        CHECK(close_relative(regularized_gamma_q(1, x), std::exp(-x), gamma_tolerance));
        CHECK(
            close_relative(regularized_gamma_q(0.5, x), std::erfc(std::sqrt(x)), gamma_tolerance));
    }
    // Reference values from mpmath (30 digits): gammainc(a, x, inf, regularized=True).
    struct reference {
        double a, x, q;
    };
    const reference references[] = {
        {2.5, 1.0, 0.849145036084609636},  {3, 7.5, 0.0202567150566644050},
        {10, 5, 0.968171942693795188},     {10, 15, 0.0698536606994097677},
        {50, 40, 0.929664933340605046},    {50, 60, 0.0844066810936918296},
        {0.1, 0.01, 0.337378740045520208}, {100, 130, 0.00275040836730652628},
        {5, 0.5, 0.999827884370044159},    {49.5, 67.5, 0.00945955967768324020},
    };
    for (const reference& r : references) {
        INFO("a = " << r.a << ", x = " << r.x);
        CHECK(close_relative(regularized_gamma_q(r.a, r.x), r.q, gamma_tolerance));
    }
    CHECK(regularized_gamma_q(3, 0) == 1);
    CHECK_THROWS_AS(regularized_gamma_q(0, 1), std::invalid_argument);
    CHECK_THROWS_AS(regularized_gamma_q(1, -1), std::invalid_argument);
}

TEST_CASE("statistics: chi-square p-values match the textbook table", "[statistics][ch01]") {
    // A table gives critical values to 3-5 digits; 3.84 is the rounded 5% point of 1 dof (its
    // exact p-value is 0.050044), so 1e-3 absolute is the precision the table itself has.
    CHECK(std::fabs(chi_square_p_value(3.84, 1) - 0.05) < 1e-3);
    // Exact critical values (mpmath) pin the function far tighter.
    CHECK(close_relative(chi_square_p_value(3.841458820694124, 1), 0.05, 1e-10));
    CHECK(close_relative(chi_square_p_value(6.634896601021214, 1), 0.01, 1e-10));
    CHECK(close_relative(chi_square_p_value(18.307038053275146, 10), 0.05, 1e-10));
    CHECK(close_relative(chi_square_p_value(134.64162, 99), 0.00999999513851280, 1e-10));
    CHECK(chi_square_p_value(0, 4) == 1);
    CHECK_THROWS_AS(chi_square_p_value(1, 0), std::invalid_argument);
}

TEST_CASE("statistics: a fair uniform histogram passes, a biased one fails", "[statistics][ch01]") {
    constexpr int bins    = 50;
    constexpr int samples = 100000;
    const std::vector<double> expected(bins, double(samples) / bins);

    // Counts equal to their expectation are a perfect fit.
    auto perfect = chi_square_test(expected, expected, 0.01);
    CHECK(perfect.passed);
    CHECK(perfect.statistic == 0);
    CHECK(perfect.p_value == 1);
    CHECK(perfect.dof == bins - 1);

    // Fixed seeds make these deterministic: the fair stream passes at alpha = 0.01 (its p-value
    // is printed on failure). u^1.05 moves 1.8% of the samples to other bins; that adds about 243
    // to the 49 a fair histogram expects, a p-value near 1e-35, so the biased one must fail.
    std::vector<double> fair(bins, 0), biased(bins, 0);
    rt::pcg32 rng(7, 11);
    for (int i = 0; i < samples; ++i) {
        double u = double(rng.uniform());
        fair[std::size_t(u * bins)] += 1;
        biased[std::size_t(std::pow(u, 1.05) * bins)] += 1;
    }
    auto fair_result = chi_square_test(fair, expected, 0.01);
    INFO(fair_result.summary);
    CHECK(fair_result.passed);
    auto biased_result = chi_square_test(biased, expected, 0.01);
    INFO(biased_result.summary);
    CHECK_FALSE(biased_result.passed);
}

TEST_CASE("statistics: chi-square pools low-count bins and rejects impossible samples",
          "[statistics][ch01]") {
    // Sorted by expectation: 1, 1, 1, 2 pool into one bin of 5, leaving {pool, 100, 100}: 2 dof.
    const std::vector<double> expected = {100, 1, 100, 1, 2, 1};
    const std::vector<double> observed = {100, 0, 99, 2, 3, 1};
    auto pooled                        = chi_square_test(observed, expected, 0.01);
    INFO(pooled.summary);
    CHECK(pooled.dof == 2);
    // (6-5)^2/5 + 0 + (99-100)^2/100
    CHECK(std::fabs(pooled.statistic - (0.2 + 0.01)) < 1e-12);
    CHECK(pooled.passed);

    // A sample in a bin of zero probability is a sampler bug however well the rest fits.
    auto impossible = chi_square_test({500, 499, 1}, {500, 500, 0}, 0.01);
    CHECK_FALSE(impossible.passed);
    // Samples that landed in no bin show up as a total that does not match.
    auto lost = chi_square_test({500, 499}, {500, 500}, 0.01);
    CHECK_FALSE(lost.passed);
    CHECK_THROWS_AS(chi_square_test({1, 2}, {3}, 0.01), std::invalid_argument);
}

TEST_CASE("statistics: mean within k standard errors", "[statistics][ch01]") {
    // {1, 2, 3, 4}: mean 2.5, sample variance 5/3, standard error sqrt(5/12) = 0.6455.
    const std::vector<double> samples = {1, 2, 3, 4};
    auto estimate                     = rt_test::estimate_mean(samples);
    CHECK(estimate.count == 4);
    CHECK(estimate.mean == 2.5);
    CHECK(std::fabs(estimate.standard_error - std::sqrt(5.0 / 12)) < 1e-15);

    const double se = std::sqrt(5.0 / 12);
    CHECK(rt_test::mean_within_tolerance(samples, 2.5 + 4.9 * se, 5).passed);
    CHECK_FALSE(rt_test::mean_within_tolerance(samples, 2.5 - 5.1 * se, 5).passed);

    // A noise-free estimator passes on round-off alone (the floor is 8 ulps of rt::real), and
    // fails for anything larger.
    const double ulp = std::numeric_limits<rt::real>::epsilon();
    const std::vector<double> constant(10, 0.1);
    CHECK(rt_test::mean_within_tolerance(constant, 1.0 / 10, 5).passed);
    CHECK(rt_test::mean_within_tolerance(constant, 0.1 * (1 + 4 * ulp), 5).passed);
    CHECK_FALSE(rt_test::mean_within_tolerance(constant, 0.1 * (1 + 16 * ulp), 5).passed);

    // The running form agrees with the batch form and needs two samples for an error bar.
    rt_test::running_mean running;
    running.add(1);
    CHECK_THROWS_AS(running.estimate(), std::invalid_argument);
    for (double x : {2.0, 3.0, 4.0}) running.add(x);
    CHECK(running.estimate().mean == estimate.mean);
    CHECK(running.estimate().standard_error == estimate.standard_error);
}
