// Next-event estimation with multiple importance sampling: at each surface that can be evaluated
// the path both aims a shadow ray at a light (light_set) and scatters as the material chooses,
// and light reached either way counts with the power heuristic's weight (Veach 1997, as in
// pbrt-v4's path integrator):
//   w_light = p_light^2 / (p_light^2 + p_material^2),   w_material = 1 - w_light for that path,
// so a small bright light is found by the shadow ray and a glossy reflection of a big one by the
// scattered ray, and neither is counted twice. Shadow rays take the exact transmittance of the
// media they cross (hittable::transmittance). After the third segment a path that carries
// little is ended with probability q = 1 - max(throughput) and otherwise divided by 1 - q
// (Russian roulette): fewer, equally unbiased paths. Chapter 15.
#pragma once

#include "rt/integrators/path_tracer.h"
#include "rt/lights/light_set.h"

namespace rt {

// The power heuristic's weight of a sample drawn with density pdf_taken, when the other
// strategy would have drawn it with density pdf_other. Safe for 0 and infinite densities.
real power_heuristic(real pdf_taken, real pdf_other);

// [ch17 begin]
// How a path counts the light it meets behind a medium (fog, smoke). `sampled`: as chapter 12's
// media decide, by a random hit: the light counts fully if the ray happens to pass, not at all
// if it scatters first. `expected`: the light that one sphere or quad sends along each segment
// counts with the segment's exact transmittance, whether the ray passed or scattered (what
// the random hit gives on average), and a ray that passes does not count it again. The same
// mean, without the noise of an all-or-nothing draw: a lamp seen through thin mist, which a
// few percent of samples miss, stops speckling.
enum class light_through_media { sampled, expected };

// The light media scatter once towards a segment's origin, estimated along the whole segment
// (in_scattering.h), and the medium points whose own light that replaces.
class segment_in_scattering {
  public:
    virtual ~segment_in_scattering() = default;
    // Whether hit `rec`, made along r, is a medium's point whose light along() counted for the
    // segment that reached it: that point aims at no light, and its next segment counts none
    // the light set could have aimed at.
    virtual bool covers(const ray& r, const hit_record& rec) const = 0;
    // The estimate for segment r, whose nearest hit (if `found`) is `nearest`.
    virtual color along(const ray& r, bool found, const hit_record& nearest, sampler& s) const = 0;
};
using in_scattering_maker = std::shared_ptr<const segment_in_scattering> (*)(
    const hittable& world, const light_set& lights);

// What chapter 17 adds to the way a path meets lights; the defaults are chapter 15's.
struct mis_choices {
    light_through_media through_media = light_through_media::sampled;
    // How the lights of emitting quads are made (light_set; nullptr: by area).
    light_set::quad_light_maker make_quad = nullptr;
    // Whether fuzzy metal (material::spread_is_evaluable) joins MIS: the lights are aimed at
    // from it too, and each way weighed by its density, instead of its direction only
    // followed. A broad fuzz sees a lamp by its scattered ray rarely, by a shadow ray always.
    bool weigh_fuzzy_metal = false;
    // Makes what lets each segment through a medium aim at the lights from a point chosen
    // along it (in_scattering::make: equiangular sampling); nullptr: only from where the ray
    // scatters.
    in_scattering_maker aim_along_rays = nullptr;
};
// [ch17 end]

class mis_tracer : public radiance_estimator {
  public:
    mis_tracer(std::shared_ptr<const hittable> world, const background& sky);
    // [ch17 begin]
    mis_tracer(std::shared_ptr<const hittable> world, const background& sky,
               const mis_choices& choices);
    // What choices.aim_along_rays makes holds this tracer's light set by reference: a copy, or
    // a tracer moved from, would leave it pointing at another's.
    mis_tracer(const mis_tracer&)            = delete;
    mis_tracer& operator=(const mis_tracer&) = delete;
    // [ch17 end]

    // Per path segment at an evaluable material: 3 dimensions for the light sample, then the
    // material's own; from the third segment on, 1 for Russian roulette.
    color radiance(const ray& r, sampler& s, int max_depth) const override;
    std::string_view name() const override {
        // [ch17 begin]
        if (choices.through_media == light_through_media::expected) return "mis-expected";
        // [ch17 end]
        return "mis";
    }

  private:
    // The fraction of the light sample's radiance that reaches rec unblocked.
    real visibility(const ray& r_in, const hit_record& rec, const light_sample& towards) const;

    // [ch17 begin]
    // With light_through_media::expected: what the nearest light along r sends back along it,
    // times the transmittance up to it (0 when a surface is in the way); `shape` and `on_light`
    // name that light's hit, so the path does not count it again.
    color expected_light(const ray& r, const hittable*& shape, hit_record& on_light) const;
    // [ch17 end]

    std::shared_ptr<const hittable> world;
    background sky;
    light_set lights;
    mis_choices choices;                                      // [ch17]
    std::shared_ptr<const segment_in_scattering> along_rays;  // [ch17] choices.aim_along_rays
};

// The scene's job, with next-event estimation and MIS.
render_job mis_trace(const scene& sc);
// [ch17 begin]
render_job mis_trace(const scene& sc, const mis_choices& choices);
// [ch17 end]

}  // namespace rt
