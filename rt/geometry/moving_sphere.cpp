#include "rt/geometry/moving_sphere.h"

namespace rt {

moving_sphere::moving_sphere(const point3& c0, const point3& c1, real r,
                             std::shared_ptr<material> m)
    : path_(c0, c1), radius_(r), mat(std::move(m)) {
    require_positive(radius_, "sphere radius");
    require_given(mat, "sphere material");
}

bool moving_sphere::hit(const ray& r, interval ray_t, hit_record& rec) const {
    if (!hit_sphere(center_at(r.time()), radius_, r, ray_t, rec)) return false;
    rec.mat    = mat.get();
    rec.object = this;  // [ch08]
    return true;
}

aabb moving_sphere::bounding_box() const {
    vec3 extent(radius_, radius_, radius_);
    return aabb(aabb(path_.center0 - extent, path_.center0 + extent),
                aabb(path_.center1 - extent, path_.center1 + extent));
}

}  // namespace rt
