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

    point3 center_at(real time) const { return center0 + time * velocity; }
    real radius() const { return radius_; }

    // Texture coordinates of a point given by its unit outward normal n: u = phi / (2 pi) from
    // the -x axis around through -z, +x, +z; v = theta / pi from the south pole (y = -1) up.
    //   n = (1,0,0) -> (0.50, 0.50)   n = (0,1,0) -> (u, 1)   n = (0,0,1) -> (0.75, 0.50)
    //   n = (-1,0,0) -> (0.00, 0.50)  n = (0,-1,0) -> (u, 0)  n = (0,0,-1) -> (0.25, 0.50)
    static void uv_from_normal(const vec3& n, real& u, real& v);

  private:
    [[gnu::noinline]] bool record_hit(const ray& r, interval ray_t, hit_record& rec,
                                      const point3& center, real a, real b, real c,
                                      real a2_discriminant) const;

    point3 center0;
    vec3 velocity;  // C1 - C0: zero for a static sphere
    real radius_;
    std::shared_ptr<material> mat;
};

}  // namespace rt
