// Placing a model where a scene wants it. Chapter 18.
#pragma once

#include "rt/accel/aabb.h"
#include "rt/geometry/triangle_mesh.h"

namespace rt {

// The model scaled, without turning it, to `height` (its box's y extent), its box's floor centre
// moved to `base`: a scan comes in its own units, wherever its author left it. The vertices
// themselves move (not an instance around them), so the mesh's tree is built where it stands.
inline mesh_data fitted(mesh_data model, const point3& base, real height) {
    aabb box;
    for (const point3& p : model.positions) box = aabb(box, aabb(p, p));
    const real scale = height / box.y.size();
    const point3 floor_centre((box.x.min + box.x.max) / 2, box.y.min, (box.z.min + box.z.max) / 2);
    for (point3& p : model.positions) p = base + scale * (p - floor_centre);
    return model;
}

}  // namespace rt
