// A ray P(t) = A + t*b: origin A and direction b. Chapter 01.
// Chapter 07 adds the instant the ray samples (motion blur): 0 until a shutter camera sets it,
// and carried along the whole path by continued().
#pragma once

#include "rt/core/vec3.h"

namespace rt {

class ray {
  public:
    ray() = default;
    ray(const point3& origin, const vec3& direction) : orig(origin), dir(direction) {}
    ray(const point3& origin, const vec3& direction, real time)  // [ch07]
        : orig(origin), dir(direction), tm(time) {}              // [ch07]

    const point3& origin() const { return orig; }
    const vec3& direction() const { return dir; }
    real time() const { return tm; }  // [ch07]

    point3 at(real t) const { return orig + t * dir; }

    // The next segment of the same path (a scattered ray, or this ray in an instance's frame):
    // a new origin and direction, everything else carried over.
    ray continued(const point3& origin, const vec3& direction) const {
        ray next  = *this;
        next.orig = origin;
        next.dir  = direction;
        return next;
    }

  private:
    point3 orig;
    vec3 dir;
    real tm = 0;  // [ch07] the instant, in the shutter interval [0, 1]
};

}  // namespace rt
