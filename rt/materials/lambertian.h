// An ideal diffuse reflector: f = albedo / pi, the same from every viewing direction. Chapter 03
// (chapter 08's textured_lambertian lets the albedo vary over the surface).
// Sampling cos(theta)/pi cancels f * cos(theta) / pdf down to the albedo.
#pragma once

#include "rt/materials/material.h"

namespace rt {

// What an ideal diffuse reflector of this albedo scatters: a cosine-weighted direction about
// the normal, weighted by the albedo. Draws 2 sampler dimensions.
scatter_sample scatter_diffuse(const ray& r_in, const hit_record& rec, sampler& s,
                               const color& albedo);

// [ch14 begin]
// |cos| / pi of unit wi about the hit's normal on the side the ray came from; 0 below it. It is
// both scatter_diffuse()'s density and, times the albedo, f |cos|.
real diffuse_cosine_pdf(const hit_record& rec, const vec3& wi);
// [ch14 end]

class lambertian : public material {
  public:
    // Throws user_error unless every channel of albedo is in [0, 1] (more would create energy).
    explicit lambertian(const color& albedo);

    // Draws 2 sampler dimensions: a cosine-weighted direction about the normal.
    std::optional<scatter_sample> scatter(const ray& r_in, const hit_record& rec,
                                          sampler& s) const override;

    const color& albedo() const { return albedo_; }

    // [ch14 begin]
    lobe lobe_kind() const override { return lobe::evaluable; }
    color eval(const ray&, const hit_record& rec, const vec3& wi) const override {
        return albedo_ * diffuse_cosine_pdf(rec, wi);
    }
    real pdf(const ray&, const hit_record& rec, const vec3& wi) const override {
        return diffuse_cosine_pdf(rec, wi);
    }
    // [ch14 end]

  private:
    color albedo_;
};

}  // namespace rt
