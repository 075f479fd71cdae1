#include "rt/materials/dielectric.h"

#include <cmath>

#include "rt/core/exercise.h"
#include "rt/core/validate.h"
#include "rt/geometry/spawn_ray.h"
#include "rt/materials/optics.h"
#include "rt/materials/refraction.h"

namespace rt {

namespace {
fresnel_model scene_default = fresnel_model::schlick;
}  // namespace

fresnel_model default_fresnel_model() {
    return scene_default;
}

void set_default_fresnel_model(fresnel_model model) {
    scene_default = model;
}

dielectric::dielectric(real index, fresnel_model m) : ior(index), model(m) {
    require_positive(index, "dielectric index of refraction");
}

real dielectric::reflectance(real cos_theta, real eta) const {
    switch (model) {
        case fresnel_model::exact:
            return fresnel_reflectance(cos_theta, eta);
        case fresnel_model::book_schlick:
            return schlick_reflectance_incident(cos_theta, eta);
        case fresnel_model::schlick:
            break;
    }
    return schlick_reflectance(cos_theta, eta);
}

std::optional<scatter_sample> dielectric::scatter(const ray& r_in, const hit_record& rec,
                                                  sampler& s) const {
    // [exercise dielectric::scatter begin]
    real choice    = s.next_1d();
    real eta       = rec.front_face ? 1 / ior : ior;
    vec3 unit_dir  = unit_vector(r_in.direction());
    real cos_theta = std::min(dot(-unit_dir, rec.normal), real(1));

    bool reflects =
        total_internal_reflection(cos_theta, eta) || reflectance(cos_theta, eta) > choice;
    vec3 direction = reflects ? reflect(unit_dir, rec.normal) : refract(unit_dir, rec.normal, eta);

    return scatter_sample{spawn_ray(rec, r_in, direction),
                          color(1, 1, 1)};  // clear: absorbs nothing
    // [exercise dielectric::scatter end]
}

}  // namespace rt
