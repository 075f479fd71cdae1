#include "rt/integrators/show_normals.h"

#include "rt/core/exercise.h"
#include "rt/core/validate.h"
#include "rt/render/ray_count.h"

namespace rt {

normals_estimator::normals_estimator(std::shared_ptr<const hittable> w, const background& b)
    : world(std::move(w)), sky(b) {
    require_given(world, "scene world");
}

color normals_estimator::radiance(const ray& r, sampler&, int) const {
    // [exercise normals_estimator::radiance begin]
    hit_record rec;
    count_ray();
    if (!world->hit(r, interval(0, infinity), rec)) return sky.radiance(r.direction());
    vec3 outward = rec.front_face ? rec.normal : -rec.normal;
    return real(0.5) * (outward + color(1, 1, 1));
    // [exercise normals_estimator::radiance end]
}

render_job show_normals(const scene& sc) {
    return {sc.cam, std::make_shared<normals_estimator>(sc.world, sc.sky), sc.settings};
}

}  // namespace rt
