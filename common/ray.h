// A ray P(t) = A + t*b: origin A, direction b, and the instant it travels at. Chapter 01.
#pragma once

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

  private:
    point3 orig;
    vec3 dir;
    real tm = 0;
};

}  // namespace rt
