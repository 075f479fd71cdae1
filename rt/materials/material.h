// How a surface answers a ray: it scatters the ray, or absorbs it. Chapter 03; chapter 10 lets
// it emit light as well. The path tracer (path_tracer.cpp) computes L = Le + weight *
// L(scattered), so a material returns, with the direction it chose, the sample's weight
// f * |cos theta| / pdf.
#pragma once

#include <cstdint>
#include <optional>

#include "rt/geometry/hittable.h"
#include "rt/samplers/sampler.h"

namespace rt {

// [ch14 begin]
// What a material draws its directions from, which says what an integrator may do at its
// surface besides following it (chapters 14 and 15).
enum class lobe : std::uint8_t {
    // A density the material can evaluate for any direction (material::eval and pdf): a light
    // may be aimed at, and each way of finding it weighed against the other.
    evaluable,
    // Only followed: one direction for each incoming ray (a mirror, glass: a delta), or a
    // spread chapters 14-16 do not weigh (metal's fuzz, whose density chapter 17 gives).
    sampled_only,
};
// [ch14 end]

// One scattering: the path's next segment and how much of the light coming back along it counts.
struct scatter_sample {
    ray scattered;  // from the hit (moved off the surface, where there is one)
    color weight;   // f * |cos theta| / pdf, the pdf taken with respect to solid angle
    // [ch14 begin]
    lobe from = lobe::sampled_only;  // the lobe the direction was drawn from
    real pdf  = 0;  // its solid-angle density, for an evaluable lobe (what pdf() would give)
    // [ch14 end]
};

class material {
  public:
    virtual ~material() = default;

    // [ch10 begin]
    // Radiance emitted at the hit towards the ray's origin. Most materials emit nothing.
    virtual color emitted(const ray& /*r_in*/, const hit_record& /*rec*/) const { return color(); }
    // [ch10 end]

    // Samples the direction light arrives from, for a ray r_in that hit at rec, drawing from s.
    // Nothing when the ray is absorbed.
    virtual std::optional<scatter_sample> scatter(const ray& r_in, const hit_record& rec,
                                                  sampler& s) const = 0;

    // [ch14 begin]
    // The lobe scatter() draws from, known before it draws: an integrator decides by it
    // whether to aim at a light here, which draws numbers of its own first. Every sample
    // scatter() returns names the same lobe.
    virtual lobe lobe_kind() const { return lobe::sampled_only; }
    // For an evaluable lobe, what importance sampling needs beyond scatter(): the scattering
    // function's value for a direction the material did not choose,
    // f(wo, wi) |cos theta_i| towards unit wi (for a medium: the phase function times albedo),
    virtual color eval(const ray& /*r_in*/, const hit_record& /*rec*/, const vec3& /*wi*/) const {
        return color();
    }
    // and the solid-angle density with which scatter() draws unit wi.
    virtual real pdf(const ray& /*r_in*/, const hit_record& /*rec*/, const vec3& /*wi*/) const {
        return 0;
    }
    // [ch14 end]
    // [ch17 begin]
    // A sampled_only lobe whose density is known all the same, so that an integrator that asks
    // for it may aim at lights here and weigh both ways: metal's fuzz (a direction towards a
    // point uniform in a ball has a density in closed form). Chapters 14-16 follow such a lobe
    // only, and eval and pdf stay 0 for it; these give what they would give.
    virtual bool spread_is_evaluable() const { return false; }
    virtual color spread_eval(const ray& /*r_in*/, const hit_record& /*rec*/,
                              const vec3& /*wi*/) const {
        return color();
    }
    virtual real spread_pdf(const ray& /*r_in*/, const hit_record& /*rec*/,
                            const vec3& /*wi*/) const {
        return 0;
    }
    // [ch17 end]
};

}  // namespace rt
