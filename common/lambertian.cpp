#include "lambertian.h"

#include "error.h"
#include "onb.h"
#include "sampling.h"
#include "validate.h"

namespace rt {

lambertian::lambertian(const color& a) : albedo(std::make_shared<solid_color>(a)) {
    require_reflectance(a, "lambertian albedo");
}

lambertian::lambertian(std::shared_ptr<texture> a) : albedo(std::move(a)) {
    if (!albedo) throw user_error("lambertian needs a texture");
}

bool lambertian::scatter(const ray& r_in, const hit_record& rec, sampler& s, color& attenuation,
                         ray& scattered) const {
    // The book's normal + random_unit_vector() has this same cosine density; sampling it in a
    // local frame needs no rejection loop and no degenerate-direction fix-up.
    vec3 direction = onb(rec.normal).to_world(sample_cosine_hemisphere(s.next_2d()));
    scattered      = rec.spawn_reflected_ray(direction, r_in.time());
    attenuation    = albedo->value(rec.u, rec.v, rec.p);
    return true;
}

}  // namespace rt
