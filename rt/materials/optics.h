// The geometric optics of smooth surfaces: mirror reflection. Chapter 04 (chapter 05's
// refraction.h adds what passes through a surface).
#pragma once

#include "rt/core/exercise.h"
#include "rt/core/vec3.h"

namespace rt {

// Mirror reflection of v about the unit normal n: r = v - 2 (v.n) n. |r| = |v|.
inline vec3 reflect(const vec3& v, const vec3& n) {
    // [exercise reflect begin]
    return v - 2 * dot(v, n) * n;
    // [exercise reflect end]
}

}  // namespace rt
