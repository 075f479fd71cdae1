#include "bounded.h"

namespace rt {

aabb bounding_box(const sphere& s) {
    vec3 extent(s.radius(), s.radius(), s.radius());
    return aabb(s.center() - extent, s.center() + extent);
}

aabb bounding_box(const quad& q) {
    const point3& Q = q.corner();
    const vec3 &u = q.edge_u(), &v = q.edge_v();
    return aabb(aabb(Q, Q + u + v), aabb(Q + u, Q + v));
}

}  // namespace rt
