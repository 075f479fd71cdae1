// What passes through a smooth surface between two clear media: Snell's refraction, total
// internal reflection, and the Fresnel reflectance (Schlick's approximation and the exact
// equations) that says how much of the light is reflected instead. Chapter 05.
#pragma once

#include <algorithm>
#include <cmath>

#include "rt/core/exercise.h"
#include "rt/core/vec3.h"

namespace rt {

// Snell's law for a unit direction uv arriving against the unit normal n (dot(uv, n) <= 0),
// eta = n_incident / n_transmitted. The tangential part scales by eta; the normal part makes the
// result unit length. Callers check total internal reflection first (eta sin(theta) > 1); the
// clamp only absorbs rounding, so the square root never sees a negative number.
inline vec3 refract(const vec3& uv, const vec3& n, real eta) {
    // [exercise refract begin]
    real cos_theta      = std::min(dot(-uv, n), real(1));
    vec3 r_out_perp     = eta * (uv + cos_theta * n);
    real parallel_sq    = std::max(real(0), 1 - r_out_perp.length_squared());
    vec3 r_out_parallel = -std::sqrt(parallel_sq) * n;
    return r_out_perp + r_out_parallel;
    // [exercise refract end]
}

// True when a ray at this angle cannot leave the denser medium: eta sin(theta) > 1.
inline bool total_internal_reflection(real cos_theta, real eta) {
    // [exercise total_internal_reflection begin]
    real sin_theta = std::sqrt(std::max(real(0), 1 - cos_theta * cos_theta));
    return eta * sin_theta > 1;
    // [exercise total_internal_reflection end]
}

// cos(theta_t) of the transmitted ray by Snell's law, or -1 under total internal reflection.
inline real transmitted_cosine(real cos_incident, real eta) {
    real sin2_t = eta * eta * std::max(real(0), 1 - cos_incident * cos_incident);
    return sin2_t >= 1 ? real(-1) : std::sqrt(1 - sin2_t);
}

// Schlick's approximation of the Fresnel reflectance: R0 + (1 - R0)(1 - cos theta)^5, with
// R0 = ((1 - eta) / (1 + eta))^2 and theta the angle on the LESS dense side: the incident angle
// when light enters the denser medium (eta < 1), the transmitted angle when it leaves (eta > 1).
// Reflectance is the same both ways along one light path (Helmholtz), and only the cosine on the
// less dense side makes the formula agree with Fresnel there. 1 under total internal reflection.
inline real schlick_reflectance(real cos_incident, real eta) {
    // [exercise schlick_reflectance begin]
    real cos_theta = cos_incident;
    if (eta > 1) {
        cos_theta = transmitted_cosine(cos_incident, eta);
        if (cos_theta < 0) return 1;
    }
    real r0 = (1 - eta) / (1 + eta);
    r0      = r0 * r0;
    real c  = 1 - cos_theta;
    return r0 + (1 - r0) * c * c * c * c * c;
    // [exercise schlick_reflectance end]
}

// The book's form: the incident cosine on both sides. Leaving glass it reflects too little near
// the critical angle (R jumps from well below 1 to 1 there). Kept to compare (ch05 README).
inline real schlick_reflectance_incident(real cos_incident, real eta) {
    real r0 = (1 - eta) / (1 + eta);
    r0      = r0 * r0;
    real c  = 1 - cos_incident;
    return r0 + (1 - r0) * c * c * c * c * c;
}

// The exact Fresnel reflectance of unpolarised light at a smooth dielectric boundary: the mean
// of the s- and p-polarised reflectances,
//   r_s = (eta cos_i - cos_t) / (eta cos_i + cos_t),  r_p = (cos_i - eta cos_t) / (cos_i + eta
//   cos_t).
// ((1 - eta) / (1 + eta))^2 at normal incidence; r_p = 0 at Brewster's angle, tan = 1 / eta;
// 1 under total internal reflection.
inline real fresnel_reflectance(real cos_incident, real eta) {
    real cos_t = transmitted_cosine(cos_incident, eta);
    if (cos_t < 0) return 1;
    real cos_i = std::clamp(cos_incident, real(0), real(1));
    real r_s   = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    real r_p   = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return (r_s * r_s + r_p * r_p) / 2;
}

}  // namespace rt
