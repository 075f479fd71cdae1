// What a ray that hits nothing sees: a vertical blend from `bottom` (looking straight down) to
// `top` (straight up). Chapter 01's sky is white to light blue; a uniform color is the special
// case bottom == top (book 2 scenes, furnace tests, black for lit interiors).
// L(d) = (1 - a) bottom + a top, with a = (d.y / |d| + 1) / 2.
#pragma once

#include <cmath>

#include "rt/core/exercise.h"
#include "rt/core/vec3.h"

namespace rt {

struct background {
    color bottom = color(1, 1, 1);
    color top    = color(real(0.5), real(0.7), real(1.0));

    static background sky() { return {}; }
    static background uniform(const color& c) { return {c, c}; }

    color radiance(const vec3& direction) const {
        // [exercise background::radiance begin]
        real a = real(0.5) * (direction.y() / direction.length() + 1);
        // std::lerp, not (1 - a) bottom + a top: it is exact at both ends and returns c itself
        // when bottom == top == c, so a uniform background is uniform to the last bit.
        return color(std::lerp(bottom.x(), top.x(), a), std::lerp(bottom.y(), top.y(), a),
                     std::lerp(bottom.z(), top.z(), a));
        // [exercise background::radiance end]
    }
};

}  // namespace rt
