// The geometric optics of smooth surfaces. Chapter 04 (reflect), chapter 05 (refract, Schlick).
#pragma once

#include <algorithm>
#include <cmath>

#include "vec3.h"

namespace rt {

// Mirror reflection of v about the unit normal n: r = v - 2 (v.n) n. |r| = |v|.
constexpr vec3 reflect(const vec3& v, const vec3& n) {
    return v - 2 * dot(v, n) * n;
}

// Snell's law for a unit direction uv arriving against the unit normal n (dot(uv, n) <= 0),
// eta = n_incident / n_transmitted. The tangential part scales by eta; the normal part makes the
// result unit length. Callers check total internal reflection first (eta sin(theta) > 1); the
// clamp only absorbs rounding, so the square root never sees a negative number.
inline vec3 refract(const vec3& uv, const vec3& n, real eta) {
    real cos_theta      = std::min(dot(-uv, n), real(1));
    vec3 r_out_perp     = eta * (uv + cos_theta * n);
    real parallel_sq    = std::max(real(0), 1 - r_out_perp.length_squared());
    vec3 r_out_parallel = -std::sqrt(parallel_sq) * n;
    return r_out_perp + r_out_parallel;
}

// True when a ray at this angle cannot leave the denser medium: eta sin(theta) > 1.
inline bool total_internal_reflection(real cos_theta, real eta) {
    real sin_theta = std::sqrt(std::max(real(0), 1 - cos_theta * cos_theta));
    return eta * sin_theta > 1;
}

// Schlick's approximation of the Fresnel reflectance: R0 + (1 - R0)(1 - cos)^5, with
// R0 = ((1 - eta) / (1 + eta))^2. R(0 degrees) = R0, R(90 degrees) = 1.
inline real schlick_reflectance(real cos_theta, real eta) {
    real r0 = (1 - eta) / (1 + eta);
    r0      = r0 * r0;
    real c  = 1 - cos_theta;
    return r0 + (1 - r0) * c * c * c * c * c;
}

}  // namespace rt
