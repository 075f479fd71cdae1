#include "moving_sphere.h"

namespace rt {

moving_sphere::moving_sphere(const point3& c0, const point3& c1, real r,
                             std::shared_ptr<material> m)
    : center0(c0), center1(c1), velocity(c1 - c0), radius(r), mat(std::move(m)) {
    require_positive(radius, "sphere radius");
    require_given(mat, "sphere material");
}

bool moving_sphere::hit(const ray& r, interval ray_t, hit_record& rec) const {
    if (!hit_sphere(center_at(r.time()), radius, r, ray_t, rec)) return false;
    rec.mat    = mat.get();
    rec.object = this;  // [ch08]
    return true;
}

aabb moving_sphere::bounding_box() const {
    vec3 extent(radius, radius, radius);
    return aabb(aabb(center0 - extent, center0 + extent), aabb(center1 - extent, center1 + extent));
}

}  // namespace rt
