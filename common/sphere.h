// A sphere |P - C|^2 = r^2. Chapter 02 (chapter 07's moving_sphere lets the center move).
// Ray hit: |A + t b - C|^2 = r^2, a quadratic in t, solved in the numerically stable form of
// Ray Tracing Gems ch. 7 (discriminant from the perpendicular distance, q = -(b' + sign(b') sqrt)).
#pragma once

#include <memory>

#include "hittable.h"

namespace rt {

// The nearest hit of r with the sphere (center, radius) inside ray_t: fills rec's t, p, p_error,
// normal and front_face (the caller adds the material) and returns true, or returns false and
// leaves rec unchanged. Shared by every sphere, moving or not.
bool hit_sphere(const point3& center, real radius, const ray& r, interval ray_t, hit_record& rec);

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
