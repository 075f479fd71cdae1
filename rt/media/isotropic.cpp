#include "rt/media/isotropic.h"

#include "rt/core/validate.h"
#include "rt/samplers/sampling.h"

namespace rt {

isotropic::isotropic(const color& a) : albedo(std::make_shared<solid_color>(a)) {
    require_reflectance(a, "isotropic albedo");
}

isotropic::isotropic(std::shared_ptr<texture> a) : albedo(std::move(a)) {
    require_given(albedo, "isotropic albedo");
}

std::optional<scatter_sample> isotropic::scatter(const ray& r_in, const hit_record& rec,
                                                 sampler& s) const {
    scatter_sample sample{r_in.continued(rec.p, sample_uniform_sphere(s.next_2d())),
                          albedo->value_at(rec)};
    sample.from = lobe::evaluable;       // [ch14]
    sample.pdf  = uniform_sphere_pdf();  // [ch14]
    return sample;
}

// [ch14 begin]
color isotropic::eval(const ray&, const hit_record& rec, const vec3&) const {
    return albedo->value_at(rec) * uniform_sphere_pdf();
}

real isotropic::pdf(const ray&, const hit_record&, const vec3&) const {
    return uniform_sphere_pdf();
}
// [ch14 end]

}  // namespace rt
