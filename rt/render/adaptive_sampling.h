// Adaptive sampling: a pixel stops taking samples once the noise of its mean, as a screen would
// show it, is below a threshold. Chapter 17.
// The rule, asked by the render loop (render.h, stopping_rule) after `min_spp` samples and at
// every doubling after that (min_spp, 2 min_spp, 4 min_spp, ... below samples_per_pixel): with
// m the pixel's mean and s the standard error of that mean, per channel, the screen's noise is
// half the spread that +-s makes on the display curve,
//   noise = max over channels of (srgb(m + s) - srgb(m - s)) / 2,
// srgb being the sRGB curve clamped to [0, 1], in units of white. The pixel stops when noise
// <= threshold. So a dark pixel, where the curve is steep, keeps sampling for a noise a bright
// one may stop at, and a pixel far beyond white, whose every value shows as white, stops at
// its first check. Checks at doublings only: each one is a chance to stop on a lucky estimate
// of s (a pixel whose rare bright paths have not shown yet), and Sobol' points are balanced
// at powers of two. The image stays a function of the scene, the settings and the seed: each
// pixel decides from its own samples. Not unbiased: a pixel that stops early because its rare
// paths have not shown is darker than its mean; min_spp bounds how often that happens.
#pragma once

#include "rt/render/render.h"

namespace rt {

class display_noise_rule final : public stopping_rule {
  public:
    // Throws user_error unless 0 < threshold < 1 and min_spp >= 2 (a variance needs two).
    display_noise_rule(real threshold, int min_spp);

    int first_check() const override { return min_spp; }
    bool enough(const double (&mean)[3], const double (&m2)[3], int n) const override;

    // The screen's noise of a mean with these statistics (above), in units of white.
    static double display_noise(const double (&mean)[3], const double (&m2)[3], int n);

  private:
    double threshold;
    int min_spp;
};

}  // namespace rt
