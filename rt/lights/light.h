// A light a path can aim at: chapter 14's answer to "most directions from here see no light".
// Instead of waiting for a scattered ray to stumble onto a small lamp, we pick a point on it (or
// a direction to it) with a density we know and weight what it sends by 1 / that density:
//   L_direct ~= f(wi) |cos| Le(wi) V / pdf(wi).
// Every density here is per unit solid angle at the point being lit, so light samples and
// material samples can be mixed and weighed against each other (chapters 14 and 15).
#pragma once

#include "rt/geometry/hittable.h"
#include "rt/samplers/sampler.h"

namespace rt {

// Whether no light at all comes with c (every channel exactly 0): a sample not worth a ray.
inline bool is_black(const color& c) {
    return c.x() == 0 && c.y() == 0 && c.z() == 0;
}

// A direction towards a light, with what arrives along it if nothing is in the way.
struct light_sample {
    vec3 wi;                   // unit, from the lit point towards the light
    real pdf = 0;              // solid-angle density of drawing wi
    color radiance;            // Le arriving along -wi
    hit_record on_light;       // the point sampled (p, p_error, normal facing the lit point)
    bool at_infinity = false;  // the sky: no point, the shadow ray runs to infinity
};

class light {
  public:
    virtual ~light() = default;

    // Draws a direction towards the light as seen from ref, from u. False when the sample is
    // of no use (the light is seen edge-on, or rounding lost the point); that counts as no
    // light, and the estimate stays unbiased because pdf() gives such directions no density.
    virtual bool sample(const point3& ref, sample2 u, light_sample& out) const = 0;

    // The density sample() has for unit direction wi from ref, whether or not anything else
    // is in the way (0 if wi misses the light).
    virtual real pdf(const point3& ref, const vec3& wi) const = 0;

    // The same density when a ray from ref along wi is already known to hit this light at
    // `hit` (saves intersecting the light again).
    virtual real pdf_at(const point3& ref, const vec3& wi, const hit_record& hit) const = 0;

    // [ch17 begin]
    // A point the light's power gathers around, for aiming at it along a whole ray through a
    // medium (rt/integrators/in_scattering.h); false where there is none (the sky).
    virtual bool center(point3& /*at*/) const { return false; }
    // [ch17 end]
};

}  // namespace rt
