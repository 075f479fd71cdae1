// Independent random numbers, chapter 01's sampler: each pixel sample owns one PCG32 stream,
// chosen by hash(pixel, seed) and advanced to sample_index * 65536 (as pbrt-v4's
// StartPixelSample), so it may draw up to 65536 dimensions before it would overlap the next.
#pragma once

#include <cstdint>
#include <memory>

#include "rt/core/rng.h"
#include "rt/samplers/sampler.h"

namespace rt {

class independent_sampler final : public sampler {
  public:
    static constexpr std::uint64_t dimensions_per_sample = 65536;
    // From one pixel sample's start to the next: the same jump in every stream, computed at
    // compile time, so that starting sample k costs O(log k) steps.
    static constexpr pcg32::jump sample_stride = pcg32::jump_of(dimensions_per_sample);

    explicit independent_sampler(std::uint64_t render_seed) : seed(render_seed) {}
    static std::unique_ptr<sampler> make(std::uint64_t render_seed) {
        return std::make_unique<independent_sampler>(render_seed);
    }

    void start_pixel_sample(int px, int py, int sample_index) override {
        auto pixel = (std::uint64_t(std::uint32_t(px)) << 32u) | std::uint32_t(py);
        rng.set_sequence(hash_values(pixel, seed, 0), mix_bits(seed));
        rng.apply(pcg32::repeated(sample_stride, std::uint64_t(sample_index)));
    }

    real next_1d() override { return rng.uniform(); }
    sample2 next_2d() override {
        real u = rng.uniform();
        return {u, rng.uniform()};
    }

    const char* name() const override { return "independent"; }

  private:
    std::uint64_t seed;
    pcg32 rng;
};

}  // namespace rt
