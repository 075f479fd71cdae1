// Renders a scene into an image, in parallel over rows. Chapter 01.
// Each pixel averages samples_per_pixel paths; the result depends only on the scene, the
// settings and the seed, never on the number of threads (see sampler.h).
#pragma once

#include <cstdint>

#include "image.h"
#include "scene.h"

namespace rt {

struct render_settings {
    int samples_per_pixel = 100;    // Camera paths averaged per pixel
    int max_depth         = 50;     // Ray segments followed per path at most
    std::uint64_t seed    = 1;      // Selects the random streams
    int threads           = 0;      // 0 = all cores
    bool quiet            = false;  // No progress on stderr
};

struct render_result {
    image mean;           // the estimate: the average of the samples per pixel
    image mean_variance;  // its variance per channel: sample variance / samples_per_pixel
    double seconds = 0;   // wall-clock time of the render loop
};

// sc.cam must be initialized.
render_result render(const scene& sc, const render_settings& settings);

}  // namespace rt
