// Equiangular sampling (Kulla and Fajardo 2012): a distance along a ray chosen so that the
// points near a light are taken more often, in proportion to 1 / (squared distance to it), the
// way the light a medium scatters falls off. Seen from the light's point c, at height h above
// the ray's line and with the foot of the perpendicular at distance f along it, the point at s
// lies at angle theta = atan((s - f) / h); taking theta uniform between the ends' angles gives
//   s = f + h tan(theta),   pdf(s) = h / ((theta_b - theta_a) (h^2 + (s - f)^2)),
// exactly the 1 / distance^2 shape, up to the medium's transmittance (which varies slowly in
// thin fog). Chapter 17.
#pragma once

#include "rt/core/vec3.h"

namespace rt {

class equiangular {
  public:
    // The line origin + s * unit_direction for s in [s_min, s_max], seen from `center`.
    equiangular(const point3& origin, const vec3& unit_direction, const point3& center, real s_min,
                real s_max);

    // False when the center lies on the line (or so near it, against the stretch's length,
    // that the density would be a spike no sample could follow): use another density then.
    bool usable() const { return usable_; }

    // The distance for u uniform in [0, 1); inside [s_min, s_max]. Only when usable().
    real sample(real u) const;
    // Its density per unit distance at s (0 outside the stretch). Only when usable().
    real pdf(real s) const;

  private:
    real s_min, s_max;
    real foot = 0, height = 0;
    real angle_min = 0, angle_max = 0;
    bool usable_ = false;
};

}  // namespace rt
