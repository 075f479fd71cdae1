#include "rt/materials/metal.h"

#include "rt/core/exercise.h"
#include "rt/core/validate.h"
#include "rt/geometry/spawn_ray.h"
#include "rt/materials/optics.h"
#include "rt/samplers/sampling.h"

namespace rt {

metal::metal(const color& a, real f) : albedo(a), fuzz(f) {
    require_reflectance(a, "metal albedo");
    require_in_range(f, 0, 1, "metal fuzz");
}

std::optional<scatter_sample> metal::scatter(const ray& r_in, const hit_record& rec,
                                             sampler& s) const {
    // [exercise metal::scatter begin]
    sample2 ball_uv = s.next_2d();
    real ball_w     = s.next_1d();
    vec3 reflected  = unit_vector(reflect(r_in.direction(), rec.normal));
    vec3 direction  = reflected + fuzz * sample_uniform_ball(ball_uv, ball_w);
    if (!(dot(direction, rec.normal) > 0)) return std::nullopt;  // fuzzed under the surface
    return scatter_sample{spawn_ray(rec, r_in, direction), albedo};
    // [exercise metal::scatter end]
}

// [ch17 begin]
real metal::spread_pdf(const ray& r_in, const hit_record& rec, const vec3& wi) const {
    if (!spread_is_evaluable() || !(dot(wi, rec.normal) > 0)) return 0;
    const vec3 mirror = unit_vector(reflect(r_in.direction(), rec.normal));
    const real c      = dot(wi, mirror);
    // |w x m|^2 rather than 1 - c^2, which cancels for the narrow cones of a small fuzz.
    const real h2 = fuzz * fuzz - cross(wi, mirror).length_squared();
    if (!(c > 0) || !(h2 > 0)) return 0;
    const real h = std::sqrt(h2);
    return h * (3 * c * c + h2) / (2 * pi * fuzz * fuzz * fuzz);
}

color metal::spread_eval(const ray& r_in, const hit_record& rec, const vec3& wi) const {
    return spread_pdf(r_in, rec, wi) * albedo;
}
// [ch17 end]

}  // namespace rt
