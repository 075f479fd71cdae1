// Rays recorded from a real render: every ray the path tracer asks the scene about, camera rays
// and every bounce after them, in render order (single thread, so the order is fixed).
#pragma once

#include <cstddef>
#include <vector>

#include "rt/scene/scene.h"

namespace rt_bench {

struct recorded_rays {
    // Rounded to float; a spawned ray's origin is moved off its surface by the float build's
    // offset instead of this build's (single_precision.h), on the same side.
    std::vector<rt::ray> rays;
    // The real scene's nearest hit along each of these rays when it is on a surface (p NaN for
    // a miss or a scattering event in a medium), to check a copy of the scene's shapes: the
    // point and the float build's bound on its error (single_precision.h).
    struct surface_hit {
        rt::point3 p;
        rt::real error = 0;
    };
    std::vector<surface_hit> surface_hits;
    std::size_t recorded  = 0;  // rays the render traced, before thinning to `rays`
    std::size_t respawned = 0;  // of those, spawned from a hit (the origin re-offset)
};

// Renders sc at its own width and max depth with samples_per_pixel, on one thread, and keeps
// at most max_rays of the rays it traced, evenly spread over the render.
recorded_rays record_rays(const rt::scene& sc, int samples_per_pixel, std::size_t max_rays);

}  // namespace rt_bench
