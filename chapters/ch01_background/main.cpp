// Chapter 01: the background. With nothing in the scene every ray sees the sky, a blend from
// white (looking down) to light blue (looking up) by the y of the ray's unit direction:
//   color = (1 - a) * white + a * blue,   a = (y + 1) / 2.
#include <memory>

#include "rt/integrators/sky_only.h"
#include "rt/program/command_line.h"
#include "rt/scene/background.h"

// Nothing to hit: every ray sees the sky. The camera is chapter 01's own: at the origin, looking
// down -z with a 90 degree vertical view, 16:9.
rt::render_job empty_sky() {
    rt::render_job job;
    job.estimator = std::make_shared<rt::sky_only>(rt::background::sky());
    // A gradient needs few samples; one segment per path, since nothing can be hit.
    job.settings = {.width = 400, .samples_per_pixel = 4, .max_depth = 1};
    return job;
}

int main(int argc, char** argv) {
    return rt::command_line("ch01_background").run(argc, argv, empty_sky);
}
