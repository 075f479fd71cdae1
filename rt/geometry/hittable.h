// What a ray can hit, and what it learns at the hit. Chapter 02.
// A hit record stores the nearest hit's distance t, point p and a unit normal that always faces
// the incoming ray (front_face says whether that is the outward normal). Key rule: among the
// hits with t_min < t < t_max, the nearest wins.
#pragma once

#include <limits>

#include "rt/core/exercise.h"
#include "rt/core/interval.h"
#include "rt/core/ray.h"

namespace rt {

class material;  // [ch03]
class hittable;

// Relative size of the offset that moves a new ray's origin off the surface it leaves (quads and
// instances; a sphere bounds its own points more tightly, sphere.cpp). Many ulps, so it
// dominates the rounding in p and in the intersection test; still only ~1e-14 (double) or
// ~1e-5 (float) of the scene's scale, far below a pixel.
inline constexpr real spawn_offset_scale = 64 * std::numeric_limits<real>::epsilon();

// [ch08 begin]
// Surface coordinates (u, v) of a hit, for textures.
struct surface_uv {
    real u = 0, v = 0;
};
// [ch08 end]

struct hit_record {
    point3 p;
    vec3 normal;                    // unit, facing against the incoming ray
    const material* mat = nullptr;  // [ch03] owned by the scene; null for chapter 02's spheres
    real t              = 0;
    real p_error        = 0;     // bound on the distance of p from the true surface
    bool front_face     = true;  // the ray arrived from the outside
    // [ch08 begin]
    // What (u, v) are computed from, later and only for the nearest hit (a sphere's acos and
    // atan2 on every candidate would cost about a tenth of a big scene's time): the shape that
    // recorded the hit, and the hit in that shape's own terms (before any instance moved it).
    const hittable* object = nullptr;
    vec3 local;
    surface_uv uv() const;
    // [ch08 end]

    // outward_normal must be unit length.
    void set_face_normal(const ray& r, const vec3& outward_normal) {
        // [exercise hit_record::set_face_normal begin]
        front_face = dot(r.direction(), outward_normal) < 0;
        normal     = front_face ? outward_normal : -outward_normal;
        // [exercise hit_record::set_face_normal end]
    }
};

// [ch14 begin]
// Something that wants to see the parts of a composite object (finding a scene's lights).
class part_visitor {
  public:
    virtual void visit(const hittable& part) = 0;

  protected:
    ~part_visitor() = default;
};
// [ch14 end]

class hittable {
  public:
    virtual ~hittable() = default;

    // Finds the nearest hit with t inside ray_t. On a hit, fills rec completely and returns true;
    // on a miss returns false and leaves rec unchanged.
    virtual bool hit(const ray& r, interval ray_t, hit_record& rec) const = 0;

    // [ch08 begin]
    // The surface coordinates of a hit this object recorded, from its rec.local. Objects with
    // no surface (a medium) have none: (0, 0).
    virtual surface_uv uv_at(const vec3& /*local*/) const { return {}; }
    // [ch08 end]

    // [ch12 begin]
    // The stretch of r inside this object, for a medium's boundary (constant_medium): from the
    // nearest hit at any t, even behind the ray's origin, to the next hit after it. The same two
    // numbers as hit() over interval::universe() and then over (entry, infinity), which is what
    // this default asks; a shape that solves for both at once (a sphere) answers for half of
    // the work. False, and `inside` unchanged, when there are not two such hits.
    virtual bool crossing(const ray& r, interval& inside) const {
        // [exercise hittable::crossing begin]
        hit_record entry, exit;
        if (!hit(r, interval::universe(), entry)) return false;
        if (!hit(r, interval(entry.t, infinity), exit)) return false;
        inside = interval(entry.t, exit.t);
        return true;
        // [exercise hittable::crossing end]
    }
    // [ch12 end]

    // [ch14 begin]
    // The fraction of light that travels along r through ray_t unscattered: 0 when a surface is
    // in the way, exp(-density * length) through a medium (constant_medium), the product over
    // the parts of a composite. A shadow ray asks this instead of hit(): any blocker ends it,
    // no nearest hit is needed, and a medium attenuates exactly instead of by a random hit.
    virtual real transmittance(const ray& r, interval ray_t) const {
        hit_record rec;
        return hit(r, ray_t, rec) ? 0 : 1;
    }
    // Shows visitor the objects this one holds directly (a list's members, a BVH's leaves).
    // Shapes, instances and media hold none that a light search should see.
    virtual void visit_parts(part_visitor& /*visitor*/) const {}
    // [ch14 end]
};

// [ch08 begin]
inline surface_uv hit_record::uv() const {
    return object ? object->uv_at(local) : surface_uv{};
}
// [ch08 end]

}  // namespace rt
