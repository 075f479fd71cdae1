// Low-discrepancy samples: Owen-scrambled Sobol' points, indexed per pixel as in Burley's
// "Practical Hash-based Owen Scrambling" (JCGT 2020), the Sobol-Burley sampler of Cycles.
// Chapter 16.
//
// Independent random numbers clump and leave gaps; the first two dimensions of Sobol's sequence
// put exactly one of every 2^m consecutive points in each of 2^m equal cells of the unit square
// (any cell shape of that area with power-of-two sides), so the error of a smooth integrand falls
// faster than 1/sqrt(N). For every draw of a sample (a slot of the layout in sampler.h) we take
// the 2D Sobol' point of the pixel sample's index:
//   - the index is shuffled by an Owen scramble keyed by (pixel, slot, seed), so each pixel and
//     each slot walks the points in its own order while any 2^m consecutive ones stay a net;
//   - each coordinate is Owen-scrambled with its own key, which keeps the net property and makes
//     every point uniformly distributed, so estimates stay unbiased.
// Pixels, slots and seeds are therefore decorrelated by hashing, not by the sample count: the
// points of sample index k do not depend on how many samples the render takes (pbrt-v4's ZSobol
// does), so sample ranges (--samples) and crops stay exact parts of a whole render.
// Deterministic: the numbers depend only on (pixel, sample index, slot, seed).
#pragma once

#include <cstdint>
#include <memory>

#include "rt/samplers/sampler.h"

namespace rt {

class sobol_sampler final : public sampler {
  public:
    explicit sobol_sampler(std::uint64_t render_seed);
    static std::unique_ptr<sampler> make(std::uint64_t render_seed) {
        return std::make_unique<sobol_sampler>(render_seed);
    }

    void start_pixel_sample(int px, int py, int sample_index) override;
    real next_1d() override;
    sample2 next_2d() override;
    const char* name() const override { return "sobol"; }

    // The building blocks, for tests.
    static std::uint32_t sobol_dimension_0(std::uint32_t index);  // van der Corput: bits reversed
    static std::uint32_t sobol_dimension_1(std::uint32_t index);
    // A random permutation of 32-bit values that maps every aligned block of 2^m values (by
    // their leading bits) onto another: an Owen scramble of the binary fraction x / 2^32.
    static std::uint32_t owen_scramble(std::uint32_t x, std::uint32_t key);

  private:
    // The key of the current draw: the pixel's key mixed with the draw's place in the layout.
    std::uint64_t draw_key();
    // owen_scramble(index, key): the draw's own order of the pixel's sample indices.
    std::uint32_t shuffled_index(std::uint32_t key) const;

    std::uint64_t seed_key;
    std::uint64_t pixel_key      = 0;
    std::uint32_t index_reversed = 0;  // the sample index, bits reversed
};

}  // namespace rt
