// A clear dielectric (glass, water, air bubbles): each hit either reflects or refracts, chosen
// at random with the Fresnel reflectance as the probability, so one ray continues and the
// average is right. Chapter 05.
// Snell: n1 sin(theta1) = n2 sin(theta2). The index ratio is 1/ior entering (front face) and
// ior leaving; an air bubble in glass is a sphere with ior = 1/1.5 inside the glass sphere.
#pragma once

#include "rt/materials/material.h"

namespace rt {

// How the reflectance is computed (refraction.h): Schlick's approximation with the cosine taken
// on the less dense side (ours), the exact Fresnel equations, or Schlick's with the incident
// cosine on both sides (the book's form, to compare with a render of the book's code).
enum class fresnel_model { schlick, exact, book_schlick };

// The model of a dielectric built without one: schlick, unless a program's --fresnel chose
// another before it built its scene (chapters/ch05_dielectric/fresnel_option.h). It is read only
// while a scene is built, so a render never sees it change.
fresnel_model default_fresnel_model();
void set_default_fresnel_model(fresnel_model model);

class dielectric : public material {
  public:
    // index: refractive index relative to the surrounding medium. Throws user_error unless > 0.
    explicit dielectric(real index) : dielectric(index, default_fresnel_model()) {}
    dielectric(real index, fresnel_model model);

    // Draws 1 sampler dimension (the choice between reflection and refraction).
    std::optional<scatter_sample> scatter(const ray& r_in, const hit_record& rec,
                                          sampler& s) const override;

    // The reflectance for a ray arriving at cos_theta to the normal, eta = n_in / n_out.
    real reflectance(real cos_theta, real eta) const;

    // [ch19 begin]
    // What it was made with, for a scene file (rt/scene_files).
    real refraction_index() const { return ior; }
    fresnel_model fresnel() const { return model; }
    // [ch19 end]

  private:
    real ior;
    fresnel_model model;
};

}  // namespace rt
