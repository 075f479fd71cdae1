// A rectangle as seen from a point: the part of the unit sphere around ref that it covers (a
// spherical rectangle), and directions drawn uniformly in it (Urena, Fajardo and King 2013, "An
// Area-Preserving Parametrization for Spherical Rectangles"). Drawing a point uniformly by area
// gives directions a density d^2 / (|cos| A) per solid angle, large where the rectangle is near
// and seen obliquely (a ceiling beside its lamp); drawn by solid angle, every direction towards
// it has the same density 1 / solid_angle, however near.
// The solid angle is the sum of the four inner angles of the spherical quadrilateral minus 2 pi
// (Girard). A direction is drawn in two steps, each inverting a cumulative area in closed form:
// first the column x of the rectangle (the area of the part left of it grows linearly with the
// first number), then the height y on that column (uniform in the sine of the elevation seen
// along it, which is uniform in solid angle).
// Far away the inner angles come close to pi/2 and their sum loses its digits to rounding, so
// below min_solid_angle the rectangle is drawn by area, with the density that goes with it; the
// choice depends only on ref, so sample and density always agree. Chapter 17.
#pragma once

#include <algorithm>
#include <limits>

#include "rt/core/vec3.h"
#include "rt/samplers/sampler.h"

namespace rt {

class spherical_rectangle {
  public:
    // Below this solid angle (steradians) a rectangle is sampled by area: the inner angles' sum
    // minus 2 pi is off by a few roundings of pi, so it keeps 1e-10 of relative precision at
    // 1e-5 sr in double; in float, 1e5 roundings keep 1e-4 at 0.012 sr.
    static constexpr real min_solid_angle =
        std::max(real(1e-5), real(1e5) * std::numeric_limits<real>::epsilon());

    // The rectangle corner + a edge_u + b edge_v, (a, b) in [0, 1]^2, with edge_u
    // perpendicular to edge_v, seen from ref. Either side of its plane.
    spherical_rectangle(const point3& ref, const point3& corner, const vec3& edge_u,
                        const vec3& edge_v);

    // Whether directions are drawn by solid angle (false: ref is in the rectangle's plane, or
    // sees it too small; then it is drawn by area).
    bool by_solid_angle() const { return solid_angle_ >= min_solid_angle; }
    real solid_angle() const { return solid_angle_; }

    // A point of the rectangle whose direction from ref is uniform in the solid angle, from u
    // in [0, 1)^2; only when by_solid_angle().
    point3 sample(sample2 u) const;

  private:
    point3 ref;
    vec3 x, y, z;         // the frame: along edge_u, along edge_v, away from ref's side
    real x0, x1, y0, y1;  // the rectangle's extent in that frame, seen from ref
    real z0;              // its plane's offset along z (<= 0: z points from the plane to ref)
    real b0, b1, k;       // for the column's inversion
    real solid_angle_ = 0;
};

}  // namespace rt
