#include "rt/textures/perlin.h"

#include <cmath>

#include "rt/core/exercise.h"

namespace rt {

namespace {

std::array<int, 256> permutation(book_random& draws) {
    std::array<int, 256> p{};
    for (int i = 0; i < 256; ++i) p[std::size_t(i)] = i;
    for (int i = 255; i > 0; --i) std::swap(p[std::size_t(i)], p[std::size_t(draws.integer(0, i))]);
    return p;
}

}  // namespace

perlin::perlin(book_random& draws) {
    // [ch19 begin]
    drawn_seed = draws.seed();
    drawn_skip = draws.draws();
    // [ch19 end]
    // Normalized points of the cube [-1, 1)^3, as the book has them (they lean a little
    // towards the cube's diagonals; the noise's bound and variance need only unit length).
    for (auto& g : gradients) g = unit_vector(draws.vector(-1, 1));
    perm_x = permutation(draws);
    perm_y = permutation(draws);
    perm_z = permutation(draws);
}

perlin::perlin(std::uint32_t seed) {
    book_random draws(seed);
    *this = perlin(draws);
}

real perlin::noise(const point3& p) const {
    // [exercise perlin::noise begin]
    const real fx = std::floor(p.x()), fy = std::floor(p.y()), fz = std::floor(p.z());
    const real u = p.x() - fx, v = p.y() - fy, w = p.z() - fz;
    // Lattice indices wrap every 256 cells; long long keeps huge coordinates from overflowing.
    const auto i = static_cast<long long>(fx), j = static_cast<long long>(fy),
               k  = static_cast<long long>(fz);
    const real su = u * u * (3 - 2 * u), sv = v * v * (3 - 2 * v), sw = w * w * (3 - 2 * w);

    real sum = 0;
    for (int di = 0; di < 2; ++di) {
        for (int dj = 0; dj < 2; ++dj) {
            for (int dk = 0; dk < 2; ++dk) {
                const vec3& g = gradients[std::size_t(perm_x[std::size_t((i + di) & 255)] ^
                                                      perm_y[std::size_t((j + dj) & 255)] ^
                                                      perm_z[std::size_t((k + dk) & 255)])];
                vec3 offset(u - real(di), v - real(dj), w - real(dk));
                real weight = (di ? su : 1 - su) * (dj ? sv : 1 - sv) * (dk ? sw : 1 - sw);
                sum += weight * dot(g, offset);
            }
        }
    }
    return sum;
    // [exercise perlin::noise end]
}

real perlin::turbulence(point3 p, int depth) const {
    // [exercise perlin::turbulence begin]
    real sum = 0, weight = 1;
    for (int i = 0; i < depth; ++i) {
        sum += weight * noise(p);
        weight *= real(0.5);
        p = 2 * p;
    }
    return std::fabs(sum);
    // [exercise perlin::turbulence end]
}

}  // namespace rt
