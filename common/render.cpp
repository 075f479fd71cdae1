#include "render.h"

#include <omp.h>

#include "integrator.h"
#include "progress.h"

namespace rt {

render_result render(const scene& sc, const render_settings& settings) {
    const camera& cam = sc.cam;
    const int width = cam.image_width, height = cam.image_height();
    const int spp = settings.samples_per_pixel;
    render_result result{image(width, height), image(width, height), 0};
    progress_meter progress(height, double(width) * spp, settings.quiet);

    const int threads = settings.threads > 0 ? settings.threads : omp_get_num_procs();
    // Dynamic scheduling: rows through glass cost more than rows of sky.
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int j = 0; j < height; ++j) {
        sampler s(settings.seed);
        for (int i = 0; i < width; ++i) {
            // Sums in double: the order is fixed per pixel, so the result is too.
            double sum[3] = {0, 0, 0}, sum_squares[3] = {0, 0, 0};
            for (int k = 0; k < spp; ++k) {
                s.start_pixel_sample(i, j, k);
                color L = trace_path(sc, cam.get_ray(i, j, s), s, settings.max_depth);
                for (int c = 0; c < 3; ++c) {
                    sum[c] += double(L[c]);
                    sum_squares[c] += double(L[c]) * double(L[c]);
                }
            }
            color mean, variance;
            for (int c = 0; c < 3; ++c) {
                double m = sum[c] / spp;
                double sample_var =
                    spp > 1 ? std::max(0.0, (sum_squares[c] - spp * m * m) / (spp - 1)) : 0.0;
                mean[c]     = real(m);
                variance[c] = real(sample_var / spp);
            }
            result.mean.set(i, j, mean);
            result.mean_variance.set(i, j, variance);
        }
        progress.row_done();
    }
    progress.finish();
    result.seconds = progress.elapsed_seconds();
    return result;
}

}  // namespace rt
