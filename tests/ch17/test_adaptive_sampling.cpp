// Tests for adaptive sampling (rt/render/adaptive_sampling.h and the render loop's stopping rule,
// render.h): the display noise a rule computes; pixels stop exactly at the checks the rule
// names and only when their noise allows; the image does not depend on the threads; without a
// rule, or with one that never stops a pixel, the image is bit for bit the render without it;
// bad thresholds and split renders are refused. And its bias, which the header states: a
// fraction of a pixel's noise at stopping where every few samples show the noise, and where
// light comes from rare samples exactly what the chance of stopping before any of them predicts.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string_view>

#include "rt/camera/camera.h"
#include "rt/core/error.h"
#include "rt/image/display_encoding.h"
#include "rt/integrators/estimator.h"
#include "rt/render/adaptive_sampling.h"
#include "rt/render/film.h"
#include "rt/render/render.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::real;
using rt_test::same_bits;

// Left half of the image (rays with x < 0): a constant 0.5, no noise. Right half: a value
// uniform in [0, 1): noise that no small threshold lets stop.
class half_noisy : public rt::radiance_estimator {
  public:
    color radiance(const rt::ray& r, rt::sampler& s, int) const override {
        const real u = s.next_1d();
        if (r.direction().x() < 0) return color(0.5, 0.5, 0.5);
        return color(u, u, u);
    }
    std::string_view name() const override { return "half noisy"; }
};

// Light that comes from rare samples: 0.9 with probability p, else 0.
class rare_light : public rt::radiance_estimator {
  public:
    explicit rare_light(double p_) : p(p_) {}
    color radiance(const rt::ray&, rt::sampler& s, int) const override {
        const real v = s.next_1d() < real(p) ? real(0.9) : real(0);
        return color(v, v, v);
    }
    std::string_view name() const override { return "rare light"; }

  private:
    double p;
};

// A value uniform in [0.1, 0.5): noise in every sample, mean 0.3, below white (where the
// display clamps, a pixel whose mean is one standard error beyond white shows no noise).
class uniform_light : public rt::radiance_estimator {
  public:
    color radiance(const rt::ray&, rt::sampler& s, int) const override {
        const real v = real(0.1) + real(0.4) * s.next_1d();
        return color(v, v, v);
    }
    std::string_view name() const override { return "uniform light"; }
};

struct view {
    rt::film f;
    rt::camera cam;
    explicit view(int width) : f(rt::film::for_aspect(width, 1)) { cam.initialize(f); }
};

rt::render_settings settings(int spp, int threads, std::shared_ptr<const rt::stopping_rule> rule) {
    rt::render_settings s;
    s.samples_per_pixel = spp;
    s.seed              = 5;
    s.threads           = threads;
    s.stop_early        = std::move(rule);
    return s;
}

double mean_of(const rt::image& img) {
    double sum = 0;
    for (float v : img.data()) sum += double(v);
    return sum / double(img.data().size());
}

}  // namespace

TEST_CASE("display_noise_rule: half the display spread of +- one standard error", "[ch17]") {
    // Every sample the same: no noise, whatever the mean (white and beyond too).
    const double flat_m2[3] = {0, 0, 0};
    for (double m : {0.0, 0.02, 0.5, 1.0, 7.0}) {
        const double mean[3] = {m, m, m};
        CHECK(rt::display_noise_rule::display_noise(mean, flat_m2, 16) == 0);
    }
    // A standard error of 0.01 about 0.5 in the green channel only: (n - 1) n se^2 = m2.
    const int n           = 64;
    const double se       = 0.01;
    const double mean[3]  = {0.5, 0.5, 0.5};
    const double m2[3]    = {0, se * se * n * (n - 1), 0};
    const double expected = (rt::linear_to_srgb(0.51) - rt::linear_to_srgb(0.49)) / 2;
    const double noise    = rt::display_noise_rule::display_noise(mean, m2, n);
    CHECK(noise == Approx(expected).epsilon(1e-12));
    // The same noise in the dark, where the curve is steeper, shows more; far beyond white,
    // where every value shows as white, none.
    const double dark[3]   = {0.02, 0.02, 0.02};
    const double bright[3] = {5, 5, 5};
    CHECK(rt::display_noise_rule::display_noise(dark, m2, n) > 2 * noise);
    CHECK(rt::display_noise_rule::display_noise(bright, m2, n) == 0);
}

TEST_CASE("display_noise_rule: bad thresholds and minimum counts are refused", "[ch17]") {
    CHECK_THROWS_AS(rt::display_noise_rule(0, 16), rt::user_error);
    CHECK_THROWS_AS(rt::display_noise_rule(1, 16), rt::user_error);
    CHECK_THROWS_AS(rt::display_noise_rule(real(-0.1), 16), rt::user_error);
    CHECK_THROWS_AS(rt::display_noise_rule(real(0.01), 1), rt::user_error);
    CHECK_NOTHROW(rt::display_noise_rule(real(0.01), 2));
}

TEST_CASE("adaptive sampling: flat pixels stop at the first check, noisy ones take every sample",
          "[ch17]") {
    const view v(32);
    const half_noisy estimator;
    const auto rule           = std::make_shared<rt::display_noise_rule>(real(0.001), 8);
    const rt::render_result r = rt::render(v.f, v.cam, estimator, settings(64, 2, rule));
    // 32 x 32 pixels: 16 columns flat (8 samples each), 16 noisy (all 64): the camera's jitter
    // never moves a pixel across the image's middle.
    CHECK(r.camera_samples == std::uint64_t(32 * 16 * 8 + 32 * 16 * 64));
    // The flat half is exact, and its variance 0; the noisy half's mean is that of 64 samples.
    for (int y = 0; y < 32; ++y) {
        CHECK(r.mean.get(3, y).x() == real(0.5));
        CHECK(r.mean_variance.get(3, y).x() == 0);
        CHECK(r.mean_variance.get(28, y).x() > 0);
    }
    // Without a rule, every pixel takes every sample.
    const rt::render_result all = rt::render(v.f, v.cam, estimator, settings(64, 2, nullptr));
    CHECK(all.camera_samples == std::uint64_t(32 * 32 * 64));
}

TEST_CASE("adaptive sampling: a pixel stops only at a check, min_spp times a power of two",
          "[ch17]") {
    // A sample's standard deviation is 0.4 / sqrt(12) = 0.115 about 0.3, where the display
    // curve's slope is 0.89: a pixel's display noise after n samples is about 0.10 / sqrt(n),
    // at or below 0.025 from n = 16 on: most stop at the third check (24).
    const view v(16);
    const uniform_light estimator;
    const auto rule = std::make_shared<rt::display_noise_rule>(real(0.025), 6);
    for (int spp : {40, 48}) {
        INFO("spp " << spp);
        const rt::render_result r = rt::render(v.f, v.cam, estimator, settings(spp, 2, rule));
        // Each pixel's count is one of 6, 12, 24 or spp: the total is a sum of those.
        const std::uint64_t pixels = 16 * 16;
        CHECK(r.camera_samples >= pixels * 6);
        CHECK(r.camera_samples < pixels * std::uint64_t(spp));
        // Pixel by pixel, from one pixel renders (a crop): the count is on the schedule.
        int stopped_early = 0;
        for (int x = 0; x < 16; x += 5) {
            rt::render_settings one = settings(spp, 1, rule);
            one.crop                = rt::pixel_window{x, 7, x + 1, 8};
            const std::uint64_t n   = rt::render(v.f, v.cam, estimator, one).camera_samples;
            INFO("pixel " << x << ": " << n << " samples");
            CHECK((n == 6 || n == 12 || n == 24 || n == std::uint64_t(spp)));
            stopped_early += n < std::uint64_t(spp) ? 1 : 0;
        }
        CHECK(stopped_early > 0);
    }
}

TEST_CASE("adaptive sampling: one thread or two, the same image and the same count", "[ch17]") {
    const view v(24);
    const uniform_light estimator;
    const auto rule             = std::make_shared<rt::display_noise_rule>(real(0.02), 4);
    const rt::render_result one = rt::render(v.f, v.cam, estimator, settings(64, 1, rule));
    const rt::render_result two = rt::render(v.f, v.cam, estimator, settings(64, 2, rule));
    CHECK(same_bits(one.mean, two.mean));
    CHECK(same_bits(one.mean_variance, two.mean_variance));
    CHECK(one.camera_samples == two.camera_samples);
}

TEST_CASE("adaptive sampling: a rule that never stops a pixel leaves the image as it was",
          "[ch17]") {
    const view v(24);
    const uniform_light uniform;
    // A threshold no pixel meets: every pixel is checked at 4, 8 and 16 samples, and goes on.
    const auto never = std::make_shared<rt::display_noise_rule>(real(1e-9), 4);
    const auto with  = rt::render(v.f, v.cam, uniform, settings(32, 2, never));
    const auto plain = rt::render(v.f, v.cam, uniform, settings(32, 2, nullptr));
    CHECK(same_bits(with.mean, plain.mean));
    CHECK(same_bits(with.mean_variance, plain.mean_variance));
    CHECK(with.camera_samples == plain.camera_samples);
}

TEST_CASE("adaptive sampling: not with a split render's sample range", "[ch17]") {
    const view v(8);
    const uniform_light estimator;
    rt::render_settings s =
        settings(16, 1, std::make_shared<rt::display_noise_rule>(real(0.01), 4));
    s.samples = rt::sample_range{0, 8};
    CHECK_THROWS_AS(rt::render(v.f, v.cam, estimator, s), rt::user_error);
}

TEST_CASE(
    "adaptive sampling: its bias, none beyond noise where every few samples show the "
    "noise, and as predicted where light comes from rare samples",
    "[ch17]") {
    const view v(64);  // 4096 pixels
    SECTION("noise in every sample: biased by a fraction of a pixel's noise at stopping") {
        // The display noise depends on the pixel's mean too (the curve is steeper in the dark),
        // so a pixel whose estimate came out bright stops a little sooner than one whose came
        // out dark: the image comes out a little bright. Most pixels stop at 32 samples, where
        // one pixel's standard error is 0.115 / sqrt(32) = 0.020; the bias is a fraction of that
        // (measured: +0.0043, 0.21 of it; the image's own noise, below 0.0009, cannot hide it).
        const uniform_light estimator;
        const auto rule           = std::make_shared<rt::display_noise_rule>(real(0.02), 4);
        const rt::render_result r = rt::render(v.f, v.cam, estimator, settings(64, 2, rule));
        REQUIRE(r.camera_samples < std::uint64_t(64 * 64 * 64));  // some pixels stopped
        INFO("image mean " << mean_of(r.mean));
        CHECK(mean_of(r.mean) > 0.3);
        CHECK(mean_of(r.mean) - 0.3 < 0.35 * 0.020);
        // Without the rule: no bias beyond the image's noise (0.115 / sqrt(64) / 64 = 2.2e-4).
        const rt::render_result all = rt::render(v.f, v.cam, estimator, settings(64, 2, nullptr));
        CHECK(std::fabs(mean_of(all.mean) - 0.3) < 5 * 2.2e-4);
    }
    SECTION("light from rare samples: pixels that see none by the first check stop dark") {
        // 0.9 with probability p = 1/32, else 0 (mean 0.9 p; never beyond white, so no pixel's
        // noise vanishes by clamping). First check after 8 samples: a pixel sees no bright
        // sample by then with probability q = (31/32)^8 = 0.776, shows no noise and stops at 0.
        // Any other pixel's noise is far above 0.02 at every check (its mean is dark, where the
        // display curve is steep): it takes all 64. So the image's mean is
        //   0.9 (1 - q) (E[bright in 8 | seen] + 56 p) / 64 = 0.9 (8 p + 56 p (1 - q)) / 64,
        // 0.32 of the estimator's mean: the bias the header states, predicted exactly.
        const double p = 1.0 / 32, q = std::pow(1 - p, 8);
        const double expected = 0.9 * (8 * p + 56 * p * (1 - q)) / 64;
        const rare_light estimator(p);
        const auto rule           = std::make_shared<rt::display_noise_rule>(real(0.02), 8);
        const rt::render_result r = rt::render(v.f, v.cam, estimator, settings(64, 2, rule));
        INFO("image mean " << mean_of(r.mean) << ", predicted " << expected << ", the estimator's "
                           << 0.9 * p);
        // A pixel's mean has a standard deviation below 0.9 sqrt(p / 8) / 8 = 0.007 (at least 8
        // samples); over 4096 pixels the image's, below 1.1e-4.
        CHECK(std::fabs(mean_of(r.mean) - expected) < 5 * 1.1e-4);
        CHECK(mean_of(r.mean) < 0.5 * 0.9 * p);
    }
}
