// A parallelogram Q + a u + b v with a, b in [0, 1]. Chapter 03 uses it as a floor (an
// axis-aligned xz-rectangle is the case u = (dx,0,0), v = (0,0,dz)).
// Ray hit: plane n.P = D with n = unit(u x v), D = n.Q; then (a, b) of the hit point from
// a = w.(p x v), b = w.(u x p), w = (u x v) / |u x v|^2, p = P - Q.
#pragma once

#include <memory>

#include "hittable.h"

namespace rt {

class quad : public hittable {
  public:
    // Throws user_error when u and v span no area (zero, or parallel).
    quad(const point3& Q, const vec3& u, const vec3& v, std::shared_ptr<material> mat);

    bool hit(const ray& r, interval ray_t, hit_record& rec) const override;

    // [ch08 begin]
    // (u, v) = (a, b): the hit's coordinates along the two edges, kept in rec.local.
    surface_uv uv_at(const vec3& local) const override { return {local.x(), local.y()}; }
    // [ch08 end]

    // The corner and the two edges.
    const point3& corner() const { return Q; }
    const vec3& edge_u() const { return u; }
    const vec3& edge_v() const { return v; }
    const std::shared_ptr<material>& surface() const { return mat; }  // [ch14]

  private:
    point3 Q;
    vec3 u, v;
    vec3 w;       // (u x v) / |u x v|^2, for the plane coordinates of a hit
    vec3 normal;  // unit(u x v)
    real D;       // plane offset: n.P = D
    std::shared_ptr<material> mat;
};

}  // namespace rt
