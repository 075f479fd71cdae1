// A metal: mirror reflection r = v - 2 (v.n) n, blurred by moving the reflected direction's tip
// by up to `fuzz` inside a ball. Chapter 04. A fuzzed ray that points below the surface is
// absorbed: the surface shadows it.
#pragma once

#include "rt/materials/material.h"

namespace rt {

class metal : public material {
  public:
    // Throws user_error unless albedo is in [0, 1] per channel and fuzz in [0, 1] (0 = mirror).
    metal(const color& albedo, real fuzz);

    // Draws 3 sampler dimensions (a point in the unit ball), even for a perfect mirror.
    std::optional<scatter_sample> scatter(const ray& r_in, const hit_record& rec,
                                          sampler& s) const override;

    // [ch17 begin]
    // The fuzz's density, for chapter 17's MIS (material.h: spread_is_evaluable). A point
    // uniform in the ball of radius fuzz about the unit mirror direction m lies, seen from the
    // hit, in direction w with density (1 / ball volume) times the integral of t^2 dt along w's
    // chord through the ball: with c = w.m and h = sqrt(fuzz^2 - |w x m|^2) the chord runs from
    // c - h to c + h, so pdf(w) = h (3 c^2 + h^2) / (2 pi fuzz^3), 0 off the cone the ball
    // subtends and below the surface (those rays are absorbed: pdf integrates to the share
    // kept). The sample's weight, albedo, is spread_eval / spread_pdf: eval = albedo pdf.
    bool spread_is_evaluable() const override { return fuzz >= min_evaluable_fuzz; }
    color spread_eval(const ray& r_in, const hit_record& rec, const vec3& wi) const override;
    real spread_pdf(const ray& r_in, const hit_record& rec, const vec3& wi) const override;
    // Below it, a spread so narrow (a density about 3 / (2 pi fuzz^2), 5e11 at 1e-6) that a
    // float's rounding of the mirror direction is a good part of the fuzz: a mirror to MIS.
    static constexpr real min_evaluable_fuzz = real(1e-6);
    // [ch17 end]

    // [ch19 begin]
    // What it was made with, for a scene file (rt/scene_files).
    const color& albedo_color() const { return albedo; }
    real fuzziness() const { return fuzz; }
    // [ch19 end]

  private:
    color albedo;
    real fuzz;
};

}  // namespace rt
