// Renders an image, in parallel over rows. Chapter 01.
// Each pixel averages samples_per_pixel estimates of the radiance along camera rays; the result
// depends only on the scene, the settings and the seed, never on the number of threads (see
// sampler.h).
#pragma once

#include <cstdint>
#include <memory>

#include "camera.h"
#include "estimator.h"
#include "film.h"
#include "image.h"

namespace rt {

// How to render: a scene brings its own defaults (its report settings); flags override them.
struct render_settings {
    int width             = 400;    // Image width in pixels; the height from the aspect ratio
    int samples_per_pixel = 100;    // Camera samples averaged per pixel
    int max_depth         = 50;     // Ray segments followed per path at most
    std::uint64_t seed    = 1;      // Selects the random streams
    int threads           = 0;      // 0 = all cores
    bool quiet            = false;  // No progress on stderr
};

// Everything a chapter's program renders: how the camera looks, how a sample is estimated, and
// the scene's own default settings.
struct render_job {
    std::shared_ptr<camera> cam = std::make_shared<camera>();
    std::shared_ptr<const radiance_estimator> estimator;
    render_settings settings;
};

struct render_result {
    image mean;           // the estimate: the average of the samples per pixel
    image mean_variance;  // its variance per channel: sample variance / samples_per_pixel
    double seconds = 0;   // wall-clock time of the render loop
};

// cam must have been initialized for f.
render_result render(const film& f, const camera& cam, const radiance_estimator& estimator,
                     const render_settings& settings);

}  // namespace rt
