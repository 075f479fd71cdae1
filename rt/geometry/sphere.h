// A sphere |P - C|^2 = r^2. Chapter 02 (chapter 07's moving_sphere lets the center move).
// Ray hit: |A + t b - C|^2 = r^2, a quadratic in t, solved in the numerically stable form of
// Ray Tracing Gems ch. 7 (discriminant from the perpendicular distance, q = -(b' + sign(b') sqrt)).
#pragma once

#include <cmath>
#include <limits>
#include <memory>

#include "rt/geometry/hittable.h"

namespace rt {

// The rarer half of hit_sphere(): the roots and the record of a ray known to cross the sphere
// (sphere.cpp). a, b, c and a2_discriminant are solve_sphere_quadratic()'s.
bool record_sphere_hit(const point3& center, real radius, const ray& r, interval ray_t,
                       hit_record& rec, real a, real b, real c, real a2_discriminant);

// The quadratic of r and the sphere (center, radius): with f = A - C, a t^2 + 2 b t + c = 0,
// a = d.d, b = f.d, c = f.f - r^2, and a2_discriminant = a^2 (b^2 - a c). Returns false when r
// surely misses the sphere, else what crossing(a, b, c, a2_discriminant) returns (then
// a2_discriminant is not negative). Inline, and only the common miss: a wide BVH's leaf (chapter
// 17) tests its spheres in a loop, and the compiler can then compute the ray's own terms (d.d)
// once for all of them. A callback rather than output parameters, so that the terms stay in
// registers; chapter 12's crossing() asks the same quadratic for both of its roots.
template <class Crossing>
inline bool solve_sphere_quadratic(const point3& center, real radius, const ray& r,
                                   Crossing&& crossing) {
    const vec3& d = r.direction();
    vec3 f        = r.origin() - center;
    real a        = dot(d, d);
    real b        = dot(f, d);
    real c        = dot(f, f) - radius * radius;

    // Most spheres of a big list are clearly missed. The textbook discriminant b^2 - a c says so
    // cheaply, but it cancels badly (distant or grazing spheres); trust its "miss" only when it
    // is below minus its own rounding-error bound.
    real bb = b * b, ac = a * c;
    if (bb - ac < -8 * std::numeric_limits<real>::epsilon() * (bb + std::fabs(ac))) return false;

    // b^2 - a c = a (r^2 - |f_perp|^2), where f_perp = f - (b/a) d is f minus its part along the
    // ray: this form avoids subtracting two huge, nearly equal numbers. Scaled by a^2
    // (g = a f_perp) so that it needs no division.
    vec3 g               = a * f - b * d;
    real a2_discriminant = radius * radius * a * a - dot(g, g);
    if (a2_discriminant < 0) return false;
    return crossing(a, b, c, a2_discriminant);
}

// The nearest hit of r with the sphere (center, radius) inside ray_t: fills rec's t, p, p_error,
// normal and front_face (the caller adds the material) and returns true, or returns false and
// leaves rec unchanged. Shared by every sphere, moving or not.
inline bool hit_sphere(const point3& center, real radius, const ray& r, interval ray_t,
                       hit_record& rec) {
    return solve_sphere_quadratic(center, radius, r, [&](real a, real b, real c, real a2_disc) {
        return record_sphere_hit(center, radius, r, ray_t, rec, a, b, c, a2_disc);
    });
}

class sphere : public hittable {
  public:
    // Throws user_error unless radius is positive and finite (no negative-radius tricks: a
    // hollow glass sphere is an inner sphere with an index ratio below 1).
    // Chapter 02 shows shapes by their normals, so a sphere needs no material yet.
    sphere(const point3& center, real radius);
    // [ch03 begin]
    // A sphere made of mat; throws user_error if mat is missing.
    sphere(const point3& center, real radius, std::shared_ptr<material> mat);
    // [ch03 end]

    bool hit(const ray& r, interval ray_t, hit_record& rec) const override;
    bool crossing(const ray& r, interval& inside) const override;  // [ch12] one quadratic

    const point3& center() const { return center_; }
    real radius() const { return radius_; }
    const std::shared_ptr<material>& surface() const { return mat; }  // [ch03]

    // [ch08 begin]
    surface_uv uv_at(const vec3& local) const override { return uv_from_normal(local); }

    // Texture coordinates of a point given by its unit outward normal n: u = phi / (2 pi) from
    // the -x axis eastward around +y, through +z, +x, -z (so an image seen from outside is not
    // mirrored); v = theta / pi from the south pole (y = -1) up.
    //   n = (1,0,0) -> (0.50, 0.50)   n = (0,1,0) -> (u, 1)   n = (0,0,1) -> (0.25, 0.50)
    //   n = (-1,0,0) -> (0.00, 0.50)  n = (0,-1,0) -> (u, 0)  n = (0,0,-1) -> (0.75, 0.50)
    static surface_uv uv_from_normal(const vec3& n);
    // [ch08 end]

  private:
    point3 center_;
    real radius_;
    std::shared_ptr<material> mat;  // [ch03]
};

}  // namespace rt
