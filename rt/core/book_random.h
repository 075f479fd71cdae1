// The book's random numbers, so that the scenes it lays out at random (book 1's final scene,
// book 2's bouncing spheres and final scene, the Perlin tables) are its own. Chapter 06.
//
// The book draws with random_double() = rand() / (RAND_MAX + 1.0), from the default seed, in
// the order its code calls it. This is glibc's rand(): an additive feedback generator of degree
// 31, r[i] = r[i-31] + r[i-3] (mod 2^32), whose first 31 words come from the seed through
// 16807 x mod 2^31 - 1, and whose first 310 results are thrown away; rand() is r[i] >> 1.
// MSVC's and macOS's rand() are other generators (a 15-bit LCG; a different algorithm), so
// the book's layouts differ there: tools/check-render says so when a student names such a
// platform.
//
// Where the book draws inside one argument list, vec3(random_double(), random_double(),
// random_double()) or point3(a + 0.9*random_double(), 0.2, b + 0.9*random_double()), C++
// leaves the order open; g++ on x86-64 evaluates the arguments right to left, which the book's
// own binary shows (its first sphere of book 1 is at z = -11 + 0.9 * the second draw). The
// helpers below that fill a vector follow g++.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "rt/core/vec3.h"

namespace rt {

// The seed every layout starts from: 1, the book's own (a program that never calls srand), unless
// a program's --layout-seed sets another. Another seed gives another layout the book's code could
// have drawn, as it does where rand() is another generator; tools/check-render measures with
// such layouts what a student's image shares with ours whatever its layout.
inline std::uint32_t& layout_seed_setting() {
    static std::uint32_t seed = 1;
    return seed;
}
inline std::uint32_t book_layout_seed() {
    return layout_seed_setting();
}
inline void set_book_layout_seed(std::uint32_t seed) {
    layout_seed_setting() = seed;
}

class book_random {
  public:
    static constexpr std::int32_t max = 2147483647;  // glibc's RAND_MAX

    // srand(seed); glibc takes seed 0 as 1. The default is the layout seed, the book's 1 unless
    // set.
    explicit book_random(std::uint32_t seed = book_layout_seed()) {
        // glibc keeps the seed in a 32-bit signed word and multiplies by Schrage's method,
        // which for a negative word (a seed of 2^31 or more) gives its own numbers.
        first_seed        = seed;  // [ch19]
        std::int64_t word = std::int32_t(seed == 0 ? 1 : seed);
        std::array<std::uint32_t, 344> r{};  // the words, added modulo 2^32 from r[34] on
        r[0] = std::uint32_t(word);
        for (std::size_t i = 1; i < 31; ++i) {
            const std::int64_t hi = word / 127773, lo = word % 127773;
            word = 16807 * lo - 2836 * hi;
            if (word < 0) word += 2147483647;
            r[i] = std::uint32_t(word);
        }
        for (std::size_t i = 31; i < 34; ++i) r[i] = r[i - 31];
        for (std::size_t i = 34; i < 344; ++i) r[i] = r[i - 31] + r[i - 3];
        for (std::size_t i = 313; i < 344; ++i) ring[i % 31] = r[i];
        position = 344 % 31;
    }

    // rand(): the next number in [0, RAND_MAX].
    std::int32_t next() {
        ++drawn;  // [ch19]
        std::uint32_t& word = ring[position];
        word += ring[(position + 28) % 31];  // r[i-31] + r[i-3]
        position = (position + 1) % 31;
        return std::int32_t(word >> 1);
    }

    // The book's random_double(): in [0, 1).
    double uniform() { return next() / (double(max) + 1.0); }
    // random_double(lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    // random_int(lo, hi): in [lo, hi], as the book truncates random_double(lo, hi + 1).
    int integer(int lo, int hi) { return int(uniform(lo, hi + 1)); }
    // vec3::random(lo, hi) as g++ evaluates it: z is drawn first, then y, then x.
    vec3 vector(double lo, double hi) {
        const double z = uniform(lo, hi), y = uniform(lo, hi), x = uniform(lo, hi);
        return vec3(real(x), real(y), real(z));
    }

    void skip(std::size_t draws) {
        for (std::size_t i = 0; i < draws; ++i) next();
    }

    // [ch19 begin]
    // The seed it started from and the numbers drawn since: where a later draw stands in the
    // stream (a scene file names the Perlin tables so).
    std::uint32_t seed() const { return first_seed; }
    std::uint64_t draws() const { return drawn; }
    // [ch19 end]

  private:
    std::array<std::uint32_t, 31> ring{};  // the last 31 words
    std::size_t position = 0;              // where the word of 31 draws ago sits
    // [ch19 begin]
    std::uint32_t first_seed = 1;
    std::uint64_t drawn      = 0;
    // [ch19 end]
};

}  // namespace rt
