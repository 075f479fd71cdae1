// A diffuse reflector whose albedo varies over the surface: chapter 03's lambertian with the
// albedo looked up in a texture at each hit. Chapter 08.
#pragma once

#include <memory>

#include "rt/materials/lambertian.h"
#include "rt/textures/texture.h"

namespace rt {

class textured_lambertian : public material {
  public:
    // The texture's values must lie in [0, 1] (an albedo); throws user_error if it is missing.
    explicit textured_lambertian(std::shared_ptr<texture> albedo);

    // Draws 2 sampler dimensions, as lambertian does.
    std::optional<scatter_sample> scatter(const ray& r_in, const hit_record& rec,
                                          sampler& s) const override;

    // [ch14 begin]
    lobe lobe_kind() const override { return lobe::evaluable; }
    color eval(const ray&, const hit_record& rec, const vec3& wi) const override {
        return albedo->value_at(rec) * diffuse_cosine_pdf(rec, wi);
    }
    real pdf(const ray&, const hit_record& rec, const vec3& wi) const override {
        return diffuse_cosine_pdf(rec, wi);
    }
    // [ch14 end]

    const std::shared_ptr<texture>& albedo_texture() const { return albedo; }  // [ch19]

  private:
    std::shared_ptr<texture> albedo;
};

}  // namespace rt
