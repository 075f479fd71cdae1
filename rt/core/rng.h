// PCG32 (O'Neill 2014): a small, fast generator with 2^63 independent streams and O(log n)
// jump-ahead, so every pixel sample can own its own reproducible stream. Chapter 01.
// state' = state * 6364136223846793005 + inc;  output = rotr32(xorshifted, state >> 59).
#pragma once

#include <cstdint>
#include <cstring>

#include "rt/core/scalar.h"

namespace rt {

class pcg32 {
  public:
    pcg32() = default;
    pcg32(std::uint64_t sequence, std::uint64_t seed) { set_sequence(sequence, seed); }

    // Selects stream `sequence` and places it at the start given by `seed`.
    void set_sequence(std::uint64_t sequence, std::uint64_t seed) {
        state = 0;
        inc   = (sequence << 1u) | 1u;
        next_u32();
        state += seed;
        next_u32();
    }

    std::uint32_t next_u32() {
        std::uint64_t old = state;
        state             = old * multiplier + inc;
        auto xorshifted   = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        auto rot          = static_cast<std::uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31u));
    }

    // A uniform number in [0, 1): 32 random bits scaled by 2^-32, then kept below 1 because a
    // float cannot hold 1 - 2^-32 and would round up to 1.
    real uniform() {
        constexpr real one_minus_epsilon = real(1) - std::numeric_limits<real>::epsilon() / 2;
        real u                           = real(next_u32()) * real(0x1p-32);
        return u < one_minus_epsilon ? u : one_minus_epsilon;
    }

    // n calls of next_u32() move the state by an affine map, state -> mult * state + plus * inc,
    // whose two numbers do not depend on the stream: plus is the sum of multiplier^i for i < n
    // (Brown, "Random number generation with arbitrary strides", 1994). So the jump for a
    // stride is computed once, for every stream, and raised to a power in O(log power) steps.
    struct jump {
        std::uint64_t mult = 1, plus = 0;  // the identity: no step
        // This jump, then `next` (all jumps of one generator commute).
        constexpr jump then(const jump& next) const {
            return {mult * next.mult, next.mult * plus + next.plus};
        }
    };

    // `step` made `times` times, by squaring: O(log times).
    static constexpr jump repeated(jump step, std::uint64_t times) {
        jump total;
        while (times > 0) {
            if (times & 1u) total = total.then(step);
            step = step.then(step);
            times >>= 1u;
        }
        return total;
    }
    // What `steps` calls of next_u32() do.
    static constexpr jump jump_of(std::uint64_t steps) { return repeated({multiplier, 1}, steps); }

    void apply(const jump& j) { state = j.mult * state + j.plus * inc; }

    // Moves the stream delta steps ahead in O(log delta): the same state as calling next_u32()
    // delta times (all of this arithmetic is exact, modulo 2^64).
    void advance(std::uint64_t delta) { apply(jump_of(delta)); }

  private:
    static constexpr std::uint64_t multiplier = 0x5851f42d4c957f2dULL;
    std::uint64_t state                       = 0x853c49e6748fea9bULL;
    std::uint64_t inc                         = 0xda3e39cb94b95bdbULL;
};

// Mixes 64 bits so that nearby inputs give unrelated outputs (the splitmix64 finalizer).
constexpr std::uint64_t mix_bits(std::uint64_t v) {
    v ^= v >> 30u;
    v *= 0xbf58476d1ce4e5b9ULL;
    v ^= v >> 27u;
    v *= 0x94d049bb133111ebULL;
    v ^= v >> 31u;
    return v;
}

// The bit pattern of a real, to hash scene parameters into ids and salts.
inline std::uint64_t bits_of(real x) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof x);
    return bits;
}

// A hash of several integers, used to pick a stream per (pixel, seed).
constexpr std::uint64_t hash_values(std::uint64_t a, std::uint64_t b, std::uint64_t c) {
    return mix_bits(a ^ mix_bits(b ^ mix_bits(c + 0x9e3779b97f4a7c15ULL)));
}

}  // namespace rt
