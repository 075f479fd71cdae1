// The one set of checks for parameters a user sets (scene values, camera settings): a bad value
// becomes a user_error that names it and says what was expected, never a NaN image. Chapter 01.
// Every message reads "<what> must <rule>, got <value>".
#pragma once

#include <cmath>
#include <sstream>
#include <string>

#include "rt/core/error.h"
#include "rt/core/vec3.h"

namespace rt {

// The general form: throws "<what> must <rule>, got <value>" unless ok.
template <typename T>
void require(bool ok, const char* what, const char* rule, const T& value) {
    if (ok) return;
    std::ostringstream message;
    message << what << " must " << rule << ", got " << value;
    throw user_error(message.str());
}

// A scalar parameter must lie in [lo, hi] (which also refuses NaN).
inline void require_in_range(real value, real lo, real hi, const char* what) {
    if (value >= lo && value <= hi) return;
    std::ostringstream rule;
    rule << "be in [" << lo << ", " << hi << "]";
    require(false, what, rule.str().c_str(), value);
}

// A size or distance that must be > 0 and finite (a radius, a density, a scale).
inline void require_positive(real value, const char* what) {
    require(value > 0 && std::isfinite(value), what, "be positive and finite", value);
}

// A setting that may be 0 but not negative, and must be finite (an aperture, a distance).
inline void require_non_negative(real value, const char* what) {
    require(value >= 0 && std::isfinite(value), what, "be >= 0 and finite", value);
}

// A reflectance (albedo) must lie in [0, 1] per channel: more would create energy.
inline void require_reflectance(const color& albedo, const char* what) {
    bool ok = true;
    for (int i = 0; i < 3; ++i) ok = ok && albedo[i] >= 0 && albedo[i] <= 1;
    require(ok, what, "be in [0, 1] per channel", albedo);
}

// A radiance must be >= 0 and finite per channel.
inline void require_radiance(const color& radiance, const char* what) {
    bool ok = true;
    for (int i = 0; i < 3; ++i) ok = ok && radiance[i] >= 0 && std::isfinite(radiance[i]);
    require(ok, what, "be >= 0 and finite per channel", radiance);
}

// A part that must be given (a material, a texture, an object to place).
template <typename Pointer>
void require_given(const Pointer& p, const char* what) {
    if (!p) throw user_error(std::string(what) + " is missing");
}

}  // namespace rt
