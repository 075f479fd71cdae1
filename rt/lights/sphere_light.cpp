#include "rt/lights/sphere_light.h"

#include <cmath>

#include "rt/core/exercise.h"
#include "rt/core/onb.h"
#include "rt/materials/material.h"
#include "rt/samplers/sampling.h"

namespace rt {

sphere_light::sphere_light(const sphere& s) : shape(&s) {}

real sphere_light::one_minus_cos_max(real s) {
    return s / (1 + std::sqrt(std::fmax(real(0), 1 - s)));
}

real sphere_light::sin2_max(const point3& ref) const {
    real r = shape->radius();
    return r * r / (shape->center() - ref).length_squared();
}

bool sphere_light::sample(const point3& ref, sample2 u, light_sample& out) const {
    real s = sin2_max(ref);
    vec3 direction;
    if (s < 1) {
        // [exercise sphere_light::sample begin]
        // Uniform in the cone about the center: cos theta = 1 - u (1 - cos theta_max), and
        // sin^2 = (1 - cos)(1 + cos) computed from 1 - cos itself, so a tiny cone keeps its size.
        real one_minus_cos = u.u * one_minus_cos_max(s);
        real cos_theta     = 1 - one_minus_cos;
        real sin_theta     = std::sqrt(std::fmax(real(0), one_minus_cos * (2 - one_minus_cos)));
        real phi           = 2 * pi * u.v;
        vec3 axis          = unit_vector(shape->center() - ref);
        direction          = onb(axis).to_world(
                     vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta));
        // [exercise sphere_light::sample end]
    } else {
        // Inside: aim at a uniform point of the surface.
        direction = shape->center() + shape->radius() * sample_uniform_sphere(u) - ref;
    }
    // The sphere says where the ray meets it. A direction on the cone's very rim can miss by
    // rounding; that sample is lost (the rim has no measure, so nothing is biased).
    if (!shape->hit(ray(ref, direction), interval(0, infinity), out.on_light)) return false;
    out.wi  = unit_vector(direction);
    out.pdf = pdf_at(ref, out.wi, out.on_light);
    if (!(out.pdf > 0 && std::isfinite(out.pdf))) return false;
    out.radiance    = out.on_light.mat->emitted(ray(ref, out.wi), out.on_light);
    out.at_infinity = false;
    return true;
}

real sphere_light::pdf(const point3& ref, const vec3& wi) const {
    hit_record hit;
    if (!shape->hit(ray(ref, wi), interval(0, infinity), hit)) return 0;
    return pdf_at(ref, wi, hit);
}

real sphere_light::pdf_at(const point3& ref, const vec3& wi, const hit_record& hit) const {
    // [exercise sphere_light::pdf_at begin]
    real s = sin2_max(ref);
    if (s < 1) {
        // A sphere so small or far that its cone underflows is never sampled (sample() refuses
        // an infinite density): density 0.
        real density = 1 / (2 * pi * one_minus_cos_max(s));
        return std::isfinite(density) ? density : 0;
    }
    // From inside: area density 1 / (4 pi r^2), times d^2 / |cos| for solid angle.
    real r         = shape->radius();
    real cos_light = std::fabs(dot(hit.normal, wi));
    real density   = (hit.p - ref).length_squared() / (cos_light * 4 * pi * r * r);
    return cos_light > 0 && std::isfinite(density) ? density : 0;  // as quad_light::pdf_at
    // [exercise sphere_light::pdf_at end]
}

// [ch17 begin]
bool sphere_light::center(point3& at) const {
    at = shape->center();
    return true;
}
// [ch17 end]

}  // namespace rt
