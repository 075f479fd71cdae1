#include "rt/materials/textured_lambertian.h"

#include "rt/core/validate.h"

namespace rt {

textured_lambertian::textured_lambertian(std::shared_ptr<texture> a) : albedo(std::move(a)) {
    require_given(albedo, "lambertian albedo texture");
}

bool textured_lambertian::scatter(const ray& r_in, const hit_record& rec, sampler& s,
                                  color& attenuation, ray& scattered) const {
    scattered   = scatter_diffuse(r_in, rec, s);
    attenuation = albedo->value_at(rec);
    return true;
}

}  // namespace rt
