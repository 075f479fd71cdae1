// Does a noisy render agree with a converged reference, within its own noise? Used by the
// golden tests (tools/noise_compare) and tested in test_noise_statistic.cpp.
//
// The statistic: cut the image into square blocks; per block and channel compare the mean of the
// test render with the mean of the reference:
//     z = (mean_test - mean_ref) / sqrt(sum_i var_test_i + sum_i var_ref_i) * n
// where var_i is each pixel's variance of the mean (the renderer's --variance-out) and n the
// block's pixel count. Pixels are independent (one random stream each), so the block mean's
// variance is the sum of the pixel variances over n^2, and by the central limit theorem (a block
// averages n * spp samples) z is close to standard normal when the render is unbiased.
// The test's own per-pixel variance is unreliable at few samples: a pixel where 2% of the paths
// reach something darker usually shows 16 equal samples and a variance of 0. So var_test_i is
// the larger of the test's estimate and the reference's, scaled from its sample count to the
// test's (variance of a mean ~ 1/spp): the reference has seen the rare paths. A block
// fails when |z| exceeds the Bonferroni bound for the whole image at family-wise rate alpha, so an
// unbiased render fails by chance at most that often, while a bias of a few standard errors in
// any block (a wrong material, a shadow in the wrong place, a missing light) is caught.
// Rounding: the images are float32 files, and a render in float (or with another libm) rounds
// differently from the reference; where the noise is nearly 0 (the normals of chapter 02, a
// uniform sky) that last-bit difference alone would give a huge z. So each block's standard
// error has a floor of rounding_ulps float ulps of the block's summed radiance, added in
// quadrature, as one systematic error (rounding in a block is correlated, not independent). It
// is ~1e-6 of the value: far below any bias the test exists to find.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "rt/image/image.h"

namespace rt_test {

struct noise_comparison {
    int blocks     = 0;                               // number of (block, channel) tests
    int failed     = 0;                               // how many exceeded z_limit
    double z_limit = 0;                               // the Bonferroni bound used
    double worst_z = 0;                               // the largest |z| seen
    int worst_x = 0, worst_y = 0, worst_channel = 0;  // where (block origin in pixels)
    bool passed() const { return failed == 0; }
};

// The two-sided standard-normal quantile: the z with P(|Z| > z) = p, by bisection on erfc.
inline double two_sided_normal_quantile(double p) {
    double lo = 0, hi = 40;
    for (int i = 0; i < 200; ++i) {
        double mid                                      = (lo + hi) / 2;
        (std::erfc(mid / std::sqrt(2.0)) > p ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
}

// Float ulps (2^-24 relative) that a render may differ from the reference by rounding alone.
inline constexpr double rounding_ulps = 16;

// spp_ratio = reference samples per pixel / test samples per pixel.
inline noise_comparison compare_within_noise(const rt::image& test, const rt::image& test_var,
                                             const rt::image& ref, const rt::image& ref_var,
                                             double spp_ratio, int block_size = 16,
                                             double alpha = 1e-3) {
    noise_comparison result;
    const int w = test.width(), h = test.height();
    const int bx = (w + block_size - 1) / block_size, by = (h + block_size - 1) / block_size;
    result.blocks  = bx * by * 3;
    result.z_limit = two_sided_normal_quantile(alpha / result.blocks);
    for (int y0 = 0; y0 < h; y0 += block_size) {
        for (int x0 = 0; x0 < w; x0 += block_size) {
            for (int c = 0; c < 3; ++c) {
                double diff = 0, var = 0, magnitude = 0;
                for (int y = y0; y < std::min(h, y0 + block_size); ++y) {
                    for (int x = x0; x < std::min(w, x0 + block_size); ++x) {
                        diff += double(test.get(x, y)[c]) - double(ref.get(x, y)[c]);
                        double ref_v = double(ref_var.get(x, y)[c]);
                        var += std::max(double(test_var.get(x, y)[c]), ref_v * spp_ratio) + ref_v;
                        magnitude += std::fabs(double(ref.get(x, y)[c]));
                    }
                }
                const double rounding = rounding_ulps * std::ldexp(1.0, -24) * magnitude;
                var += rounding * rounding;
                // A black block with no variance at all must agree exactly.
                double z = var > 0 ? diff / std::sqrt(var) : (diff == 0 ? 0.0 : INFINITY);
                if (std::fabs(z) > result.z_limit) ++result.failed;
                if (std::fabs(z) > std::fabs(result.worst_z)) {
                    result.worst_z       = z;
                    result.worst_x       = x0;
                    result.worst_y       = y0;
                    result.worst_channel = c;
                }
            }
        }
    }
    return result;
}

}  // namespace rt_test
