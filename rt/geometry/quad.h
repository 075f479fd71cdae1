// A parallelogram Q + a u + b v with a, b in [0, 1]. Chapter 03 uses it as a floor (an
// axis-aligned xz-rectangle is the case u = (dx,0,0), v = (0,0,dz)).
// Ray hit: plane n.P = D with n = unit(u x v), D = n.Q; then (a, b) of the hit point from
// a = w.(p x v), b = w.(u x p), w = (u x v) / |u x v|^2, p = P - Q.
#pragma once

#include <cmath>
#include <memory>

#include "rt/geometry/hittable.h"

namespace rt {

// What a quad's hit test reads: the parallelogram and its plane, precomputed (quad.cpp).
struct quad_shape {
    point3 Q;
    vec3 u, v;
    vec3 w;       // (u x v) / |u x v|^2, for the plane coordinates of a hit
    vec3 normal;  // unit(u x v)
    real D;       // plane offset: n.P = D
};

// The hit of r with the parallelogram inside ray_t: fills rec's t, p, p_error, normal and
// front_face (quad::hit adds the material), or returns false and leaves rec unchanged. A function
// of the shape's fields, not a member, so that chapter 17's BVH leaves can test quads kept as
// arrays of those fields, inlined, without a virtual call each.
inline bool hit_quad(const quad_shape& s, const ray& r, interval ray_t, hit_record& rec) {
    real denom = dot(s.normal, r.direction());
    if (denom == 0) return false;  // parallel to the plane: no single hit point

    real t = (s.D - dot(s.normal, r.origin())) / denom;
    if (!ray_t.surrounds(t)) return false;  // also false for inf and NaN

    point3 p    = r.at(t);
    vec3 planar = p - s.Q;
    real alpha  = dot(s.w, cross(planar, s.v));
    real beta   = dot(s.w, cross(s.u, planar));
    if (!(alpha >= 0 && alpha <= 1 && beta >= 0 && beta <= 1)) return false;

    rec.t = t;
    // Move p onto the plane so its error no longer grows with the distance travelled.
    rec.p       = p - (dot(s.normal, p) - s.D) * s.normal;
    rec.p_error = spawn_offset_scale * (max_abs_component(rec.p) + std::fabs(s.D));
    rec.set_face_normal(r, s.normal);
    rec.local = vec3(alpha, beta, 0);  // [ch08] the plane coordinates, for textures
    return true;
}

class quad : public hittable {
  public:
    // Throws user_error when u and v span no area (zero, or parallel).
    quad(const point3& Q, const vec3& u, const vec3& v, std::shared_ptr<material> mat);

    bool hit(const ray& r, interval ray_t, hit_record& rec) const override;

    // [ch08 begin]
    // (u, v) = (a, b): the hit's coordinates along the two edges, kept in rec.local.
    surface_uv uv_at(const vec3& local) const override { return {local.x(), local.y()}; }
    // [ch08 end]

    // The corner and the two edges; all that the hit test reads, precomputed; the material.
    const point3& corner() const { return shape_.Q; }
    const vec3& edge_u() const { return shape_.u; }
    const vec3& edge_v() const { return shape_.v; }
    const quad_shape& shape() const { return shape_; }
    const std::shared_ptr<material>& surface() const { return mat; }

  private:
    quad_shape shape_;
    std::shared_ptr<material> mat;
};

}  // namespace rt
