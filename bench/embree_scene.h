// The anchor's geometry in Embree 3, traced one ray at a time on one thread (rtcIntersect1,
// closest hit). Spheres are Embree's RTC_GEOMETRY_TYPE_SPHERE_POINT, which is a true sphere
// (Embree 3.13's SphereIntersector1 solves the ray-sphere quadratic and reports the nearer root
// inside [tnear, tfar], the farther one when the ray starts inside), not a disc that faces the
// ray (that is RTC_GEOMETRY_TYPE_DISC_POINT). Parallelograms are RTC_GEOMETRY_TYPE_QUAD with
// the corners Q, Q + u, Q + u + v, Q + v, which Embree splits into two triangles of one plane.
#pragma once

#include <embree3/rtcore.h>

#include <cstdint>
#include <vector>

#include "anchor_geometry.h"

namespace rt_bench {

class embree_scene {
  public:
    // Builds the BVH at Embree's highest build quality, on one thread.
    explicit embree_scene(const anchor_geometry& g);
    ~embree_scene();
    embree_scene(const embree_scene&)            = delete;
    embree_scene& operator=(const embree_scene&) = delete;

    // The nearest hit of each ray: the shape's number (anchor_geometry::objects(): spheres
    // first, then quads) or -1 for a miss, and its distance.
    void trace(const std::vector<RTCRay>& rays, std::vector<std::int32_t>& shape,
               std::vector<float>& t) const;

  private:
    RTCDevice device = nullptr;
    RTCScene scene   = nullptr;
    std::uint32_t sphere_count;
};

// An Embree ray for r (whose numbers are floats already: single_precision.h), tracing t in
// [t_min, inf).
RTCRay embree_ray(const rt::ray& r, float t_min = 0);

}  // namespace rt_bench
