// An emitter: a surface that sends out light and reflects none. Chapter 10.
// Like book 2 (whose Cornell scenes we match), it emits its texture's color on BOTH faces:
// seen from behind, a light quad glows just as brightly. The integrator adds the emission
// at every hit: L = Le + weight * L(scattered).
#pragma once

#include <memory>

#include "rt/core/exercise.h"
#include "rt/materials/material.h"
#include "rt/textures/texture.h"

namespace rt {

class diffuse_light : public material {
  public:
    // Radiance per channel must be >= 0 and finite; throws user_error otherwise.
    explicit diffuse_light(const color& radiance);
    explicit diffuse_light(std::shared_ptr<texture> radiance);

    color emitted(const ray&, const hit_record& rec) const override {
        // [exercise diffuse_light::emitted begin]
        return radiance->value_at(rec);
        // [exercise diffuse_light::emitted end]
    }

    // Absorbs every ray: a light does not reflect.
    std::optional<scatter_sample> scatter(const ray&, const hit_record&, sampler&) const override {
        return std::nullopt;
    }

    const std::shared_ptr<texture>& emission() const { return radiance; }  // [ch19]

  private:
    std::shared_ptr<texture> radiance;
};

}  // namespace rt
