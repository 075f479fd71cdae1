// Tests for render.h (chapter 01): the images it returns are finite, reproducible bit for bit
// whatever the number of threads, change with the seed, and carry the per-pixel variance of the
// mean that their samples show. Chapter 01 has nothing to hit, so the estimators are the sky
// (sky_only) and, for a render with real noise, a sky whose brightness is drawn from the sampler.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "rt/camera/camera.h"
#include "rt/integrators/estimator.h"
#include "rt/integrators/sky_only.h"
#include "rt/render/film.h"
#include "rt/render/render.h"
#include "rt/samplers/independent_sampler.h"
#include "rt/scene/background.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::real;

// The sky scaled by a random factor in [0.5, 1.5): one sampler dimension per sample, so the
// image shows noise (and a variance) that depends on the pixel's own stream only.
class noisy_sky : public rt::radiance_estimator {
  public:
    color radiance(const rt::ray& r, rt::sampler& s, int) const override {
        return (real(0.5) + s.next_1d()) * sky.radiance(r.direction());
    }
    std::string_view name() const override { return "noisy sky"; }

  private:
    rt::background sky = rt::background::sky();
};

// 48 x 27 pixels at 16:9, the default camera.
struct small_view {
    rt::film f = rt::film::for_aspect(48, 16.0 / 9);
    rt::camera cam;
    small_view() { cam.initialize(f); }
};

rt::render_settings small(std::uint64_t seed, int threads) {
    rt::render_settings settings;
    settings.width             = 48;
    settings.samples_per_pixel = 8;
    settings.max_depth         = 50;
    settings.seed              = seed;
    settings.threads           = threads;
    return settings;
}

rt::render_result render(const rt::radiance_estimator& estimator, const rt::render_settings& s) {
    const small_view view;
    return rt::render(view.f, view.cam, estimator, s);
}

using rt_test::same_bits;

int count_non_finite(const rt::image& img) {
    int n = 0;
    for (float f : img.data()) n += std::isfinite(f) ? 0 : 1;
    return n;
}

}  // namespace

TEST_CASE("render: the mean and variance images have no NaN or Inf, and variance >= 0", "[ch01]") {
    auto result = render(noisy_sky(), small(1, 2));
    REQUIRE(result.mean.width() == 48);
    REQUIRE(result.mean.height() == 27);
    REQUIRE(result.mean_variance.width() == 48);
    REQUIRE(result.mean_variance.height() == 27);
    CHECK(count_non_finite(result.mean) == 0);
    CHECK(count_non_finite(result.mean_variance) == 0);
    int negative  = 0;
    float largest = 0;
    for (float v : result.mean_variance.data()) {
        if (v < 0) ++negative;
        largest = std::max(largest, v);
    }
    CHECK(negative == 0);
    CHECK(largest > 0);  // the estimator is noisy at 8 spp: the variance image is not blank
}

TEST_CASE("render: one thread or two give the same image, bit for bit", "[ch01]") {
    // The sky alone: only the camera's jitter is random.
    const rt::sky_only sky(rt::background::sky());
    auto one = render(sky, small(7, 1));
    auto two = render(sky, small(7, 2));
    CHECK(same_bits(one.mean, two.mean));
    CHECK(same_bits(one.mean_variance, two.mean_variance));
    // And an estimator that draws from the sampler too.
    auto noisy_one = render(noisy_sky(), small(7, 1));
    auto noisy_two = render(noisy_sky(), small(7, 2));
    CHECK(same_bits(noisy_one.mean, noisy_two.mean));
    CHECK(same_bits(noisy_one.mean_variance, noisy_two.mean_variance));
}

TEST_CASE("render: the same seed gives the same image twice, another seed another image",
          "[ch01]") {
    auto first  = render(noisy_sky(), small(7, 2));
    auto second = render(noisy_sky(), small(7, 2));
    CHECK(same_bits(first.mean, second.mean));
    CHECK(same_bits(first.mean_variance, second.mean_variance));
    auto other = render(noisy_sky(), small(8, 2));
    CHECK_FALSE(same_bits(first.mean, other.mean));
}

TEST_CASE("render: a pixel's mean and variance are those of its own samples", "[ch01]") {
    // Recompute two pixels by hand, in the order render() documents (sampler.h): the camera ray,
    // then the estimate; the mean of the samples, and the sample variance divided by spp. Both
    // are stored as float, so they agree to float precision (6e-8 relative); 1e-6 leaves room
    // for the variance's summation order.
    const small_view view;
    const noisy_sky estimator;
    auto settings = small(3, 2);
    auto result   = rt::render(view.f, view.cam, estimator, settings);
    rt::independent_sampler s(settings.seed);
    for (auto [i, j] : {std::pair{24, 13}, std::pair{3, 25}}) {
        const int spp = settings.samples_per_pixel;
        std::vector<color> samples;
        for (int k = 0; k < spp; ++k) {
            s.start_pixel_sample(i, j, k);
            samples.push_back(estimator.radiance(view.cam.get_ray(i, j, s), s, settings.max_depth));
        }
        for (int c = 0; c < 3; ++c) {
            double mean = 0, squares = 0;
            for (const color& L : samples) mean += double(L[c]) / spp;
            for (const color& L : samples) squares += (double(L[c]) - mean) * (double(L[c]) - mean);
            double variance_of_mean = squares / (spp - 1) / spp;
            INFO("pixel (" << i << ", " << j << ") channel " << c);
            CHECK(double(result.mean.get(i, j)[c]) == Approx(mean).epsilon(1e-6));
            CHECK(double(result.mean_variance.get(i, j)[c]) ==
                  Approx(variance_of_mean).epsilon(1e-6).margin(1e-30));
            CHECK(variance_of_mean > 0);  // a pixel that shows noise: the check is not 0 == 0
        }
    }
}

TEST_CASE("render: a pixel of constant radiance has variance exactly 0", "[ch01]") {
    // A uniform background: every sample of every pixel returns the same color c, whatever its
    // jitter, so the sample variance is 0 and the mean is c exactly. The color is not a power of
    // two on purpose: sum-of-squares formulas and blends like (1 - a) c + a c round differently
    // sample by sample, and would show a spurious variance.
    const color c(0.1, 0.7, 1.0 / 3.0);
    const rt::sky_only uniform(rt::background::uniform(c));
    for (int spp : {3, 8, 100}) {
        auto settings              = small(5, 2);
        settings.samples_per_pixel = spp;
        auto result                = render(uniform, settings);
        int not_zero = 0, not_c = 0;
        for (int j = 0; j < result.mean.height(); ++j) {
            for (int i = 0; i < result.mean.width(); ++i) {
                color v = result.mean_variance.get(i, j), m = result.mean.get(i, j);
                for (int ch = 0; ch < 3; ++ch) {
                    if (v[ch] != 0) ++not_zero;
                    if (float(m[ch]) != float(c[ch])) ++not_c;
                }
            }
        }
        INFO(spp << " spp: " << not_zero << " pixel channels with variance != 0, " << not_c
                 << " with a mean != c");
        CHECK(not_zero == 0);
        CHECK(not_c == 0);
    }
}

TEST_CASE("render: the image has the film's size, and a sky that varies shows it", "[ch01]") {
    // The book's first picture: the sky blends from white at the bottom to blue at the top, so
    // the top row is bluer (less red) than the bottom row, in every column.
    const rt::film f = rt::film::for_aspect(40, 2);
    rt::camera cam;
    cam.aspect_ratio = 2;
    cam.initialize(f);
    auto settings = small(1, 2);
    auto result   = rt::render(f, cam, rt::sky_only(rt::background::sky()), settings);
    REQUIRE(result.mean.width() == 40);
    REQUIRE(result.mean.height() == 20);
    int not_bluer = 0;
    for (int i = 0; i < 40; ++i)
        if (!(result.mean.get(i, 0).x() < result.mean.get(i, 19).x())) ++not_bluer;
    CHECK(not_bluer == 0);
}
