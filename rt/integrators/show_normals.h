// Chapter 02's way of seeing a scene: each pixel shows the unit outward normal n of the nearest
// hit as the color 0.5 (n + 1), and the sky where nothing is hit. The picture shows the
// geometry and nothing else: the first test of any new shape.
#pragma once

#include "rt/scene/scene.h"

namespace rt {

class normals_estimator : public radiance_estimator {
  public:
    normals_estimator(std::shared_ptr<const hittable> world, const background& sky);

    // Draws nothing from s: one segment, no random choice.
    color radiance(const ray& r, sampler& s, int max_depth) const override;
    std::string_view name() const override { return "normals"; }

  private:
    std::shared_ptr<const hittable> world;
    background sky;
};

// The scene's job, seen through its normals.
render_job show_normals(const scene& sc);

}  // namespace rt
