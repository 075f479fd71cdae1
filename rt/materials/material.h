// How a surface answers a ray: it scatters the ray, or absorbs it. Chapter 03; chapter 10 lets
// it emit light as well. The path tracer (path_tracer.cpp) computes L = Le + attenuation *
// L(scattered), so a material returns the sample's weight f * |cos theta| / pdf as its
// attenuation.
#pragma once

#include "rt/geometry/hittable.h"
#include "rt/samplers/sampler.h"

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

    // [ch14 begin]
    // What importance sampling needs beyond scatter(): the scattering function's value for a
    // direction the material did not choose. Only materials whose scatter() draws from a density
    // we can write down answer (lambertian, isotropic); a mirror's or glass's direction is a
    // delta, and metal's fuzz has no density, so those keep evaluable() false and are only
    // sampled: no light sample and no MIS weight at them.
    virtual bool evaluable() const { return false; }
    // f(wo, wi) |cos theta_i| towards unit wi (for a medium: the phase function times albedo).
    virtual color eval(const ray& /*r_in*/, const hit_record& /*rec*/, const vec3& /*wi*/) const {
        return color();
    }
    // The solid-angle density with which scatter() draws unit wi.
    virtual real pdf(const ray& /*r_in*/, const hit_record& /*rec*/, const vec3& /*wi*/) const {
        return 0;
    }
    // [ch14 end]
};

}  // namespace rt
