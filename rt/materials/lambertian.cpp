#include "rt/materials/lambertian.h"

#include "rt/core/onb.h"
#include "rt/core/validate.h"
#include "rt/geometry/spawn_ray.h"
#include "rt/samplers/sampling.h"

namespace rt {

scatter_sample scatter_diffuse(const ray& r_in, const hit_record& rec, sampler& s,
                               const color& albedo) {
    // The book's normal + random_unit_vector() has this same cosine density; sampling it in a
    // local frame needs no rejection loop and no degenerate-direction fix-up.
    const vec3 local = sample_cosine_hemisphere(s.next_2d());
    scatter_sample sample{spawn_reflected_ray(rec, r_in, onb(rec.normal).to_world(local)), albedo};
    sample.from = lobe::evaluable;                   // [ch14]
    sample.pdf  = cosine_hemisphere_pdf(local.z());  // [ch14] the cosine, from the local frame
    return sample;
}

// [ch14 begin]
real diffuse_cosine_pdf(const hit_record& rec, const vec3& wi) {
    return cosine_hemisphere_pdf(dot(rec.normal, wi));
}
// [ch14 end]

lambertian::lambertian(const color& a) : albedo_(a) {
    require_reflectance(a, "lambertian albedo");
}

std::optional<scatter_sample> lambertian::scatter(const ray& r_in, const hit_record& rec,
                                                  sampler& s) const {
    return scatter_diffuse(r_in, rec, s, albedo_);
}

}  // namespace rt
