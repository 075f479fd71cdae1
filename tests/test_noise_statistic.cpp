// The golden tests' "within its noise" statistic (noise_statistic.h) must pass an unbiased
// render and catch a biased one. [golden statistic, all chapters]
#include <catch2/catch.hpp>

#include "common/rng.h"
#include "noise_statistic.h"

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
    auto unbiased = rt_test::compare_within_noise(test, test_var, ref, ref_var);
    INFO("worst z " << unbiased.worst_z << " limit " << unbiased.z_limit);
    CHECK(unbiased.passed());

    // Brighten one 16x16 block by 2%: about 8 standard errors of that block's mean
    // (sigma of a pixel mean = 1/sqrt(12*16) ~ 0.072, block mean ~ 0.072/16 = 0.0045 per channel).
    for (int y = 16; y < 32; ++y)
        for (int x = 16; x < 32; ++x) test.set(x, y, test.get(x, y) * rt::real(1.02));
    auto biased = rt_test::compare_within_noise(test, test_var, ref, ref_var);
    CHECK_FALSE(biased.passed());
    CHECK(biased.worst_x == 16);
    CHECK(biased.worst_y == 16);
}
