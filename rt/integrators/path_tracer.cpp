#include "rt/integrators/path_tracer.h"

#include "rt/core/exercise.h"
#include "rt/core/validate.h"
#include "rt/materials/material.h"
#include "rt/render/ray_count.h"

namespace rt {

path_tracer::path_tracer(std::shared_ptr<const hittable> w, const background& b)
    : world(std::move(w)), sky(b) {
    require_given(world, "scene world");
}

color path_tracer::radiance(const ray& camera_ray, sampler& s, int max_depth) const {
    ray r = camera_ray;
    color radiance(0, 0, 0);
    color throughput(1, 1, 1);  // product of the scattering weights along the path so far
    for (int segment = 0; segment < max_depth; ++segment) {
        hit_record rec;
        count_ray();
        // Spawned rays start off their surface (spawn_ray), so any t > 0 is a real hit.
        if (!world->hit(r, interval(0, infinity), rec)) {
            radiance += throughput * sky.radiance(r.direction());
            break;
        }
        // [exercise path_tracer::emission begin] [ch10]
        radiance += throughput * rec.mat->emitted(r, rec);  // [ch10]
        // [exercise path_tracer::emission end] [ch10]
        s.start_segment(segment);  // [ch16] the layout of sampler.h
        // [exercise path_tracer::radiance begin]
        const std::optional<scatter_sample> next = rec.mat->scatter(r, rec, s);
        if (!next) break;  // absorbed
        throughput = throughput * next->weight;
        r          = next->scattered;
        // [exercise path_tracer::radiance end]
    }
    return radiance;
}

render_job path_trace(const scene& sc) {
    return {sc.cam, std::make_shared<path_tracer>(sc.world, sc.sky), sc.settings};
}

}  // namespace rt
