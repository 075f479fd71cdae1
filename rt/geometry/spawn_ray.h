// Where the next segment of a path starts: off the surface it leaves, so that the segment cannot
// find the same surface again at t ~ 0 (shadow acne). Chapter 03.
// Why not the book's t > 0.001: that constant is too big for tiny objects and too small for huge
// or distant ones. Instead the origin moves along the normal, to the side the new ray leaves by,
// farther than the error bound of the hit point (hit_record::p_error, which every shape states).
// From there a convex surface (sphere, quad) cannot be hit again near t = 0, at any scale
// (tests/ch03/test_spawn_ray.cpp).
#pragma once

#include "rt/geometry/hittable.h"

namespace rt {

// A ray known to leave on the side the normal faces (a reflection), even when it grazes the
// tangent plane and rounding puts dot(direction, normal) at 0 or just below.
inline ray spawn_reflected_ray(const hit_record& rec, const ray& r_in, const vec3& direction) {
    return r_in.continued(rec.p + rec.p_error * rec.normal, direction);
}

// The next segment of r_in's path, leaving the hit rec in `direction`, on whichever side that
// points to.
inline ray spawn_ray(const hit_record& rec, const ray& r_in, const vec3& direction) {
    if (dot(direction, rec.normal) > 0) return spawn_reflected_ray(rec, r_in, direction);
    return r_in.continued(rec.p - rec.p_error * rec.normal, direction);
}

}  // namespace rt
