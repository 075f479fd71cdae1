// Tests for render.h (chapter 01): the images it returns are finite, reproducible bit for bit
// whatever the number of threads, change with the seed, and carry the per-pixel variance of the
// mean that their samples show.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <utility>
#include <vector>

#include "common/integrator.h"
#include "common/lambertian.h"
#include "common/quad.h"
#include "common/render.h"
#include "common/sphere.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::point3, rt::real, rt::vec3;

// Chapter 03's scene, small: matte spheres on a finite floor under the sky, 48 x 27 pixels.
rt::scene spheres_on_floor() {
    auto floor = std::make_shared<rt::lambertian>(color(0.8, 0.8, 0.0));
    auto blue  = std::make_shared<rt::lambertian>(color(0.1, 0.2, 0.5));
    auto red   = std::make_shared<rt::lambertian>(color(0.7, 0.2, 0.1));
    rt::scene sc;
    sc.world.add(
        std::make_shared<rt::quad>(point3(-3, -0.5, -4), vec3(6, 0, 0), vec3(0, 0, 5), floor));
    sc.world.add(std::make_shared<rt::sphere>(point3(0, 0, -1.2), 0.5, blue));
    sc.world.add(std::make_shared<rt::sphere>(point3(1.1, 0, -1.5), 0.5, red));
    sc.world.add(std::make_shared<rt::sphere>(point3(0.45, -0.35, -0.55), 0.15, blue));
    sc.sky              = rt::background::sky();
    sc.cam.aspect_ratio = 16.0 / 9.0;
    sc.cam.image_width  = 48;
    sc.cam.vfov         = 90;
    sc.cam.lookfrom     = point3(0, 0, 0);
    sc.cam.lookat       = point3(0, 0, -1);
    sc.cam.initialize();
    return sc;
}

rt::render_settings small(std::uint64_t seed, int threads) {
    rt::render_settings settings;
    settings.samples_per_pixel = 8;
    settings.max_depth         = 50;
    settings.seed              = seed;
    settings.threads           = threads;
    settings.quiet             = true;
    return settings;
}

using rt_test::same_bits;

int count_non_finite(const rt::image& img) {
    int n = 0;
    for (float f : img.data()) n += std::isfinite(f) ? 0 : 1;
    return n;
}

}  // namespace

TEST_CASE("render: the mean and variance images have no NaN or Inf, and variance >= 0", "[ch01]") {
    auto sc     = spheres_on_floor();
    auto result = rt::render(sc, small(1, 2));
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
    CHECK(largest > 0);  // matte surfaces are noisy at 8 spp: the variance image is not blank
}

TEST_CASE("render: one thread or two give the same image, bit for bit", "[ch01]") {
    auto sc  = spheres_on_floor();
    auto one = rt::render(sc, small(7, 1));
    auto two = rt::render(sc, small(7, 2));
    CHECK(same_bits(one.mean, two.mean));
    CHECK(same_bits(one.mean_variance, two.mean_variance));
}

TEST_CASE("render: the same seed gives the same image twice, another seed another image",
          "[ch01]") {
    auto sc     = spheres_on_floor();
    auto first  = rt::render(sc, small(7, 2));
    auto second = rt::render(sc, small(7, 2));
    CHECK(same_bits(first.mean, second.mean));
    CHECK(same_bits(first.mean_variance, second.mean_variance));
    auto other = rt::render(sc, small(8, 2));
    CHECK_FALSE(same_bits(first.mean, other.mean));
}

TEST_CASE("render: a pixel's mean and variance are those of its own samples", "[ch01]") {
    // Recompute two pixels by hand, in the order render() documents (sampler.h): the mean of the
    // paths, and the sample variance divided by spp. Both are stored as float, so they agree to
    // float precision (6e-8 relative); 1e-6 leaves room for the variance's summation order.
    auto sc       = spheres_on_floor();
    auto settings = small(3, 2);
    auto result   = rt::render(sc, settings);
    rt::sampler s(settings.seed);
    for (auto [i, j] : {std::pair{24, 13}, std::pair{34, 13}}) {  // the blue and red spheres
        const int spp = settings.samples_per_pixel;
        std::vector<color> samples;
        for (int k = 0; k < spp; ++k) {
            s.start_pixel_sample(i, j, k);
            samples.push_back(rt::trace_path(sc, sc.cam.get_ray(i, j, s), s, settings.max_depth));
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
    // Nothing in the world and a uniform background: every path of every pixel returns the same
    // color c, whatever its jitter, so the sample variance is 0 and the mean is c exactly. The
    // color is not a power of two on purpose: sum-of-squares formulas and blends like
    // (1 - a) c + a c round differently sample by sample, and would show a spurious variance.
    const color c(0.1, 0.7, 1.0 / 3.0);
    rt::scene sc;
    sc.sky              = rt::background::uniform(c);
    sc.cam.aspect_ratio = 16.0 / 9.0;
    sc.cam.image_width  = 48;
    sc.cam.initialize();
    for (int spp : {3, 8, 100}) {
        auto settings              = small(5, 2);
        settings.samples_per_pixel = spp;
        auto result                = rt::render(sc, settings);
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
