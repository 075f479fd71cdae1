// A ray P(t) = A + t*b: origin A, direction b, and the instant it travels at. Chapter 01.
// Chapter 12 adds a random key: bits a participating medium hashes into its own random numbers
// while the ray is traced (see constant_medium.h), drawn from the sampler by the integrator.
#pragma once

#include <cstdint>

#include "vec3.h"

namespace rt {

class ray {
  public:
    ray() = default;
    ray(const point3& origin, const vec3& direction, real time = 0)
        : orig(origin), dir(direction), tm(time) {}

    const point3& origin() const { return orig; }
    const vec3& direction() const { return dir; }
    real time() const { return tm; }

    point3 at(real t) const { return orig + t * dir; }

    std::uint64_t random_key() const { return key; }
    void set_random_key(std::uint64_t k) { key = k; }

  private:
    point3 orig;
    vec3 dir;
    real tm           = 0;
    std::uint64_t key = 0;
};

}  // namespace rt
