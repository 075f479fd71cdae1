#include "rt/geometry/box.h"

#include <algorithm>
#include <sstream>

#include "rt/core/exercise.h"
#include "rt/core/validate.h"
#include "rt/geometry/quad.h"

namespace rt {

std::vector<bounded_object> box_faces(const point3& a, const point3& b,
                                      const std::shared_ptr<material>& mat) {
    point3 lo(std::min(a.x(), b.x()), std::min(a.y(), b.y()), std::min(a.z(), b.z()));
    point3 hi(std::max(a.x(), b.x()), std::max(a.y(), b.y()), std::max(a.z(), b.z()));
    if (!(lo.x() < hi.x() && lo.y() < hi.y() && lo.z() < hi.z())) {
        std::ostringstream corners;
        corners << a << " and " << b;
        require(false, "box corners", "differ in every coordinate (not a flat box)", corners.str());
    }
    // [exercise box_faces begin]
    vec3 dx(hi.x() - lo.x(), 0, 0), dy(0, hi.y() - lo.y(), 0), dz(0, 0, hi.z() - lo.z());

    std::vector<bounded_object> sides;
    // Each face lists its edges so that u x v points outwards.
    sides.push_back(
        std::make_shared<quad>(point3(lo.x(), lo.y(), hi.z()), dx, dy, mat));  // front +z
    sides.push_back(
        std::make_shared<quad>(point3(hi.x(), lo.y(), hi.z()), -dz, dy, mat));  // right +x
    sides.push_back(
        std::make_shared<quad>(point3(hi.x(), lo.y(), lo.z()), -dx, dy, mat));  // back -z
    sides.push_back(
        std::make_shared<quad>(point3(lo.x(), lo.y(), lo.z()), dz, dy, mat));  // left -x
    sides.push_back(
        std::make_shared<quad>(point3(lo.x(), hi.y(), hi.z()), dx, -dz, mat));  // top +y
    sides.push_back(
        std::make_shared<quad>(point3(lo.x(), lo.y(), lo.z()), dx, dz, mat));  // bottom -y
    return sides;
    // [exercise box_faces end]
}

std::shared_ptr<bvh> box(const point3& a, const point3& b, const std::shared_ptr<material>& mat) {
    return std::make_shared<bvh>(box_faces(a, b, mat));
}

}  // namespace rt
