// A triangle's hit test, watertight: a ray that crosses a mesh through a shared edge or vertex
// hits one of the triangles there, never none. Chapter 18.
// Woop, Benthin and Wald's test (2013): move the ray's origin to 0, turn the axes so that the
// ray's largest direction component is z, and shear x and y so that the ray runs along z. In
// that space the hit lies at (0, 0), and the 2D edge functions
//   e0 = x1 y2 - y1 x2,  e1 = x2 y0 - y2 x0,  e2 = x0 y1 - y0 x1
// of the moved vertices are the barycentric weights times twice the area (all negative when
// the ray sees the winding the other way round). The ray hits where they do not differ in sign. Why
// it is watertight: the two triangles sharing an edge compute that edge's function from the same
// two moved vertices, as the same two products in the other order, so one gets exactly the other's
// negative; a ray on the edge sees 0 in both and hits both, a ray beside it hits exactly one. No
// epsilon anywhere. (The products must be rounded one by one, not fused into a multiply-add:
// chapter 18's layer compiles with -ffp-contract=off, and C++20's strict mode, in which every
// target here builds, fuses none either.)
// Error bound: the hit point is b0 p0 + b1 p1 + b2 p2, on the plane to within a few ulps of the
// vertices' coordinates; p_error is spawn_offset_scale times the largest of them, which also
// covers the rounding of the next ray's test against the same plane (tests/ch18).
#pragma once

#include <cmath>

#include "rt/core/exercise.h"
#include "rt/geometry/hittable.h"

namespace rt {

// What every triangle test of one ray shares: the axes' turn and the shear.
struct sheared_ray {
    point3 origin;
    int kx = 0, ky = 1, kz = 2;   // the turn: the ray's largest direction component becomes z
    real sx = 0, sy = 0, sz = 1;  // the shear

    explicit sheared_ray(const ray& r) : origin(r.origin()) {
        const vec3& d = r.direction();
        const real ax = std::fabs(d.x()), ay = std::fabs(d.y()), az = std::fabs(d.z());
        kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
        kx = kz == 2 ? 0 : kz + 1;
        ky = kx == 2 ? 0 : kx + 1;
        sx = d[kx] / d[kz];
        sy = d[ky] / d[kz];
        sz = 1 / d[kz];
    }
};

// Where a ray meets a triangle: the distance and the barycentric weights of the three vertices.
struct triangle_hit {
    real t  = 0;
    real b0 = 0, b1 = 0, b2 = 0;
};

// The hit of the sheared ray with the triangle (p0, p1, p2) inside ray_t, if any. A ray in the
// triangle's plane, a zero-area triangle and a NaN anywhere give none.
inline bool intersect_triangle(const sheared_ray& sr, const point3& p0, const point3& p1,
                               const point3& p2, interval ray_t, triangle_hit& hit) {
    // [exercise intersect_triangle begin]
    const vec3 a = p0 - sr.origin, b = p1 - sr.origin, c = p2 - sr.origin;
    const real x0 = a[sr.kx] - sr.sx * a[sr.kz], y0 = a[sr.ky] - sr.sy * a[sr.kz];
    const real x1 = b[sr.kx] - sr.sx * b[sr.kz], y1 = b[sr.ky] - sr.sy * b[sr.kz];
    const real x2 = c[sr.kx] - sr.sx * c[sr.kz], y2 = c[sr.ky] - sr.sy * c[sr.kz];
    const real e0 = x1 * y2 - y1 * x2;
    const real e1 = x2 * y0 - y2 * x0;
    const real e2 = x0 * y1 - y0 * x1;
    if ((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0)) return false;
    const real det = e0 + e1 + e2;
    if (!(det != 0)) return false;  // edge-on, a zero-area triangle, or NaN
    // The hit's distance times det, from the vertices' sheared z.
    const real scaled_t =
        e0 * (sr.sz * a[sr.kz]) + e1 * (sr.sz * b[sr.kz]) + e2 * (sr.sz * c[sr.kz]);
    const real inv_det = 1 / det;
    const real t       = scaled_t * inv_det;
    if (!ray_t.surrounds(t)) return false;  // also false for inf and NaN
    hit = {t, e0 * inv_det, e1 * inv_det, e2 * inv_det};
    return true;
    // [exercise intersect_triangle end]
}

// The largest |coordinate| of the three vertices: what a hit's rounding is relative to.
inline real triangle_magnitude(const point3& p0, const point3& p1, const point3& p2) {
    // fmax's answer without its library call: none is negative, and a NaN loses.
    auto larger = [](real a, real b) { return a > b || std::isnan(b) ? a : b; };
    return larger(max_abs_component(p0), larger(max_abs_component(p1), max_abs_component(p2)));
}

// Fills rec's t, p, p_error, normal (the geometric one, unit(e1 x e2) of the winding p0, p1,
// p2), front_face and local (b1, b2: the barycentric weights of p1 and p2) for a hit.
inline void record_triangle_hit(const triangle_hit& hit, const point3& p0, const point3& p1,
                                const point3& p2, const ray& r, hit_record& rec) {
    rec.t       = hit.t;
    rec.p       = hit.b0 * p0 + hit.b1 * p1 + hit.b2 * p2;
    rec.p_error = spawn_offset_scale * triangle_magnitude(p0, p1, p2);
    rec.set_face_normal(r, unit_vector(cross(p1 - p0, p2 - p0)));
    rec.local = vec3(hit.b1, hit.b2, 0);
}

}  // namespace rt
