// Objects that know their bounding box: what a BVH is built from. Chapter 07.
// Boxes arrive after spheres and quads, so those two get theirs from the functions here, and
// every object type from this chapter on (moving spheres, BVHs, instances, media) is a
// bounded_hittable that answers for itself. A bounded_object pairs any of them with its box, so
// the compiler, not a run-time check, refuses an object whose box nobody knows.
#pragma once

#include <memory>

#include "rt/accel/aabb.h"
#include "rt/core/validate.h"
#include "rt/geometry/hittable.h"
#include "rt/geometry/quad.h"
#include "rt/geometry/sphere.h"

namespace rt {

class bounded_hittable : public hittable {
  public:
    // A box that contains the object at every time of the shutter interval [0, 1].
    virtual aabb bounding_box() const = 0;
};

aabb bounding_box(const sphere& s);
aabb bounding_box(const quad& q);  // its four corners' box, a few ulps wider (bounded.cpp)
inline aabb bounding_box(const bounded_hittable& object) {
    return object.bounding_box();
}

struct bounded_object {
    std::shared_ptr<hittable> object;
    aabb box;

    // From any object whose box is known: a sphere, a quad or a bounded_hittable.
    template <typename Object>
    bounded_object(std::shared_ptr<Object> shape) {  // NOLINT: converting on purpose
        require_given(shape, "bounded object");
        box    = bounding_box(*shape);
        object = std::move(shape);
    }
};

}  // namespace rt
