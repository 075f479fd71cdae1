// An axis-aligned bounding box: the product of three intervals. Chapter 07.
// Slab test: on each axis the ray is inside the slab for t in [(min - A) / b, (max - A) / b];
// the ray hits the box where the three t intervals overlap.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "interval.h"
#include "ray.h"

namespace rt {

class aabb {
  public:
    interval x, y, z;  // empty by default: a box around nothing

    aabb() = default;
    aabb(const interval& ix, const interval& iy, const interval& iz) : x(ix), y(iy), z(iz) {
        pad_to_minimums();
    }
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

    bool empty() const { return x.min > x.max || y.min > y.max || z.min > z.max; }
    point3 centroid() const {
        return point3((x.min + x.max) / 2, (y.min + y.max) / 2, (z.min + z.max) / 2);
    }
    // Half the surface area (the sum of the three face areas): proportional to the chance that a
    // random ray crossing a parent box crosses this one, which is all the SAH needs.
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
    bool hit(const point3& origin, const vec3& inv_dir, interval ray_t) const {
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
    }

  private:
    // Widens the far slab distance by a few ulps so that rounding in the slab test can never
    // reject a box whose contents the ray does hit (pbrt's 1 + 2 gamma(3)).
    static constexpr real robust_factor = 1 + 4 * std::numeric_limits<real>::epsilon();

    // Widens any axis thinner than delta around its middle, as the book does for flat boxes (a
    // quad in a coordinate plane). The slab test divides by the direction, never by the width,
    // and the book pads because its test rejects an overlap of zero length (max <= min): the two
    // slab distances of a flat axis are equal, so without padding no crossing ray would hit a
    // flat box there.
    // hit() above needs no padding: it rejects only max < min and widens the far distance, so a
    // zero-length overlap counts. Without it the Cornell box renders byte for byte the same; we
    // keep it only so that no box has zero thickness.
    void pad_to_minimums() {
        constexpr real delta = real(1e-4);
        auto pad             = [](interval& i) {
            if (i.size() < delta) i = interval(i.min - delta / 2, i.max + delta / 2);
        };
        pad(x);
        pad(y);
        pad(z);
    }
};

}  // namespace rt
