// Shared statistical checks for the unit tests: Pearson's chi-square goodness-of-fit test that
// every sampler is held to (as in Nori and pbrt-v4), and a mean-within-k-standard-errors check for
// furnace tests, whose answer is known in closed form.
// X^2 = sum_i (O_i - E_i)^2 / E_i;  p = Q(dof/2, X^2/2);  standard error = s / sqrt(n).
#pragma once

#include <string>
#include <vector>

namespace rt_test {

// The regularized upper incomplete gamma function Q(a, x) = Gamma(a, x) / Gamma(a), for a > 0 and
// x >= 0, to about 1e-14 relative (series below x = a + 1, continued fraction above, after
// Numerical Recipes 6.2). Throws std::invalid_argument outside that domain.
double regularized_gamma_q(double a, double x);

// The probability that a chi-square variable with `dof` degrees of freedom is at least `statistic`:
// Q(dof/2, statistic/2). A small p-value means the observed counts are unlikely under the model.
double chi_square_p_value(double statistic, int dof);

struct chi_square_result {
    bool passed;          // p_value >= alpha, and no sample fell where the model says none can
    double statistic;     // Pearson's X^2 over the bins left after pooling
    int dof;              // bins after pooling minus one (the pdf has no fitted parameters)
    double p_value;       // Q(dof/2, X^2/2); 0 when the test fails before computing it
    std::string summary;  // one line for a failure message
};

// Pearson's chi-square test of observed bin counts against expected counts (both in samples, not
// fractions). Bins whose expected count is below min_expected are pooled, smallest first, into one
// bin until it reaches min_expected, because the chi-square law only holds for counts large enough
// to be roughly normal. The test fails outright when a bin with expected count 0 holds a sample (a
// sample outside the support of the pdf), when the totals of observed and expected differ by more
// than round-off (samples lost outside the bins, or expected counts that are not normalized), or
// when fewer than two bins remain. alpha is the accepted probability of a false failure.
// "Round-off" for the totals is 1e-6 relative, loose enough for expected counts from float pdfs.
// Throws std::invalid_argument when the vectors differ in size or an expected count is negative.
chi_square_result chi_square_test(const std::vector<double>& observed,
                                  const std::vector<double>& expected, double alpha,
                                  int min_expected = 5);

// The sample mean of n independent estimates and its standard error s / sqrt(n), with s^2 the
// unbiased sample variance: by the central limit theorem the mean lies within 5 standard errors of
// the true value except with probability about 6e-7.
struct mean_estimate {
    long long count;
    double mean;
    double standard_error;
};

// Accumulates samples one at a time (Welford's update, which does not lose the variance to
// cancellation the way sum and sum-of-squares do), so a furnace test need not keep its samples.
class running_mean {
  public:
    void add(double x);
    long long count() const { return n; }
    // Throws std::invalid_argument with fewer than two samples: no variance, no standard error.
    mean_estimate estimate() const;

  private:
    long long n = 0;
    double mean = 0;
    double m2   = 0;  // sum of squared deviations from the running mean
};

mean_estimate estimate_mean(const std::vector<double>& samples);

struct mean_check {
    bool passed;  // |mean - expected| <= tolerance
    double mean;  // the estimate
    double standard_error;
    double expected;
    double tolerance;     // k * standard_error plus a round-off floor
    std::string summary;  // one line for a failure message
};

// Checks |mean - expected| <= k * standard_error. The tolerance also gets a floor of 8 units in
// the last place of `expected` in the renderer's scalar type (rt::real), so an estimator without
// noise (all samples equal, standard error 0) is compared up to rounding instead of bit for bit.
mean_check mean_within_tolerance(const mean_estimate& estimate, double expected, double k);
mean_check mean_within_tolerance(const std::vector<double>& samples, double expected, double k);

}  // namespace rt_test
