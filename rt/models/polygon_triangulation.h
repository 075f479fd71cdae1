// A model's polygon as triangles: ear clipping in the plane the polygon faces most. Chapter 18.
// A convex polygon could be cut as a fan from one corner; a concave one (an L, a ring drawn as a
// keyhole) cannot: the fan's triangles would cover its notches. Ear clipping cuts off, one at a
// time, a corner whose triangle is convex and holds no other corner of what is left, which
// every simple polygon has (the two-ears theorem), so it covers exactly the polygon.
// A polygon that is not simple (its edges cross, or it does not lie in a plane) may have no ear
// left at some point: what remains is then cut as a fan, and the result says so.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "rt/core/vec3.h"

namespace rt {

struct polygon_triangles {
    std::vector<std::array<std::uint32_t, 3>> triangles;  // indices into the polygon's corners
    bool fanned = false;  // some of it had no ear: not a simple polygon
};

// The corners in order, either winding; the triangles keep that winding.
polygon_triangles triangulate_polygon(const std::vector<point3>& corners);

}  // namespace rt
