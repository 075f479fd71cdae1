// The scalar type of the whole renderer, chosen once at configure time (-DRT_SCALAR=float|double),
// plus the constants every chapter uses. Chapter 01.
#pragma once

#include <limits>

namespace rt {

#ifdef RT_SCALAR_FLOAT
using real = float;
#else
using real = double;
#endif

inline constexpr real infinity = std::numeric_limits<real>::infinity();
inline constexpr real pi       = real(3.14159265358979323846);

// In double, rounded to real once: angles come from scenes as double literals (0.3 degrees).
inline constexpr real degrees_to_radians(double degrees) {
    return static_cast<real>(degrees * 3.14159265358979323846 / 180);
}

}  // namespace rt
