#include "rt/geometry/quad.h"

#include <cmath>
#include <sstream>

#include "rt/core/validate.h"

namespace rt {

quad::quad(const point3& Q, const vec3& u, const vec3& v, std::shared_ptr<material> m)
    : mat(std::move(m)) {
    vec3 n         = cross(u, v);
    real area      = n.length();
    real edge_area = u.length() * v.length();
    // Relative test: edges that are parallel to rounding error span no usable plane.
    if (!(area > 1e-6 * edge_area && std::isfinite(area))) {
        std::ostringstream edges;
        edges << "u = " << u << ", v = " << v;
        require(false, "quad edges", "span an area (not be zero or parallel)", edges.str());
    }
    require_given(mat, "quad material");
    vec3 normal = n / area;
    shape_      = {Q, u, v, n / dot(n, n), normal, dot(normal, Q)};
}

bool quad::hit(const ray& r, interval ray_t, hit_record& rec) const {
    if (!hit_quad(shape_, r, ray_t, rec)) return false;
    rec.mat    = mat.get();
    rec.object = this;  // [ch08]
    return true;
}

}  // namespace rt
