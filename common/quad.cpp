#include "quad.h"

#include <cmath>
#include <sstream>

#include "validate.h"

namespace rt {

quad::quad(const point3& q, const vec3& u_edge, const vec3& v_edge, std::shared_ptr<material> m)
    : Q(q), u(u_edge), v(v_edge), mat(std::move(m)) {
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
    normal = n / area;
    D      = dot(normal, Q);
    w      = n / dot(n, n);
}

bool quad::hit(const ray& r, interval ray_t, hit_record& rec) const {
    real denom = dot(normal, r.direction());
    if (denom == 0) return false;  // parallel to the plane: no single hit point

    real t = (D - dot(normal, r.origin())) / denom;
    if (!ray_t.surrounds(t)) return false;  // also false for inf and NaN

    point3 p    = r.at(t);
    vec3 planar = p - Q;
    real alpha  = dot(w, cross(planar, v));
    real beta   = dot(w, cross(u, planar));
    if (!(alpha >= 0 && alpha <= 1 && beta >= 0 && beta <= 1)) return false;

    rec.t = t;
    // Move p onto the plane so its error no longer grows with the distance travelled.
    rec.p       = p - (dot(normal, p) - D) * normal;
    rec.p_error = spawn_offset_scale * (max_abs_component(rec.p) + std::fabs(D));
    rec.set_face_normal(r, normal);
    rec.mat    = mat.get();
    rec.object = this;                  // [ch08]
    rec.local  = vec3(alpha, beta, 0);  // [ch08]
    return true;
}

}  // namespace rt
