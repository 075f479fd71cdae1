// Helpers for the tests of chapter 03 on, where shapes carry materials: a material for a shape
// whose material a test never looks at, and a hit record made by hand for a material to scatter
// from. Included as "ch03/material_helpers.h".
#pragma once

#include <memory>

#include "rt/core/vec3.h"
#include "rt/geometry/hittable.h"
#include "rt/materials/lambertian.h"
#include "rt/materials/material.h"

namespace rt_test {

// A fresh material for a shape whose material the test never looks at.
inline std::shared_ptr<rt::material> any_material() {
    return std::make_shared<rt::lambertian>(rt::color(0.5, 0.5, 0.5));
}

// A hit at p with the unit normal n (facing the incoming ray), as a shape would report it: t = 1,
// and the error bound of a point at p's scale (hittable.h's spawn_offset_scale). No material.
inline rt::hit_record hit_at(const rt::point3& p, const rt::vec3& n, bool front_face) {
    rt::hit_record rec;
    rec.p          = p;
    rec.normal     = n;
    rec.front_face = front_face;
    rec.t          = 1;
    rec.p_error    = rt::spawn_offset_scale * (1 + rt::max_abs_component(p));
    return rec;
}

}  // namespace rt_test
