#include "rt/render/adaptive_sampling.h"

#include <algorithm>
#include <cmath>

#include "rt/core/validate.h"
#include "rt/image/display_encoding.h"

namespace rt {

display_noise_rule::display_noise_rule(real t, int m) : threshold(double(t)), min_spp(m) {
    require(t > 0 && t < 1, "noise threshold", "be above 0 and below 1 (units of white)", t);
    require(m >= 2, "adaptive sampling's minimum spp", "be at least 2", m);
}

double display_noise_rule::display_noise(const double (&mean)[3], const double (&m2)[3], int n) {
    double noise = 0;
    for (int c = 0; c < 3; ++c) {
        const double standard_error = std::sqrt(m2[c] / (n - 1) / n);
        const double spread =
            linear_to_srgb(mean[c] + standard_error) - linear_to_srgb(mean[c] - standard_error);
        noise = std::max(noise, spread / 2);
    }
    return noise;
}

bool display_noise_rule::enough(const double (&mean)[3], const double (&m2)[3], int n) const {
    return display_noise(mean, m2, n) <= threshold;
}

}  // namespace rt
