// A debugging material from chapter 02: it shows the unit outward normal n as the color
// 0.5 * (n + 1) and absorbs the ray, so the picture shows the geometry and nothing else.
#pragma once

#include "material.h"

namespace rt {

class normal_shading : public material {
  public:
    color emitted(const ray& /*r_in*/, const hit_record& rec) const override {
        vec3 outward = rec.front_face ? rec.normal : -rec.normal;
        return real(0.5) * (outward + color(1, 1, 1));
    }

    bool scatter(const ray&, const hit_record&, sampler&, color&, ray&) const override {
        return false;
    }
};

}  // namespace rt
