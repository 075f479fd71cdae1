#include "render.h"

#include <omp.h>

#include "progress.h"

namespace rt {

render_result render(const film& f, const camera& cam, const radiance_estimator& estimator,
                     const render_settings& settings) {
    const int width = f.width, height = f.height;
    const int spp = settings.samples_per_pixel;
    render_result result{image(width, height), image(width, height), 0};
    progress_meter progress(height, double(width) * spp, settings.quiet);

    // NOLINTNEXTLINE(clang-analyzer-deadcode.DeadStores): read by the omp pragma below
    const int threads = settings.threads > 0 ? settings.threads : omp_get_num_procs();
    // Dynamic scheduling: rows through glass cost more than rows of sky.
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int j = 0; j < height; ++j) {
        sampler s(settings.seed);
        for (int i = 0; i < width; ++i) {
            // Welford's running mean and sum of squared deviations m2, in double: the order is
            // fixed per pixel, so the result is too. Unlike sum and sum of squares, whose
            // difference cancels, it gives variance exactly 0 (and the mean exactly L) when every
            // sample is the same L, and m2 never goes negative.
            double mean[3] = {0, 0, 0}, m2[3] = {0, 0, 0};
            for (int k = 0; k < spp; ++k) {
                s.start_pixel_sample(i, j, k);
                color L = estimator.radiance(cam.get_ray(i, j, s), s, settings.max_depth);
                for (int c = 0; c < 3; ++c) {
                    double x     = double(L[c]);
                    double delta = x - mean[c];
                    mean[c] += delta / (k + 1);
                    m2[c] += delta * (x - mean[c]);
                }
            }
            color pixel_mean, variance;
            for (int c = 0; c < 3; ++c) {
                double sample_var = spp > 1 ? m2[c] / (spp - 1) : 0.0;
                pixel_mean[c]     = real(mean[c]);
                variance[c]       = real(sample_var / spp);
            }
            result.mean.set(i, j, pixel_mean);
            result.mean_variance.set(i, j, variance);
        }
        progress.row_done();
    }
    progress.finish();
    result.seconds = progress.elapsed_seconds();
    return result;
}

}  // namespace rt
