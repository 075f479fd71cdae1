// Warps from uniform numbers in [0,1)^2 to the shapes the renderer samples, each beside its
// density. Chapter 03 (disk, sphere, cosine hemisphere), chapter 04 (ball).
// A pdf here is with respect to the natural measure of the domain: area for the disk, volume for
// the ball, solid angle for directions.
#pragma once

#include <algorithm>
#include <cmath>

#include "rt/core/exercise.h"
#include "rt/core/vec3.h"
#include "rt/samplers/sampler.h"

namespace rt {

// Uniform point in the unit disk (z = 0), by Shirley and Chiu's concentric map: it keeps
// neighbouring samples neighbours and wastes no samples on rejection.
inline vec3 sample_uniform_disk(sample2 s) {
    // [exercise sample_uniform_disk begin]
    real a = 2 * s.u - 1, b = 2 * s.v - 1;
    if (a == 0 && b == 0) return vec3(0, 0, 0);
    // Which of the two wedges holds the point is a coin toss, so it selects values rather than
    // branches (a mispredicted branch costs more than the selects): the same arithmetic as
    //   |a| > |b|: r = a, theta = (pi/4) (b/a);   else: r = b, theta = pi/2 - (pi/4) (a/b).
    const bool a_wedge = std::fabs(a) > std::fabs(b);
    const real r       = a_wedge ? a : b;
    const real angle   = (pi / 4) * ((a_wedge ? b : a) / r);
    const real theta   = a_wedge ? angle : pi / 2 - angle;
    return vec3(r * std::cos(theta), r * std::sin(theta), 0);
    // [exercise sample_uniform_disk end]
}
constexpr real uniform_disk_pdf() {
    return 1 / pi;
}

// Uniform direction on the unit sphere: z uniform in [-1,1] (Archimedes), azimuth uniform.
inline vec3 sample_uniform_sphere(sample2 s) {
    // [exercise sample_uniform_sphere begin]
    real z   = 1 - 2 * s.u;
    real r   = std::sqrt(std::max(real(0), 1 - z * z));
    real phi = 2 * pi * s.v;
    return vec3(r * std::cos(phi), r * std::sin(phi), z);
    // [exercise sample_uniform_sphere end]
}
constexpr real uniform_sphere_pdf() {
    return 1 / (4 * pi);
}

// [ch04 begin]
// Uniform point inside the unit ball: a uniform direction scaled by cbrt(w), since the volume
// within radius r grows as r^3.
inline vec3 sample_uniform_ball(sample2 s, real w) {
    // [exercise sample_uniform_ball begin]
    return std::cbrt(w) * sample_uniform_sphere(s);
    // [exercise sample_uniform_ball end]
}
constexpr real uniform_ball_pdf() {
    return 3 / (4 * pi);
}
// [ch04 end]

// Cosine-weighted direction about +z (Malley's method: a uniform disk point lifted to the
// hemisphere). pdf = cos(theta) / pi, the distribution of an ideal diffuse reflector.
inline vec3 sample_cosine_hemisphere(sample2 s) {
    // [exercise sample_cosine_hemisphere begin]
    vec3 d = sample_uniform_disk(s);
    real z = std::sqrt(std::max(real(0), 1 - d.x() * d.x() - d.y() * d.y()));
    return vec3(d.x(), d.y(), z);
    // [exercise sample_cosine_hemisphere end]
}
inline real cosine_hemisphere_pdf(real cos_theta) {
    return std::max(real(0), cos_theta) / pi;
}

}  // namespace rt
