// Chapter 03 on. Checks of scene parameters, shared by the constructors that take them: a bad value
// becomes a user_error naming it, never a NaN image.
#pragma once

#include <sstream>
#include <string>

#include "error.h"
#include "vec3.h"

namespace rt {

// A reflectance (albedo) must lie in [0, 1] per channel: more would create energy.
inline void require_reflectance(const color& albedo, const char* what) {
    for (int i = 0; i < 3; ++i) {
        if (!(albedo[i] >= 0 && albedo[i] <= 1)) {
            std::ostringstream message;
            message << what << " must be in [0, 1] per channel, got " << albedo;
            throw user_error(message.str());
        }
    }
}

// A scalar parameter must lie in [lo, hi].
inline void require_in_range(real value, real lo, real hi, const char* what) {
    if (!(value >= lo && value <= hi)) {
        std::ostringstream message;
        message << what << " must be in [" << lo << ", " << hi << "], got " << value;
        throw user_error(message.str());
    }
}

}  // namespace rt
