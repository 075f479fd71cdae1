// A box: the six quads of the axis-aligned box with opposite corners a and b. Chapter 11.
// Every face's normal u x v points out of the box, so front_face means "hit from outside".
#pragma once

#include <memory>
#include <vector>

#include "rt/accel/bounded.h"
#include "rt/accel/bvh.h"

namespace rt {

// The six faces, for a caller that puts them into a larger BVH itself.
// Throws user_error when the box is flat (a and b share a coordinate).
std::vector<bounded_object> box_faces(const point3& a, const point3& b,
                                      const std::shared_ptr<material>& mat);

// The box as one object: its six faces in a small BVH (a ray then tests the faces it can reach,
// nearest first, instead of all six).
std::shared_ptr<bvh> box(const point3& a, const point3& b, const std::shared_ptr<material>& mat);

}  // namespace rt
