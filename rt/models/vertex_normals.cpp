#include "rt/models/vertex_normals.h"

#include <cmath>

namespace rt {

void add_smooth_normals(mesh_data& mesh) {
    mesh.normals.assign(mesh.positions.size(), vec3(0, 0, 0));
    for (const auto& t : mesh.triangles) {
        const point3 &p0 = mesh.positions[t[0]], &p1 = mesh.positions[t[1]],
                     &p2    = mesh.positions[t[2]];
        const vec3 weighted = cross(p1 - p0, p2 - p0);  // normal times twice the area
        if (!std::isfinite(weighted.length())) continue;
        for (std::uint32_t v : t) mesh.normals[v] += weighted;
    }
    for (vec3& n : mesh.normals) {
        const real length = n.length();
        n                 = length > 0 && std::isfinite(length) ? n / length : vec3(0, 0, 0);
    }
}

}  // namespace rt
