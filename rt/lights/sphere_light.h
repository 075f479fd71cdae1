// A sphere that emits, sampled by the cone of directions it fills. Seen from ref at distance d
// from its center, a sphere of radius r fills the cone of half-angle theta_max,
//   sin^2 theta_max = r^2 / d^2,
// and every direction of that cone hits it; drawing them uniformly (not points of its area, half
// of which face away) gives pdf(wi) = 1 / (2 pi (1 - cos theta_max)) inside the cone. From
// inside the sphere there is no cone: a uniform point of its area, converted to solid angle.
// Chapter 14.
#pragma once

#include "rt/geometry/sphere.h"
#include "rt/lights/light.h"

namespace rt {

class sphere_light : public light {
  public:
    // shape must outlive this light (the scene owns both).
    explicit sphere_light(const sphere& shape);

    bool sample(const point3& ref, sample2 u, light_sample& out) const override;
    real pdf(const point3& ref, const vec3& wi) const override;
    real pdf_at(const point3& ref, const vec3& wi, const hit_record& hit) const override;
    bool center(point3& at) const override;  // [ch17]

    // 1 - cos theta_max for a sphere whose sin^2 theta_max is s, without the cancellation of
    // 1 - sqrt(1 - s) when the sphere is small or far (s near 0).
    static real one_minus_cos_max(real sin2_max);

  private:
    // sin^2 theta_max seen from ref; >= 1 when ref is inside (or on) the sphere.
    real sin2_max(const point3& ref) const;

    const sphere* shape;
};

}  // namespace rt
