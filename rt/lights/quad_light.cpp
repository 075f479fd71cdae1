#include "rt/lights/quad_light.h"

#include <cmath>

#include "rt/core/exercise.h"
#include "rt/materials/material.h"

namespace rt {

quad_light::quad_light(const quad& q) : shape(&q), area(cross(q.edge_u(), q.edge_v()).length()) {}

bool quad_light::sample(const point3& ref, sample2 u, light_sample& out) const {
    return aim_at(ref, shape->corner() + u.u * shape->edge_u() + u.v * shape->edge_v(), out);
}

bool quad_light::aim_at(const point3& ref, const point3& target, light_sample& out,
                        real density) const {
    // Aim at the point and let the quad itself say where the ray meets it: that gives the
    // point, its error bound and the normal facing ref exactly as a scattered ray would see them.
    ray towards(ref, target - ref);
    if (!shape->hit(towards, interval(0, infinity), out.on_light)) return false;
    vec3 to_light = out.on_light.p - ref;
    real distance = to_light.length();
    if (!(distance > 0)) return false;
    out.wi  = to_light / distance;
    out.pdf = density > 0 ? density : pdf_at(ref, out.wi, out.on_light);
    if (!(out.pdf > 0 && std::isfinite(out.pdf))) return false;  // edge-on: no solid angle
    out.radiance    = out.on_light.mat->emitted(ray(ref, out.wi), out.on_light);
    out.at_infinity = false;
    return true;
}

real quad_light::pdf(const point3& ref, const vec3& wi) const {
    hit_record hit;
    if (!shape->hit(ray(ref, wi), interval(0, infinity), hit)) return 0;
    return pdf_at(ref, wi, hit);
}

real quad_light::pdf_at(const point3& ref, const vec3& wi, const hit_record& hit) const {
    // [exercise quad_light::pdf_at begin]
    real distance_squared = (hit.p - ref).length_squared();
    real cos_light        = std::fabs(dot(hit.normal, wi));
    // Seen so nearly edge-on that the density overflows: sample() never returns such a
    // direction (it refuses infinite densities), so its density is 0.
    real density = distance_squared / (cos_light * area);
    return cos_light > 0 && std::isfinite(density) ? density : 0;
    // [exercise quad_light::pdf_at end]
}

// [ch17 begin]
bool quad_light::center(point3& at) const {
    at = shape->corner() + (shape->edge_u() + shape->edge_v()) / 2;
    return true;
}
// [ch17 end]

}  // namespace rt
