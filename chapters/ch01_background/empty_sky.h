// Chapter 01's scene: nothing at all, under the sky.
#pragma once

#include <memory>

#include "rt/integrators/sky_only.h"
#include "rt/render/render.h"
#include "rt/scene/background.h"

// Nothing to hit: every ray sees the sky. The camera is chapter 01's own: at the origin, looking
// down -z with a 90 degree vertical view, 16:9.
inline rt::render_job empty_sky() {
    rt::render_job job;
    job.estimator = std::make_shared<rt::sky_only>(rt::background::sky());
    // A gradient needs few samples; one segment per path, since nothing can be hit.
    job.settings = {.width = 400, .samples_per_pixel = 4, .max_depth = 1};
    return job;
}
