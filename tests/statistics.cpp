#include "statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "rt/core/scalar.h"

namespace rt_test {

namespace {

constexpr double epsilon     = std::numeric_limits<double>::epsilon();
constexpr double tiny        = std::numeric_limits<double>::min() / epsilon;
constexpr int max_iterations = 100000;  // enough for a up to ~1e8; our tests use a < 1e4

// x^a e^-x / Gamma(a): the common factor of the series and the continued fraction, in logs so
// that large a and x do not overflow.
double gamma_prefactor(double a, double x) {
    return std::exp(a * std::log(x) - x - std::lgamma(a));
}

// P(a, x) = 1 - Q(a, x) by its power series, which converges quickly for x < a + 1.
double gamma_p_series(double a, double x) {
    double term = 1 / a, sum = term;
    for (int n = 1; n < max_iterations; ++n) {
        term *= x / (a + n);
        sum += term;
        if (std::fabs(term) < std::fabs(sum) * epsilon) return sum * gamma_prefactor(a, x);
    }
    throw std::runtime_error("regularized_gamma_q: series did not converge");
}

// Q(a, x) by its continued fraction (modified Lentz), which converges quickly for x > a + 1.
double gamma_q_continued_fraction(double a, double x) {
    double b = x + 1 - a;
    double c = 1 / tiny;
    double d = 1 / b;
    double h = d;
    for (int i = 1; i < max_iterations; ++i) {
        double an = -i * (i - a);
        b += 2;
        d = an * d + b;
        if (std::fabs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::fabs(c) < tiny) c = tiny;
        d            = 1 / d;
        double delta = d * c;
        h *= delta;
        if (std::fabs(delta - 1) < epsilon) return h * gamma_prefactor(a, x);
    }
    throw std::runtime_error("regularized_gamma_q: continued fraction did not converge");
}

std::string format_chi_square(const chi_square_result& r, double alpha, int pooled_bins) {
    std::ostringstream out;
    out << "chi-square " << (r.passed ? "passed" : "FAILED") << ": X^2 = " << r.statistic
        << " with " << r.dof << " dof, p-value " << r.p_value << " (alpha " << alpha << ")";
    if (pooled_bins > 0) out << ", " << pooled_bins << " low-count bins pooled into one";
    return out.str();
}

}  // namespace

double regularized_gamma_q(double a, double x) {
    if (!(a > 0) || !(x >= 0) || std::isinf(a)) {
        std::ostringstream message;
        message << "regularized_gamma_q needs a > 0 and x >= 0, got a = " << a << ", x = " << x;
        throw std::invalid_argument(message.str());
    }
    if (x == 0) return 1;
    if (std::isinf(x)) return 0;
    // Below a + 1, Q is at least about 0.3, so 1 - P loses no significant digits.
    return x < a + 1 ? 1 - gamma_p_series(a, x) : gamma_q_continued_fraction(a, x);
}

double chi_square_p_value(double statistic, int dof) {
    if (dof < 1 || !(statistic >= 0)) {
        std::ostringstream message;
        message << "chi_square_p_value needs dof >= 1 and statistic >= 0, got dof = " << dof
                << ", statistic = " << statistic;
        throw std::invalid_argument(message.str());
    }
    return regularized_gamma_q(0.5 * dof, 0.5 * statistic);
}

chi_square_result chi_square_test(const std::vector<double>& observed,
                                  const std::vector<double>& expected, double alpha,
                                  int min_expected) {
    if (observed.size() != expected.size()) {
        std::ostringstream message;
        message << "chi_square_test: " << observed.size() << " observed bins but "
                << expected.size() << " expected bins";
        throw std::invalid_argument(message.str());
    }
    for (std::size_t i = 0; i < expected.size(); ++i) {
        if (!(expected[i] >= 0)) {
            std::ostringstream message;
            message << "chi_square_test: expected count of bin " << i << " is " << expected[i];
            throw std::invalid_argument(message.str());
        }
    }

    chi_square_result result{false, 0, 0, 0, ""};
    auto fail = [&](const std::string& why) {
        result.summary = "chi-square FAILED: " + why;
        return result;
    };

    double observed_total = std::accumulate(observed.begin(), observed.end(), 0.0);
    double expected_total = std::accumulate(expected.begin(), expected.end(), 0.0);
    // Expected counts integrated analytically sum to the sample count up to the precision of the
    // pdf: ~1e-16 relative with double pdfs, ~1e-7 with a float build's. 1e-6 relative allows
    // that and still catches expected counts that are not normalized or a region of the domain
    // left out of the bins; changing the totals by 1e-6 N moves X^2 by only ~1e-12 N.
    if (!(std::fabs(observed_total - expected_total) <= 1e-6 * std::max(1.0, expected_total))) {
        std::ostringstream why;
        why << "observed total " << observed_total << " differs from expected total "
            << expected_total << " (samples outside every bin, or expected not normalized)";
        return fail(why.str());
    }

    // Pool from the smallest expected count up, so the pooled bin reaches min_expected with as
    // few bins as possible.
    std::vector<std::size_t> order(expected.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return expected[a] < expected[b]; });

    double pooled_observed = 0, pooled_expected = 0;
    int pooled_bins = 0, bins = 0;
    for (std::size_t index : order) {
        double o = observed[index], e = expected[index];
        if (e == 0) {
            if (o > 0) {
                std::ostringstream why;
                why << o << " samples in bin " << index << ", where the pdf is zero";
                return fail(why.str());
            }
        } else if (e < min_expected || (pooled_bins > 0 && pooled_expected < min_expected)) {
            pooled_observed += o;
            pooled_expected += e;
            ++pooled_bins;
        } else {
            result.statistic += (o - e) * (o - e) / e;
            ++bins;
        }
    }
    if (pooled_bins > 0) {
        result.statistic += (pooled_observed - pooled_expected) *
                            (pooled_observed - pooled_expected) / pooled_expected;
        ++bins;
    }

    // The pdf is fully specified (nothing fitted to the data), so only the fixed total costs a
    // degree of freedom.
    result.dof = bins - 1;
    if (result.dof < 1) return fail("fewer than two bins after pooling; use more samples");
    result.p_value = chi_square_p_value(result.statistic, result.dof);
    result.passed  = result.p_value >= alpha;
    result.summary = format_chi_square(result, alpha, pooled_bins);
    return result;
}

void running_mean::add(double x) {
    ++n;
    double delta = x - mean;
    mean += delta / double(n);
    m2 += delta * (x - mean);
}

mean_estimate running_mean::estimate() const {
    if (n < 2) {
        std::ostringstream message;
        message << "running_mean: a standard error needs at least 2 samples, got " << n;
        throw std::invalid_argument(message.str());
    }
    double variance = m2 / double(n - 1);
    return {n, mean, std::sqrt(variance / double(n))};
}

mean_estimate estimate_mean(const std::vector<double>& samples) {
    running_mean accumulator;
    for (double x : samples) accumulator.add(x);
    return accumulator.estimate();
}

mean_check mean_within_tolerance(const mean_estimate& estimate, double expected, double k) {
    // Welford's mean of n equal values is that value exactly, but `expected` may have been computed
    // another way (1 / (1 - a)), or in double while the renderer ran in float (0.6 vs 0.6f), so
    // allow a few ulps of the renderer's scalar type.
    constexpr double real_epsilon = std::numeric_limits<rt::real>::epsilon();
    double round_off = 8 * real_epsilon * std::max(std::fabs(expected), std::fabs(estimate.mean));
    mean_check check{};
    check.mean           = estimate.mean;
    check.standard_error = estimate.standard_error;
    check.expected       = expected;
    check.tolerance      = k * estimate.standard_error + round_off;
    check.passed         = std::fabs(estimate.mean - expected) <= check.tolerance;

    std::ostringstream out;
    out.precision(10);
    out << "mean " << (check.passed ? "passed" : "FAILED") << ": " << estimate.mean << " +- "
        << estimate.standard_error << " (standard error, n = " << estimate.count << "), expected "
        << expected << ", off by " << std::fabs(estimate.mean - expected)
        << (check.passed ? " <= " : " > ") << k
        << " standard errors + round-off = " << check.tolerance;
    check.summary = out.str();
    return check;
}

mean_check mean_within_tolerance(const std::vector<double>& samples, double expected, double k) {
    return mean_within_tolerance(estimate_mean(samples), expected, k);
}

}  // namespace rt_test
