// The phase function of a participating medium that scatters equally in all directions:
// p(w) = 1 / (4 pi). Sampling it exactly makes the weight just the medium's albedo. Chapter 12.
#pragma once

#include <memory>

#include "rt/materials/material.h"
#include "rt/textures/texture.h"

namespace rt {

class isotropic : public material {
  public:
    explicit isotropic(const color& albedo);  // throws user_error outside [0, 1]
    explicit isotropic(std::shared_ptr<texture> albedo);

    // Draws 2 sampler dimensions: a uniform direction on the sphere.
    std::optional<scatter_sample> scatter(const ray& r_in, const hit_record& rec,
                                          sampler& s) const override;

    // [ch14 begin]
    // Every direction alike: f = albedo / (4 pi), no cosine (a medium has no surface).
    lobe lobe_kind() const override { return lobe::evaluable; }
    color eval(const ray& r_in, const hit_record& rec, const vec3& wi) const override;
    real pdf(const ray& r_in, const hit_record& rec, const vec3& wi) const override;
    // [ch14 end]

    const std::shared_ptr<texture>& albedo_texture() const { return albedo; }  // [ch19]

  private:
    std::shared_ptr<texture> albedo;
};

}  // namespace rt
