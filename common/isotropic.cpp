#include "isotropic.h"

#include "error.h"
#include "sampling.h"
#include "validate.h"

namespace rt {

isotropic::isotropic(const color& a) : albedo(std::make_shared<solid_color>(a)) {
    require_reflectance(a, "isotropic albedo");
}

isotropic::isotropic(std::shared_ptr<texture> a) : albedo(std::move(a)) {
    if (!albedo) throw user_error("isotropic needs a texture");
}

bool isotropic::scatter(const ray& r_in, const hit_record& rec, sampler& s, color& attenuation,
                        ray& scattered) const {
    scattered   = ray(rec.p, sample_uniform_sphere(s.next_2d()), r_in.time());
    attenuation = albedo->value(rec.u, rec.v, rec.p);
    return true;
}

}  // namespace rt
