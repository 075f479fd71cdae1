// Instances: one object placed elsewhere without copying it. Chapter 11.
// Instead of moving the object, move the ray the opposite way into the object's space, hit the
// object there, and carry the hit back out: p_world = M p_object, n_world = M n_object (M is a
// rotation, so normals need no inverse transpose), and front_face is unchanged because rotations
// and translations preserve the angle between the ray and the normal.
#pragma once

#include <memory>

#include "rt/accel/bounded.h"

namespace rt {

// The object moved by `offset`.
class translate : public bounded_hittable {
  public:
    translate(const bounded_object& object, const vec3& offset);

    bool hit(const ray& r, interval ray_t, hit_record& rec) const override;
    aabb bounding_box() const override { return box; }
    // [ch12 begin]
    bool crossing(const ray& r, interval& inside) const override {
        return object->crossing(r.continued(r.origin() - offset, r.direction()), inside);
    }
    // [ch12 end]
    // [ch14 begin]
    real transmittance(const ray& r, interval ray_t) const override {
        return object->transmittance(r.continued(r.origin() - offset, r.direction()), ray_t);
    }
    // [ch14 end]

    // What is placed, and where: enough to place another object the same way.
    const std::shared_ptr<hittable>& placed() const { return object; }
    const vec3& displacement() const { return offset; }

  private:
    std::shared_ptr<hittable> object;
    vec3 offset;
    aabb box;
};

enum class axis { x, y, z };

// The object turned by `degrees` about a coordinate axis through the origin, right-handed
// (counterclockwise looking down the axis towards the origin). About y, as in the book:
//   x' = cos x + sin z,  z' = -sin x + cos z.
// About x: y' = cos y - sin z, z' = sin y + cos z.
// About z: x' = cos x - sin y, y' = sin x + cos y.
class rotate : public bounded_hittable {
  public:
    rotate(const bounded_object& object, axis about, real degrees);

    bool hit(const ray& r, interval ray_t, hit_record& rec) const override;
    aabb bounding_box() const override { return box; }
    // [ch12 begin]
    bool crossing(const ray& r, interval& inside) const override {
        return object->crossing(r.continued(to_object(r.origin()), to_object(r.direction())),
                                inside);
    }
    // [ch12 end]
    // [ch14 begin]
    real transmittance(const ray& r, interval ray_t) const override {
        return object->transmittance(r.continued(to_object(r.origin()), to_object(r.direction())),
                                     ray_t);
    }
    // [ch14 end]

    // The rotation itself (object to world) and its inverse, for tests and for hit().
    vec3 to_world(const vec3& v) const { return turn(v, sin_theta); }
    vec3 to_object(const vec3& v) const { return turn(v, -sin_theta); }

    // What is turned, and how: enough to turn another object the same way.
    const std::shared_ptr<hittable>& placed() const { return object; }
    axis turned_about() const { return about; }
    real degrees() const { return angle; }

  private:
    vec3 turn(const vec3& v, real sin_angle) const;

    std::shared_ptr<hittable> object;
    axis about;  // the two coordinates that turn: (y, z) about x, (z, x) about y, (x, y) about z
    real angle;  // in degrees, as given
    real sin_theta, cos_theta;
    aabb box;
};

}  // namespace rt
