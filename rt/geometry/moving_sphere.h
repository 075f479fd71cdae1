// A sphere whose center moves linearly while the shutter is open: C(t) = C0 + t (C1 - C0) for
// t in [0, 1]. Chapter 07. A ray meets the sphere where it is at the ray's instant, so averaging
// rays over the shutter blurs the sphere along its path (motion blur).
#pragma once

#include <memory>

#include "rt/accel/bounded.h"
#include "rt/core/exercise.h"
#include "rt/geometry/sphere.h"

namespace rt {

// The path of the center: C0 at time 0, C1 at time 1. A value of its own so that chapter 17's
// BVH leaves can keep their moving spheres' paths side by side (leaf_shapes.h) and move them
// with this same formula.
struct center_path {
    point3 center0, center1;
    vec3 velocity;  // C1 - C0

    center_path(const point3& c0, const point3& c1) : center0(c0), center1(c1), velocity(c1 - c0) {}

    // C(t), exactly C0 at time 0 and C1 at time 1: each half of the shutter starts from its
    // own end (C0 + 1 * (C1 - C0) could round away from C1), the second half as C1 + (t - 1) v,
    // with t - 1 exact. Each moves at most half of |C1 - C0| (plus rounding) from its end, so C(t)
    // stays inside the box of C0 and C1 for t in [0, 1]. One formula with selected inputs, so
    // there is nothing to branch on: ray times are random.
    point3 at(real time) const {
        // [exercise center_path::at begin]
        const bool late    = time >= real(0.5);
        const point3& from = late ? center1 : center0;
        return from + (late ? time - 1 : time) * velocity;
        // [exercise center_path::at end]
    }
};

class moving_sphere : public bounded_hittable {
  public:
    // Throws user_error unless radius is positive and finite and mat is given.
    moving_sphere(const point3& center0, const point3& center1, real radius,
                  std::shared_ptr<material> mat);

    bool hit(const ray& r, interval ray_t, hit_record& rec) const override;
    aabb bounding_box() const override;  // the box of both ends: C(t) stays between them

    point3 center_at(real time) const { return path_.at(time); }
    const center_path& path() const { return path_; }
    real radius() const { return radius_; }
    const std::shared_ptr<material>& surface() const { return mat; }

    // [ch08 begin]
    surface_uv uv_at(const vec3& local) const override { return sphere::uv_from_normal(local); }
    // [ch08 end]

  private:
    center_path path_;
    real radius_;
    std::shared_ptr<material> mat;
};

}  // namespace rt
