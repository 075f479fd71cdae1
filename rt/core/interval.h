// A closed interval [min, max] of the ray parameter t or of a color channel. Chapter 02.
// An interval with min > max is empty.
#pragma once

#include "rt/core/scalar.h"

namespace rt {

class interval {
  public:
    real min = +infinity;  // empty by default
    real max = -infinity;

    constexpr interval() = default;
    constexpr interval(real lo, real hi) : min(lo), max(hi) {}

    constexpr real size() const { return max - min; }
    constexpr bool contains(real x) const { return min <= x && x <= max; }
    constexpr bool surrounds(real x) const { return min < x && x < max; }
    constexpr real clamp(real x) const { return x < min ? min : (x > max ? max : x); }

    static constexpr interval empty() { return interval(); }
    static constexpr interval universe() { return interval(-infinity, +infinity); }
};

}  // namespace rt
