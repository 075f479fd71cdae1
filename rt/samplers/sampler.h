// The source of every random number a render uses: what a sampler is. Chapter 01 (the pixel
// jitter of anti-aliasing is its first use); independent_sampler.h is chapter 01's, chapter 16
// adds Sobol' points (sobol_sampler.h).
// A pixel sample's numbers depend only on the pixel, the sample's index and the render's seed,
// never on the thread that renders it nor on which part of the image is rendered (crops).
//
// Dimensions are drawn in a fixed order per camera sample, and only where the scene uses them:
//   the camera: 2 for the pixel jitter, then 2 for the lens position where the camera has a
//   lens (aperture > 0, chapter 06), then 1 for the instant where its shutter is open
//   (chapter 07);
//   then per path segment, the material's own: lambertian 2, metal 3, dielectric 1,
//   isotropic 2. Participating media (chapter 12) draw nothing: they hash the ray instead.
// So a feature of a later chapter never moves the samples of an earlier chapter's scene.
#pragma once

#include <cstdint>
#include <memory>

#include "rt/core/scalar.h"

namespace rt {

struct sample2 {
    real u, v;
};

class sampler {
  public:
    virtual ~sampler() = default;

    // Begins the numbers of sample `sample_index` of pixel (px, py).
    virtual void start_pixel_sample(int px, int py, int sample_index) = 0;

    // The next number of the sample, uniform in [0, 1); the next two, as a point of [0, 1)^2.
    virtual real next_1d()    = 0;
    virtual sample2 next_2d() = 0;

    // What kind of numbers these are ("independent", "sobol"), for the record of a run.
    virtual const char* name() const = 0;

    // [ch16 begin]
    // The layout of a path's draws, for samplers whose numbers depend on which draw they are
    // (chapter 16's Sobol' points): the camera's draws come first (at most 4: jitter, lens,
    // instant), then path segment k's start at draw 4 + 8 k, whatever the segments before it
    // drew. So draw j of segment k means the same thing in every sample of a pixel, and its
    // points stay evenly spread. Independent numbers need no layout: their sampler ignores it.
    static constexpr int camera_draws = 4, draws_per_segment = 8;
    void start_segment(int segment) { draw = camera_draws + segment * draws_per_segment; }
    // [ch16 end]
    // [ch17 begin]
    // Draws beside the layout, for an estimate a segment may add (chapter 17's in-scattering
    // towards the lights): segment k's side draws start at draw 2^30 + 8 k, far past any path's
    // own, so adding them moves no other draw and none is shared with another use.
    static constexpr int side_draws_from = 1 << 30;
    void start_side_draws(int segment) { draw = side_draws_from + segment * draws_per_segment; }
    // [ch17 end]
    // [ch16 begin]

  protected:
    int draw = 0;  // the next draw's place in the layout (start_segment)
    // [ch16 end]
};

// Makes the sampler one thread of a render draws from, for the render's seed.
using sampler_factory = std::unique_ptr<sampler> (*)(std::uint64_t seed);

}  // namespace rt

// Chapter 01's sampler, seen wherever the interface is: a call through sampler& can then be
// inlined as independent_sampler's, checked by a comparison of its type, in every file that
// draws (GCC's speculative devirtualization), and is an ordinary virtual call for any other.
#include "rt/samplers/independent_sampler.h"
