#include "rt/accel/triangle_leaves.h"

#include <typeinfo>

namespace rt {

std::optional<std::uint32_t> triangle_leaves::add(const hittable& object) {
    if (typeid(object) != typeid(mesh_triangle)) return std::nullopt;
    const auto& t = static_cast<const mesh_triangle&>(object);
    fields.push_back({t.mesh().data().positions.data(), t.mesh().triangle(t.index()), &t});
    return std::uint32_t(fields.size() - 1);
}

bool triangle_leaves::hit(std::uint32_t first, std::uint32_t count, const ray& r, interval& ray_t,
                          hit_record& rec) const {
    const sheared_ray sr(r);
    const one* nearest = nullptr;
    triangle_hit found, candidate;
    for (std::uint32_t i = first; i < first + count; ++i) {
        const one& t = fields[i];
        if (intersect_triangle(sr, t.positions[t.vertex[0]], t.positions[t.vertex[1]],
                               t.positions[t.vertex[2]], ray_t, candidate)) {
            found     = candidate;
            nearest   = &t;
            ray_t.max = candidate.t;
        }
    }
    if (!nearest) return false;
    // What mesh_triangle::hit fills, once: every field of the record comes from the nearest.
    const point3* p = nearest->positions;
    record_triangle_hit(found, p[nearest->vertex[0]], p[nearest->vertex[1]], p[nearest->vertex[2]],
                        r, rec);
    const mesh_triangle& object = *nearest->object;
    object.mesh().shade(object.index(), found, r, rec);
    rec.mat    = object.mesh().surface();
    rec.object = &object;
    return true;
}

leaf_shapes_maker triangle_leaves::maker() {
    return [] { return std::make_unique<triangle_leaves>(); };
}

}  // namespace rt
