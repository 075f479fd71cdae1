// Rays and shapes that Embree (single precision) and our renderer (`real`, double by default)
// see as the same numbers. Embree reads floats: a ray or a sphere rounded to float on its way
// there would differ from ours by an ulp, so every benchmark ray and shape is rounded to float
// once, up front, and both tracers get the rounded values.
#pragma once

#include <limits>

#include "rt/core/ray.h"
#include "rt/geometry/hittable.h"

namespace rt_bench {

inline rt::real to_float(rt::real x) {
    return static_cast<rt::real>(static_cast<float>(x));
}

inline rt::vec3 to_float(const rt::vec3& v) {
    return rt::vec3(to_float(v.x()), to_float(v.y()), to_float(v.z()));
}

// r with its origin and direction rounded to float (its instant stays 0: rays of the anchor
// are taken at time 0).
inline rt::ray to_float(const rt::ray& r) {
    return rt::ray(to_float(r.origin()), to_float(r.direction()));
}

// The spawn offset the float build of the renderer would use for a hit whose offset in this
// build is p_error (hittable.h: a fixed number of ulps of the shape's size). A spawned origin
// rounded to float moves by half a float ulp, which the double offset (~1e-14 of the scene)
// cannot cover: the ray could start inside its own surface and hit it again at t ~ 0, in
// Embree or in ours. With the float offset it starts safely outside in both.
inline rt::real float_spawn_offset(rt::real p_error) {
    constexpr rt::real ratio =
        rt::real(std::numeric_limits<float>::epsilon()) / std::numeric_limits<rt::real>::epsilon();
    return p_error * ratio;
}

// A new ray leaving the hit rec on the side its normal faces, with the float offset.
inline rt::ray spawn_float_ray(const rt::hit_record& rec, const rt::vec3& direction) {
    return to_float(rt::ray(rec.p + float_spawn_offset(rec.p_error) * rec.normal, direction));
}

}  // namespace rt_bench
