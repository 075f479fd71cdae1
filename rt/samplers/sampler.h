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

#include "rt/core/rng.h"

namespace rt {

struct sample2 {
    real u, v;
};

class sampler {
  public:
    static constexpr std::uint64_t dimensions_per_sample = 65536;
    // From one pixel sample's start to the next: the same jump in every stream, computed at
    // compile time, so a sample's start costs O(log sample_index) steps where
    // advance(sample_index * 65536) took 16 more.
    static constexpr pcg32::jump sample_stride = pcg32::jump_of(dimensions_per_sample);

    explicit sampler(std::uint64_t render_seed) : seed(render_seed) {}
    virtual ~sampler() = default;  // [ch16]

    // [ch16] virtual: chapter 16's sobol_sampler draws the same dimensions from Sobol' points.
    virtual void start_pixel_sample(int px, int py, int sample_index) {
        auto pixel = (std::uint64_t(std::uint32_t(px)) << 32u) | std::uint32_t(py);
        rng.set_sequence(hash_values(pixel, seed, 0), mix_bits(seed));
        rng.apply(pcg32::repeated(sample_stride, std::uint64_t(sample_index)));
        draw = 0;  // [ch16]
    }

    virtual real next_1d() { return rng.uniform(); }  // [ch16] virtual
    virtual sample2 next_2d() {                       // [ch16] virtual
        real u = rng.uniform();
        return {u, rng.uniform()};
    }

    // [ch16 begin]
    // What kind of numbers these are, for the record of a run (--stats-out).
    virtual const char* name() const { return "independent"; }

    // The layout of a path's draws, for samplers whose numbers depend on which draw they are
    // (chapter 16's Sobol' points): the camera's draws come first (at most 4: jitter, lens,
    // instant), then path segment k's start at draw 4 + 8 k, whatever the segments before it
    // drew. So draw j of segment k means the same thing in every sample of a pixel, and its
    // points stay evenly spread. Independent numbers need no layout: this sampler ignores it.
    static constexpr int camera_draws = 4, draws_per_segment = 8;
    void start_segment(int segment) { draw = camera_draws + segment * draws_per_segment; }
    // [ch16 end]

  protected:
    int draw = 0;  // [ch16] the next draw's place in the layout (start_segment)

  private:
    std::uint64_t seed;
    pcg32 rng;
};

}  // namespace rt
