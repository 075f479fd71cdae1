// How a surface answers a ray: it may emit light, and it may scatter the ray. Chapter 02.
// The path tracer (integrator.cpp) computes L = Le + attenuation * L(scattered), so a material
// returns the sample's weight f * |cos theta| / pdf as its attenuation.
#pragma once

#include "hittable.h"
#include "sampler.h"

namespace rt {

class material {
  public:
    virtual ~material() = default;

    // Radiance emitted at the hit towards the ray's origin. Most materials emit nothing.
    virtual color emitted(const ray& /*r_in*/, const hit_record& /*rec*/) const { return color(); }

    // Samples the direction light arrives from, for a ray r_in that hit at rec, drawing from s.
    // Returns false when the ray is absorbed. Otherwise sets scattered (spawned from rec) and
    // attenuation = f * |cos theta| / pdf, the pdf taken with respect to solid angle.
    virtual bool scatter(const ray& r_in, const hit_record& rec, sampler& s, color& attenuation,
                         ray& scattered) const = 0;

    // Whether emitted() or scatter() reads the hit's (u, v); see texture::uses_uv.
    virtual bool uses_uv() const { return false; }
};

}  // namespace rt
