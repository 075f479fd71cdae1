// An ideal diffuse reflector: f = albedo / pi, the same from every viewing direction. Chapter 03.
// Sampling cos(theta)/pi cancels f * cos(theta) / pdf down to the albedo.
#pragma once

#include <memory>

#include "material.h"
#include "texture.h"

namespace rt {

class lambertian : public material {
  public:
    // Throws user_error unless every channel of albedo is in [0, 1] (more would create energy).
    explicit lambertian(const color& albedo);
    // An albedo that varies over the surface (chapter 08); its values must lie in [0, 1].
    explicit lambertian(std::shared_ptr<texture> albedo);

    // Draws 2 sampler dimensions: a cosine-weighted direction about the normal.
    bool scatter(const ray& r_in, const hit_record& rec, sampler& s, color& attenuation,
                 ray& scattered) const override;

    bool uses_uv() const override { return albedo->uses_uv(); }

  private:
    std::shared_ptr<texture> albedo;
};

}  // namespace rt
