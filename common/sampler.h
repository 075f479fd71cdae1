// The source of every random number a render uses. Chapter 01 (the pixel jitter of
// anti-aliasing is its first use).
// Each pixel sample owns one PCG32 stream, chosen by hash(pixel, seed) and advanced to
// sample_index * 65536, so a pixel's value depends only on the scene, the settings and the seed:
// never on the thread that renders it, nor on which part of the image is rendered (crops).
//
// Dimensions are drawn in a fixed order per camera sample, and only where the scene uses them:
//   the camera: 2 for the pixel jitter, then 2 for the lens position where the camera has a
//   lens (aperture > 0, chapter 06), then 1 for the instant where its shutter is open
//   (chapter 07);
//   then per path segment, the material's own: lambertian 2, metal 3, dielectric 1,
//   isotropic 2. Participating media (chapter 12) draw nothing: they hash the ray instead.
// So a feature of a later chapter never moves the samples of an earlier chapter's scene.
// Each pixel sample may use up to 65536 dimensions before it would overlap the next one.
#pragma once

#include <cstdint>

#include "rng.h"

namespace rt {

struct sample2 {
    real u, v;
};

class sampler {
  public:
    static constexpr std::uint64_t dimensions_per_sample = 65536;

    explicit sampler(std::uint64_t render_seed) : seed(render_seed) {}

    void start_pixel_sample(int px, int py, int sample_index) {
        auto pixel = (std::uint64_t(std::uint32_t(px)) << 32u) | std::uint32_t(py);
        rng.set_sequence(hash_values(pixel, seed, 0), mix_bits(seed));
        rng.advance(std::uint64_t(sample_index) * dimensions_per_sample);
    }

    real next_1d() { return rng.uniform(); }
    sample2 next_2d() {
        real u = rng.uniform();
        return {u, rng.uniform()};
    }

  private:
    std::uint64_t seed;
    pcg32 rng;
};

}  // namespace rt
