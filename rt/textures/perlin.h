// Perlin gradient noise. Chapter 09.
// Each lattice point of the integer grid gets a random unit gradient g (256 of them, picked
// through three permutation tables by hashing the point's x, y, z). The noise at p is the
// trilinear blend of the eight corner planes g . (p - corner), with Hermite-smoothed weights
// s(t) = t^2 (3 - 2t), so it is continuous with a continuous gradient, and 0 at every lattice
// point. With unit gradients its values lie within [-sqrt(3)/2, sqrt(3)/2], inside [-1, 1]
// (the known bound for 3D gradient noise; test_perlin checks it over many points).
#pragma once

#include <array>
#include <cstdint>

#include "rt/core/book_random.h"
#include "rt/core/vec3.h"

namespace rt {

class perlin {
  public:
    // The book's tables, drawn from `draws` as the book's perlin() draws them: 256 gradients
    // unit_vector(vec3::random(-1, 1)), then the permutations of x, y and z, each shuffled by
    // Fisher-Yates from the top with random_int(0, i). The book builds them from the program's
    // one rand() stream, wherever its scene happens to construct the texture.
    explicit perlin(book_random& draws);
    // The tables from a fresh stream, srand(seed): the layout seed, 1 unless set, is the book's
    // when the texture is the first thing its scene draws (the two Perlin spheres, the simple
    // light).
    explicit perlin(std::uint32_t seed = book_layout_seed());
    // Smooth noise in [-1, 1], 0 at integer points.
    real noise(const point3& p) const;

    // Sum of |octaves|: sum_{i<depth} 0.5^i noise(2^i p), then its absolute value; in [0, 2).
    real turbulence(point3 p, int depth = 7) const;

    // [ch19 begin]
    // Where its tables were drawn: the book's stream from srand(table_seed()), after
    // table_skip() draws (a scene file names them so).
    std::uint32_t table_seed() const { return drawn_seed; }
    std::uint64_t table_skip() const { return drawn_skip; }
    // [ch19 end]

  private:
    static constexpr int point_count = 256;
    std::array<vec3, point_count> gradients;
    std::array<int, point_count> perm_x, perm_y, perm_z;
    // [ch19 begin]
    std::uint32_t drawn_seed = 0;
    std::uint64_t drawn_skip = 0;
    // [ch19 end]
};

}  // namespace rt
