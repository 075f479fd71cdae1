// Marble from Perlin noise: stripes along z whose phase is stirred by turbulence. Chapter 09.
//   gray = 0.5 (1 + sin(scale * z + 10 * turbulence(p)))
// This is the book's own formula (its noise_texture::value): the turbulence is taken at the
// unscaled point p; `scale` only sets the stripe frequency.
#pragma once

#include <cmath>

#include "rt/textures/perlin.h"
#include "rt/textures/texture.h"

namespace rt {

class noise_texture : public texture {
  public:
    explicit noise_texture(real stripe_scale, std::uint64_t seed = 0)
        : noise(seed), scale(stripe_scale) {}

    color value(real, real, const point3& p) const override {
        real gray = real(0.5) * (1 + std::sin(scale * p.z() + 10 * noise.turbulence(p, 7)));
        return color(gray, gray, gray);
    }
    bool uses_uv() const override { return false; }

  private:
    perlin noise;
    real scale;
};

}  // namespace rt
