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
