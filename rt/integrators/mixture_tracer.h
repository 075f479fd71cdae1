// Book 3's path tracer: at a surface whose lobe can be evaluated (material::lobe_kind), the next
// direction comes half the time from the material's own density and half the time from the
// lights (light_set), and the sample is weighted by the density of that mixture,
//   p(wi) = 1/2 p_material(wi) + 1/2 p_lights(wi),   weight = f(wi) |cos| / p(wi),
// which is valid because both parts are known for every direction: the estimate stays the
// rendering equation's, only its noise changes. Glass and metal are sampled as in chapter 03.
// Emission is added at every hit, as in chapter 10. Chapter 14.
#pragma once

#include "rt/integrators/path_tracer.h"
#include "rt/lights/light_set.h"

namespace rt {

class mixture_tracer : public radiance_estimator {
  public:
    mixture_tracer(std::shared_ptr<const hittable> world, const background& sky);

    // Per path segment at an evaluable material: 1 dimension for the choice, then the
    // material's own (scatter) or 3 for the light (which light, where on it).
    color radiance(const ray& r, sampler& s, int max_depth) const override;
    std::string_view name() const override { return "light"; }

  private:
    std::shared_ptr<const hittable> world;
    background sky;
    light_set lights;
};

// The scene's job, with book 3's mixture.
render_job mixture_trace(const scene& sc);

}  // namespace rt
