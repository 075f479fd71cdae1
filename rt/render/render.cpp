#include "rt/render/render.h"

#include <omp.h>

#include <atomic>
#include <chrono>
#include <string>

#include "rt/core/validate.h"
#include "rt/render/ray_count.h"

namespace rt {

pixel_window window_of(const film& f, const render_settings& settings) {
    if (!settings.crop) return pixel_window::whole(f);
    const pixel_window w = *settings.crop;
    const bool inside =
        0 <= w.x0 && w.x0 < w.x1 && w.x1 <= f.width && 0 <= w.y0 && w.y0 < w.y1 && w.y1 <= f.height;
    const std::string rule = "be a non-empty window X0,Y0,X1,Y1 inside the " +
                             std::to_string(f.width) + " x " + std::to_string(f.height) +
                             " image (0 <= X0 < X1 <= width, 0 <= Y0 < Y1 <= height)";
    require(inside, "crop", rule.c_str(),
            std::to_string(w.x0) + "," + std::to_string(w.y0) + "," + std::to_string(w.x1) + "," +
                std::to_string(w.y1));
    return w;
}

sample_range samples_of(const render_settings& settings) {
    const int spp = settings.samples_per_pixel;
    require(spp >= 1, "samples per pixel", "be at least 1", spp);
    if (!settings.samples) return {0, spp};
    const sample_range r = *settings.samples;
    const std::string rule =
        "satisfy 0 <= FROM < TO <= spp (" + std::to_string(spp) + ", the whole render's count)";
    require(0 <= r.from && r.from < r.to && r.to <= spp, "sample range FROM:TO", rule.c_str(),
            std::to_string(r.from) + ":" + std::to_string(r.to));
    return r;
}

render_result render(const film& f, const camera& cam, const radiance_estimator& estimator,
                     const render_settings& settings, row_observer* rows) {
    const pixel_window window = window_of(f, settings);
    const sample_range range  = samples_of(settings);
    const int width = window.width(), height = window.height();
    const int count = range.count();
    // NOLINTNEXTLINE(clang-analyzer-deadcode.DeadStores): read by the omp pragma below
    const int threads = settings.threads > 0 ? settings.threads : omp_get_num_procs();
    // [ch17 begin]
    require(!(settings.stop_early && settings.samples), "sample range FROM:TO",
            "be left out when pixels may stop early (adaptive sampling)",
            std::to_string(range.from) + ":" + std::to_string(range.to));
    const int first_check = settings.stop_early ? settings.stop_early->first_check() : 0;
    // [ch17 end]
    render_result result{image(width, height), image(width, height), 0, window, range, 0, threads};
    const auto start = std::chrono::steady_clock::now();

    std::atomic<std::uint64_t> rays{0}, samples_taken{0};
#pragma omp parallel num_threads(threads)
    {
        // Each thread counts its own rays (ray_count.h); what it counted here joins the total
        // once, at the end, so the hot loop never touches shared memory for it.
        const std::uint64_t rays_before = rays_traced_by_this_thread;
        std::uint64_t taken_here        = 0;
        // Dynamic scheduling: rows through glass cost more than rows of sky.
#pragma omp for schedule(dynamic, 1)
        for (int row = 0; row < height; ++row) {
            const int j                            = window.y0 + row;
            const std::unique_ptr<sampler> numbers = settings.make_sampler(settings.seed);
            sampler& s                             = *numbers;
            for (int col = 0; col < width; ++col) {
                const int i = window.x0 + col;
                // Welford's running mean and sum of squared deviations m2, in double: the order
                // is fixed per pixel, so the result is too. Unlike sum and sum of squares, whose
                // difference cancels, it gives variance exactly 0 (and the mean exactly L) when
                // every sample is the same L, and m2 never goes negative.
                double mean[3] = {0, 0, 0}, m2[3] = {0, 0, 0};
                int taken      = count;        // samples this pixel takes
                int next_check = first_check;  // [ch17]
                for (int k = range.from; k < range.to; ++k) {
                    s.start_pixel_sample(i, j, k);
                    color L     = estimator.radiance(cam.get_ray(i, j, s), s, settings.max_depth);
                    const int n = k - range.from + 1;
                    for (int c = 0; c < 3; ++c) {
                        double x     = double(L[c]);
                        double delta = x - mean[c];
                        mean[c] += delta / n;
                        m2[c] += delta * (x - mean[c]);
                    }
                    // [ch17 begin]
                    if (n == next_check && n < count) {
                        if (settings.stop_early->enough(mean, m2, n)) {
                            taken = n;
                            break;
                        }
                        next_check *= 2;
                    }
                    // [ch17 end]
                }
                taken_here += std::uint64_t(taken);
                color pixel_mean, variance;
                for (int c = 0; c < 3; ++c) {
                    double sample_var = taken > 1 ? m2[c] / (taken - 1) : 0.0;
                    pixel_mean[c]     = real(mean[c]);
                    variance[c]       = real(sample_var / taken);
                }
                result.mean.set(col, row, pixel_mean);
                result.mean_variance.set(col, row, variance);
            }
            if (rows) rows->row_done();
        }
        rays += rays_traced_by_this_thread - rays_before;
        samples_taken += taken_here;
    }
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.rays           = rays.load();
    result.camera_samples = samples_taken.load();
    return result;
}

}  // namespace rt
