// A quad that emits, sampled by area: a uniform point p = Q + a u + b v, (a, b) in [0, 1)^2, has
// density 1 / A per unit area; seen from ref at distance d, the patch dA covers the solid angle
// |cos theta_light| dA / d^2, so per solid angle
//   pdf(wi) = d^2 / (|cos theta_light| A).
// |cos|: book 2's lights emit on both faces, so both faces are sampled. Chapter 14.
#pragma once

#include "rt/geometry/quad.h"
#include "rt/lights/light.h"

namespace rt {

class quad_light : public light {
  public:
    // shape must outlive this light (the scene owns both).
    explicit quad_light(const quad& shape);

    bool sample(const point3& ref, sample2 u, light_sample& out) const override;
    real pdf(const point3& ref, const vec3& wi) const override;
    real pdf_at(const point3& ref, const vec3& wi, const hit_record& hit) const override;
    bool center(point3& at) const override;  // [ch17]

  protected:
    // The sample towards `target`, a point of the quad, with the given density (when the
    // caller knows it: 0 asks pdf_at).
    bool aim_at(const point3& ref, const point3& target, light_sample& out, real density = 0) const;

    const quad* shape;
    real area;
};

}  // namespace rt
