// What a ray can hit, and what it learns at the hit. Chapter 02.
// A hit record stores the nearest hit's distance t, point p, surface coordinates (u, v) and a
// unit normal that always faces the incoming ray (front_face says whether that is the outward
// normal). Bounding boxes come in chapter 07. Key rule: among the hits with t_min < t < t_max,
// the nearest wins.
#pragma once

#include <limits>

#include "aabb.h"
#include "interval.h"
#include "ray.h"

namespace rt {

class material;

// Relative size of the offset that moves a new ray's origin off the surface it leaves.
// Many ulps, so it dominates the rounding in p and in the intersection test; still only ~1e-14
// (double) or ~1e-5 (float) of the scene's scale, far below a pixel.
inline constexpr real spawn_offset_scale = 64 * std::numeric_limits<real>::epsilon();

struct hit_record {
    point3 p;
    vec3 normal;                    // unit, facing against the incoming ray
    const material* mat = nullptr;  // owned by the scene, never null for a hit
    real t              = 0;
    real u = 0, v = 0;       // surface coordinates of p, for textures
    real p_error    = 0;     // bound on the distance of p from the true surface
    bool front_face = true;  // the ray arrived from the outside

    // outward_normal must be unit length.
    void set_face_normal(const ray& r, const vec3& outward_normal) {
        front_face = dot(r.direction(), outward_normal) < 0;
        normal     = front_face ? outward_normal : -outward_normal;
    }

    // A ray leaving this hit. Why not the book's t > 0.001: that constant is too big for tiny
    // objects and too small for huge or distant ones. Instead the origin moves along the normal,
    // to the side the new ray leaves by, farther than the error bound of p. From there a convex
    // surface (sphere, quad) cannot be re-hit near t = 0, at any scale. See test_spawn_ray.
    ray spawn_ray(const vec3& direction, real time) const {
        if (dot(direction, normal) > 0) return spawn_reflected_ray(direction, time);
        return ray(p - p_error * normal, direction, time);
    }

    // A ray known to leave on the side the normal faces (a reflection), even when it grazes the
    // tangent plane and rounding puts dot(direction, normal) at 0 or just below.
    ray spawn_reflected_ray(const vec3& direction, real time) const {
        return ray(p + p_error * normal, direction, time);
    }
};

class hittable {
  public:
    virtual ~hittable() = default;

    // Finds the nearest hit with t inside ray_t. On a hit, fills rec completely and returns true;
    // on a miss returns false and leaves rec unchanged.
    virtual bool hit(const ray& r, interval ray_t, hit_record& rec) const = 0;

    // A box that contains the object at every time of the shutter interval [0, 1].
    virtual aabb bounding_box() const = 0;
};

}  // namespace rt
