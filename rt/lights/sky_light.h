// The sky as a light (chapter 14). Our sky (background.h) blends two colors by the height of the
// direction, y = cos theta, so its brightness w(y) = mean of the channels is linear in y:
//   w(y) = a + b y,   a = (w_top + w_bottom) / 2,   b = (w_top - w_bottom) / 2.
// On the sphere d omega = dy dphi, so drawing y with density (a + b y) / (2 a) on [-1, 1] and phi
// uniformly gives directions in proportion to the light each brings:
//   pdf(wi) = (a + b y) / (4 pi a).
// A uniform sky (b = 0) is sampled uniformly over the sphere. A black sky is no light at all.
#pragma once

#include "rt/lights/light.h"
#include "rt/scene/background.h"

namespace rt {

class sky_light : public light {
  public:
    explicit sky_light(const background& sky);

    // Whether the sky sends any light (a black sky is not worth a shadow ray).
    static bool emits(const background& sky);

    bool sample(const point3& ref, sample2 u, light_sample& out) const override;
    real pdf(const point3& ref, const vec3& wi) const override;
    // hit is unused: the sky is reached by missing everything.
    real pdf_at(const point3& ref, const vec3& wi, const hit_record& hit) const override;

    // The height y in [-1, 1] whose share of the sky's brightness below it is u.
    real height_for(real u) const;

  private:
    background sky;
    real a, b;
};

}  // namespace rt
