// Marble from Perlin noise: stripes along z whose phase is stirred by turbulence. Chapter 09.
//   s = scale * p,  gray = 0.5 (1 + sin(s.z + 10 * turbulence(s)))
// This is the book's own formula in the edition our scenes follow (v4.0.0-alpha.1's
// noise_texture::value): `scale` sets both the stripe frequency and the size of the veins.
// v3.2.3 and the v4.0 releases take the turbulence at the unscaled point p, which gives
// coarser veins for a scale above 1 (book 2's two Perlin spheres use 4).
#pragma once

#include <cmath>

#include "rt/core/exercise.h"
#include "rt/textures/perlin.h"
#include "rt/textures/texture.h"

namespace rt {

class noise_texture : public texture {
  public:
    // The Perlin tables of a fresh book_random(seed); the layout seed, 1 unless set, gives the
    // book's own marble where the texture is the first thing its scene draws.
    explicit noise_texture(real stripe_scale, std::uint32_t seed = book_layout_seed())
        : noise(seed), scale(stripe_scale) {}
    // The tables drawn from `draws`, where the book's scene builds its texture midway.
    noise_texture(real stripe_scale, book_random& draws) : noise(draws), scale(stripe_scale) {}

    color value(real, real, const point3& p) const override {
        // [exercise noise_texture::value begin]
        const point3 s = scale * p;
        real gray      = real(0.5) * (1 + std::sin(s.z() + 10 * noise.turbulence(s, 7)));
        return color(gray, gray, gray);
        // [exercise noise_texture::value end]
    }
    bool uses_uv() const override { return false; }

    // [ch19 begin]
    // What it was made with, for a scene file (rt/scene_files).
    real stripe_scale() const { return scale; }
    const perlin& tables() const { return noise; }
    // [ch19 end]

  private:
    perlin noise;
    real scale;
};

}  // namespace rt
