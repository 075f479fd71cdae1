// A sphere |P - C(t)|^2 = r^2. Chapter 02; chapter 07 lets the center move linearly,
// C(t) = C0 + t (C1 - C0) over the shutter interval t in [0, 1]; chapter 08 adds (u, v).
// Ray hit: |A + t b - C|^2 = r^2, a quadratic in t, solved in the numerically stable form of
// Ray Tracing Gems ch. 7 (discriminant from the perpendicular distance, q = -(b' + sign(b') sqrt)).
#pragma once

#include <memory>

#include "hittable.h"
#include "material.h"

namespace rt {

class sphere : public hittable {
  public:
    // Throws user_error unless radius is positive and finite (no negative-radius tricks: a
    // hollow glass sphere is an inner sphere with an index ratio below 1).
    sphere(const point3& center, real radius, std::shared_ptr<material> mat);
    // A sphere moving from center0 at time 0 to center1 at time 1.
    sphere(const point3& center0, const point3& center1, real radius,
           std::shared_ptr<material> mat);

    bool hit(const ray& r, interval ray_t, hit_record& rec) const override;
    aabb bounding_box() const override;

    // C(t), exactly C0 at time 0 and C1 at time 1: each half of the shutter starts from its
    // own end (C0 + 1 * (C1 - C0) could round away from C1), the second half as C1 + (t - 1) v,
    // with t - 1 exact. Each moves at most half of |C1 - C0| (plus rounding) from its end, so C(t)
    // stays inside the box of C0 and C1 for t in [0, 1]. One formula with selected inputs, so
    // there is nothing to branch on: ray times are random, and every sphere test runs this.
    point3 center_at(real time) const {
        const bool late    = time >= real(0.5);
        const point3& from = late ? center1 : center0;
        return from + (late ? time - 1 : time) * velocity;
    }

    // Texture coordinates of a point given by its unit outward normal n: u = phi / (2 pi) from
    // the -x axis eastward around +y, through +z, +x, -z (so an image seen from outside is not
    // mirrored); v = theta / pi from the south pole (y = -1) up.
    //   n = (1,0,0) -> (0.50, 0.50)   n = (0,1,0) -> (u, 1)   n = (0,0,1) -> (0.25, 0.50)
    //   n = (-1,0,0) -> (0.00, 0.50)  n = (0,-1,0) -> (u, 0)  n = (0,0,-1) -> (0.75, 0.50)
    static void uv_from_normal(const vec3& n, real& u, real& v);

  private:
    [[gnu::noinline]] bool record_hit(const ray& r, interval ray_t, hit_record& rec,
                                      const point3& center, real a, real b, real c,
                                      real a2_discriminant) const;

    point3 center0, center1;
    vec3 velocity;          // C1 - C0: zero for a static sphere
    bool is_moving;         // C1 != C0
    bool needs_uv = false;  // the material reads (u, v): only then pay for acos and atan2
    real radius_;
    std::shared_ptr<material> mat;
};

}  // namespace rt
