// The golden tests' "within its noise" statistic (noise_statistic.h) must pass an unbiased
// render and catch a biased one. [golden statistic, all chapters]
#include <catch2/catch.hpp>

#include "noise_statistic.h"
#include "rt/core/rng.h"

namespace {

// A synthetic "render": per pixel the mean of `spp` uniform samples on [0, 2 * truth), with the
// variance of that mean, so both the estimate and its noise are known.
void synthetic_render(rt::image& mean, rt::image& variance, double truth, int spp,
                      std::uint64_t seed) {
    rt::pcg32 rng(seed, 7);
    const double sample_variance = (2 * truth) * (2 * truth) / 12;
    for (int y = 0; y < mean.height(); ++y) {
        for (int x = 0; x < mean.width(); ++x) {
            rt::color m;
            for (int c = 0; c < 3; ++c) {
                double sum = 0;
                for (int k = 0; k < spp; ++k) sum += 2 * truth * rng.uniform();
                m[c] = rt::real(sum / spp);
            }
            mean.set(x, y, m);
            rt::real v = rt::real(sample_variance / spp);
            variance.set(x, y, rt::color(v, v, v));
        }
    }
}

}  // namespace

TEST_CASE("noise statistic: quantile matches the normal table", "[ch01]") {
    CHECK(rt_test::two_sided_normal_quantile(0.05) == Approx(1.959964).epsilon(1e-5));
    CHECK(rt_test::two_sided_normal_quantile(0.01) == Approx(2.575829).epsilon(1e-5));
}

TEST_CASE("noise statistic: unbiased render passes, biased block fails", "[ch01]") {
    rt::image test(64, 48), test_var(64, 48), ref(64, 48), ref_var(64, 48);
    synthetic_render(test, test_var, 0.5, 16, 1);
    synthetic_render(ref, ref_var, 0.5, 1024, 2);
    auto unbiased = rt_test::compare_within_noise(test, test_var, ref, ref_var, 1024.0 / 16);
    INFO("worst z " << unbiased.worst_z << " limit " << unbiased.z_limit);
    CHECK(unbiased.passed());

    // Brighten one 16x16 block by 10% (+0.05): about 11 standard errors of that block's mean.
    // A sample is uniform on [0, 1): sigma 0.289; a 16-sample pixel mean 0.072; the mean of 256
    // such pixels 0.0045 (the 1024-sample reference adds only 1/64 of that variance).
    for (int y = 16; y < 32; ++y)
        for (int x = 16; x < 32; ++x) test.set(x, y, test.get(x, y) * rt::real(1.10));
    auto biased = rt_test::compare_within_noise(test, test_var, ref, ref_var, 1024.0 / 16);
    CHECK_FALSE(biased.passed());
    CHECK(biased.worst_x == 16);
    CHECK(biased.worst_y == 16);
}

TEST_CASE("noise statistic: a pixel that missed a rare path is not a failure", "[ch01]") {
    // The ch06 case: a mirror pixel whose true mean is 0.195 because 2.5% of its paths reach a
    // black ground; 16 samples usually all see the sky (0.2) and report variance 0. The
    // reference, at 4096 samples, has seen those paths and knows the variance.
    rt::image test(16, 16), test_var(16, 16), ref(16, 16), ref_var(16, 16);
    const double p = 0.025, value = 0.2;
    const double sample_variance = value * value * p * (1 - p);
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 16; ++x) {
            bool edge      = x == 15 && y == 0;
            rt::real truth = rt::real(edge ? value * (1 - p) : value);
            rt::real v     = rt::real(edge ? sample_variance / 4096 : 0);
            test.set(x, y, rt::color(value, value, value));  // all 16 samples saw the sky
            ref.set(x, y, rt::color(truth, truth, truth));
            ref_var.set(x, y, rt::color(v, v, v));
        }
    }
    auto result = rt_test::compare_within_noise(test, test_var, ref, ref_var, 4096.0 / 16);
    INFO("worst z " << result.worst_z);
    CHECK(result.passed());
    // Without the reference's variance (same sample count claimed) the block would fail.
    CHECK_FALSE(rt_test::compare_within_noise(test, test_var, ref, ref_var, 1).passed());
}

TEST_CASE("noise statistic: where there is no noise, rounding passes and a real bias fails",
          "[ch01]") {
    // A noiseless image (like chapter 02's normals): zero variance everywhere.
    rt::image ref(32, 32), zero(32, 32), last_bits(32, 32), biased(32, 32);
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 32; ++x) {
            const float value = 0.999995f;
            ref.set(x, y, rt::color(value, value, value));
            // A few float ulps off, as a render in float rounds: not a bias.
            const float off = std::nextafter(std::nextafter(value, 2.0f), 2.0f);
            last_bits.set(x, y, rt::color(off, value, off));
            // One part in 10^4 off: a real, if small, bias.
            biased.set(x, y, rt::color(value, value * 0.9999f, value));
        }
    }
    CHECK(rt_test::compare_within_noise(last_bits, zero, ref, zero, 256).failed == 0);
    CHECK(rt_test::compare_within_noise(biased, zero, ref, zero, 256).failed == 4);
    // Black and noiseless must agree exactly.
    rt::image dark(32, 32);
    dark.set(3, 3, rt::color(0, 1e-30, 0));
    CHECK(rt_test::compare_within_noise(dark, zero, zero, zero, 256).failed == 1);
}
