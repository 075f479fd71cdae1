// How a surface answers a ray: it scatters the ray, or absorbs it. Chapter 03; chapter 10 lets
// it emit light as well. The path tracer (path_tracer.cpp) computes L = Le + attenuation *
// L(scattered), so a material returns the sample's weight f * |cos theta| / pdf as its
// attenuation.
#pragma once

#include "hittable.h"
#include "sampler.h"

namespace rt {

class material {
  public:
    virtual ~material() = default;

    // [ch10 begin]
    // Radiance emitted at the hit towards the ray's origin. Most materials emit nothing.
    virtual color emitted(const ray& /*r_in*/, const hit_record& /*rec*/) const { return color(); }
    // [ch10 end]

    // Samples the direction light arrives from, for a ray r_in that hit at rec, drawing from s.
    // Returns false when the ray is absorbed. Otherwise sets scattered (spawned from rec) and
    // attenuation = f * |cos theta| / pdf, the pdf taken with respect to solid angle.
    virtual bool scatter(const ray& r_in, const hit_record& rec, sampler& s, color& attenuation,
                         ray& scattered) const = 0;
};

}  // namespace rt
