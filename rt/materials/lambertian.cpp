#include "rt/materials/lambertian.h"

#include "rt/core/onb.h"
#include "rt/core/validate.h"
#include "rt/samplers/sampling.h"

namespace rt {

ray scatter_diffuse(const ray& r_in, const hit_record& rec, sampler& s) {
    // The book's normal + random_unit_vector() has this same cosine density; sampling it in a
    // local frame needs no rejection loop and no degenerate-direction fix-up.
    vec3 direction = onb(rec.normal).to_world(sample_cosine_hemisphere(s.next_2d()));
    return rec.spawn_reflected_ray(r_in, direction);
}

// [ch14 begin]
real diffuse_cosine_pdf(const hit_record& rec, const vec3& wi) {
    return cosine_hemisphere_pdf(dot(rec.normal, wi));
}
// [ch14 end]

lambertian::lambertian(const color& a) : albedo_(a) {
    require_reflectance(a, "lambertian albedo");
}

bool lambertian::scatter(const ray& r_in, const hit_record& rec, sampler& s, color& attenuation,
                         ray& scattered) const {
    scattered   = scatter_diffuse(r_in, rec, s);
    attenuation = albedo_;
    return true;
}

}  // namespace rt
