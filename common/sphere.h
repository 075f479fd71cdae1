// A sphere |P - C|^2 = r^2. Chapter 02.
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

    bool hit(const ray& r, interval ray_t, hit_record& rec) const override;

    const point3& center() const { return center_; }
    real radius() const { return radius_; }

  private:
    [[gnu::noinline]] bool record_hit(const ray& r, interval ray_t, hit_record& rec, real a, real b,
                                      real c, real a2_discriminant) const;

    point3 center_;
    real radius_;
    std::shared_ptr<material> mat;
};

}  // namespace rt
