// From linear light to the numbers a screen expects. Chapter 01 (every PNG is written with it).
// We use the sRGB transfer curve (IEC 61966-2-1), the one PNG viewers assume, not the book's
// gamma 2 (sqrt): V = 12.92 L for L <= 0.0031308, else 1.055 L^(1/2.4) - 0.055.
#pragma once

#include <cmath>
#include <cstdint>

#include "rt/core/exercise.h"

namespace rt {

inline double linear_to_srgb(double linear) {
    // [exercise linear_to_srgb begin]
    if (!(linear > 0)) return 0;  // also maps NaN to 0, so no bad pixel can turn bright
    if (linear >= 1) return 1;
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
    // [exercise linear_to_srgb end]
}

inline double srgb_to_linear(double encoded) {
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

// Linear value to an 8-bit sRGB code, rounded to nearest.
inline std::uint8_t to_srgb8(double linear) {
    return std::uint8_t(std::lround(255 * linear_to_srgb(linear)));
}

}  // namespace rt
