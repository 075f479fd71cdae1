// A clear dielectric (glass, water, air bubbles): each hit either reflects or refracts, chosen
// at random with the Fresnel reflectance as the probability, so one ray continues and the
// average is right. Chapter 05.
// Snell: n1 sin(theta1) = n2 sin(theta2). The index ratio is 1/ior entering (front face) and
// ior leaving; an air bubble in glass is a sphere with ior = 1/1.5 inside the glass sphere.
#pragma once

#include "rt/materials/material.h"

namespace rt {

// How the reflectance is computed (refraction.h): Schlick's approximation (the book's choice, with
// the cosine taken on the less dense side) or the exact Fresnel equations.
enum class fresnel_model { schlick, exact };

class dielectric : public material {
  public:
    // ior: refractive index relative to the surrounding medium. Throws user_error unless > 0.
    explicit dielectric(real ior, fresnel_model model = fresnel_model::schlick);

    // Draws 1 sampler dimension (the choice between reflection and refraction).
    std::optional<scatter_sample> scatter(const ray& r_in, const hit_record& rec,
                                          sampler& s) const override;

    // The reflectance for a ray arriving at cos_theta to the normal, eta = n_in / n_out.
    real reflectance(real cos_theta, real eta) const;

  private:
    real ior;
    fresnel_model model;
};

}  // namespace rt
