// An axis-aligned bounding box: the product of three intervals. Chapter 07.
// Slab test: on each axis the ray is inside the slab for t in [(min - A) / b, (max - A) / b];
// the ray hits the box where the three t intervals overlap.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "rt/core/exercise.h"
#include "rt/core/interval.h"
#include "rt/core/ray.h"

namespace rt {

class aabb {
  public:
    interval x, y, z;  // empty by default: a box around nothing

    aabb() = default;
    // Not padded: a flat box (a quad in a coordinate plane) keeps zero thickness, and a point's
    // box is the point. hit() needs no thickness (see there), and an absolute pad would be too
    // wide for a scene of size 1e-4 and vanish in the rounding of one at 1e5.
    aabb(const interval& ix, const interval& iy, const interval& iz) : x(ix), y(iy), z(iz) {}
    // The box with corners a and b, in any order.
    aabb(const point3& a, const point3& b)
        : aabb(interval(std::min(a.x(), b.x()), std::max(a.x(), b.x())),
               interval(std::min(a.y(), b.y()), std::max(a.y(), b.y())),
               interval(std::min(a.z(), b.z()), std::max(a.z(), b.z()))) {}
    // The smallest box holding both boxes.
    aabb(const aabb& a, const aabb& b)
        : x(std::min(a.x.min, b.x.min), std::max(a.x.max, b.x.max)),
          y(std::min(a.y.min, b.y.min), std::max(a.y.max, b.y.max)),
          z(std::min(a.z.min, b.z.min), std::max(a.z.max, b.z.max)) {}

    const interval& axis_interval(int n) const { return n == 1 ? y : (n == 2 ? z : x); }

    // The box grown by `margin` on every side: room for a bound on the rounding of whatever
    // computed it (rotate's and translate's boxes, a quad's box: see there).
    aabb widened(real margin) const {
        return aabb(interval(x.min - margin, x.max + margin),
                    interval(y.min - margin, y.max + margin),
                    interval(z.min - margin, z.max + margin));
    }

    // The largest |coordinate| of its corners: what the rounding of the box is relative to.
    real magnitude() const {
        return std::fmax(std::fmax(std::fmax(std::fabs(x.min), std::fabs(x.max)),
                                   std::fmax(std::fabs(y.min), std::fabs(y.max))),
                         std::fmax(std::fabs(z.min), std::fabs(z.max)));
    }

    bool empty() const { return x.min > x.max || y.min > y.max || z.min > z.max; }
    point3 centroid() const {
        return point3((x.min + x.max) / 2, (y.min + y.max) / 2, (z.min + z.max) / 2);
    }
    // Half the surface area (the sum of the three face areas): proportional to the chance that a
    // random ray crossing a parent box crosses this one, which is all the SAH needs. A flat box
    // has the area of its one face; a line or a point has 0 (bvh.cpp copes with a zero parent).
    real half_area() const {
        if (empty()) return 0;
        real dx = x.size(), dy = y.size(), dz = z.size();
        return dx * dy + dy * dz + dz * dx;
    }
    int longest_axis() const {
        real dx = x.size(), dy = y.size(), dz = z.size();
        return dx > dy ? (dx > dz ? 0 : 2) : (dy > dz ? 1 : 2);
    }

    // Slab test with a precomputed 1 / direction (+-inf for axis-parallel rays, which the IEEE
    // rules turn into the right +-inf slab bounds). Returns whether the ray overlaps the box
    // within ray_t. NaN from 0 * inf (a ray exactly on a slab face) compares false and is
    // treated as "no constraint", so a ray along a face still counts as inside.
    // Near and far are told apart by the sign of 1 / direction, not by comparing t0 with t1:
    // a comparison with NaN would keep a -inf far distance (a ray along a face with direction
    // -0), and on an empty box (min = +inf > max = -inf) it would swap +-inf into "everywhere".
    // A flat box (min = max on an axis, a quad in a coordinate plane) needs no padding: a ray
    // crossing its plane gets t0 = t1 there, an overlap of zero length, and the test rejects
    // only max < min, after widening the far distance. (The book pads flat boxes by an absolute
    // 1e-4 because its test also rejects max = min.) A ray parallel to the plane is inside the
    // slab only if it lies in the plane: 0 * inf = NaN there, +-inf just off it.
    bool hit(const point3& origin, const vec3& inv_dir, interval ray_t) const {
        // [exercise aabb::hit begin]
        for (int axis = 0; axis < 3; ++axis) {
            const interval& ax = axis_interval(axis);
            real t0            = (ax.min - origin[axis]) * inv_dir[axis];
            real t1            = (ax.max - origin[axis]) * inv_dir[axis];
            if (inv_dir[axis] < 0) std::swap(t0, t1);
            t1 *= t1 > 0 ? robust_factor : 2 - robust_factor;  // later, also when t1 < 0
            if (t0 > ray_t.min) ray_t.min = t0;
            if (t1 < ray_t.max) ray_t.max = t1;
            if (ray_t.max < ray_t.min) return false;
        }
        return true;
        // [exercise aabb::hit end]
    }

  private:
    // Widens the far slab distance by a few ulps so that rounding in the slab test can never
    // reject a box whose contents the ray does hit: each distance (min - A) * (1 / b) is rounded
    // three times, so it is off by at most gamma(3) = 1.5 eps of itself, and a near distance
    // compared with a far one needs twice that (pbrt's 1 + 2 gamma(3)). Relative to the
    // distance, so it holds at every scale.
    static constexpr real robust_factor = 1 + 4 * std::numeric_limits<real>::epsilon();
};

}  // namespace rt
