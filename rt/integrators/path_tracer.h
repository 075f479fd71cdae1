// The path tracer: chapter 03's way of turning a camera ray into radiance, the one chapters
// 03-13 render with (and chapters 14-17 on request). It evaluates the rendering equation one
// path at a time,
//   L(x, wo) = Le(x, wo) + weight * L(x', wi),
// following at most max_depth ray segments; a path that runs out of depth brings back nothing.
// Chapter 10 adds the emitted term Le (before it, nothing in a scene emits but the sky).
#pragma once

#include "rt/scene/scene.h"

namespace rt {

class path_tracer : public radiance_estimator {
  public:
    // Every shape in world must have a material (a chapter-02 sphere made without one has none).
    path_tracer(std::shared_ptr<const hittable> world, const background& sky);

    // Draws, per path segment, whatever the material hit draws (material.h); nothing else.
    color radiance(const ray& r, sampler& s, int max_depth) const override;
    std::string_view name() const override { return "path"; }

  private:
    std::shared_ptr<const hittable> world;
    background sky;
};

// The scene's job, path traced.
render_job path_trace(const scene& sc);

}  // namespace rt
