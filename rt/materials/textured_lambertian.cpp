#include "rt/materials/textured_lambertian.h"

#include "rt/core/validate.h"

namespace rt {

textured_lambertian::textured_lambertian(std::shared_ptr<texture> a) : albedo(std::move(a)) {
    require_given(albedo, "lambertian albedo texture");
}

std::optional<scatter_sample> textured_lambertian::scatter(const ray& r_in, const hit_record& rec,
                                                           sampler& s) const {
    return scatter_diffuse(r_in, rec, s, albedo->value_at(rec));
}

}  // namespace rt
