#include "rt/integrators/mixture_tracer.h"

#include "rt/core/exercise.h"
#include "rt/core/validate.h"
#include "rt/geometry/spawn_ray.h"
#include "rt/materials/material.h"
#include "rt/render/ray_count.h"

namespace rt {

namespace {
std::shared_ptr<const hittable> given(std::shared_ptr<const hittable> world) {
    require_given(world, "scene world");
    return world;
}
}  // namespace

mixture_tracer::mixture_tracer(std::shared_ptr<const hittable> w, const background& b)
    : world(given(std::move(w))), sky(b), lights(*world, b) {}

color mixture_tracer::radiance(const ray& camera_ray, sampler& s, int max_depth) const {
    ray r = camera_ray;
    color radiance(0, 0, 0);
    color throughput(1, 1, 1);
    for (int segment = 0; segment < max_depth; ++segment) {
        hit_record rec;
        count_ray();
        if (!world->hit(r, interval(0, infinity), rec)) {
            radiance += throughput * sky.radiance(r.direction());
            break;
        }
        const material& surface = *rec.mat;
        radiance += throughput * surface.emitted(r, rec);
        s.start_segment(segment);  // [ch16]

        if (surface.lobe_kind() != lobe::evaluable || lights.empty()) {
            const std::optional<scatter_sample> next = surface.scatter(r, rec, s);
            if (!next) break;
            throughput = throughput * next->weight;
            r          = next->scattered;
            continue;
        }

        // [exercise mixture_tracer::radiance begin]
        vec3 wi;
        real material_pdf = 0;  // the material's density of wi
        if (s.next_1d() < real(0.5)) {
            const std::optional<scatter_sample> next = surface.scatter(r, rec, s);
            if (!next) break;
            wi           = unit_vector(next->scattered.direction());
            material_pdf = next->pdf;
        } else {
            real pick = s.next_1d();
            light_sample towards;
            if (!lights.sample(rec.p, pick, s.next_2d(), towards)) break;
            wi           = towards.wi;
            material_pdf = surface.pdf(r, rec, wi);
        }
        // The mixture's density of wi, whichever half drew it: both halves could have.
        real pdf = real(0.5) * material_pdf + real(0.5) * lights.pdf(rec.p, wi);
        color f  = surface.eval(r, rec, wi);
        if (!(pdf > 0) || is_black(f)) break;  // below the surface: no light comes that way
        throughput = throughput * f / pdf;
        r          = spawn_ray(rec, r, wi);
        // [exercise mixture_tracer::radiance end]
    }
    return radiance;
}

render_job mixture_trace(const scene& sc) {
    return {sc.cam, std::make_shared<mixture_tracer>(sc.world, sc.sky), sc.settings};
}

}  // namespace rt
