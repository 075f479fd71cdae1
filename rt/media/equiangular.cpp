#include "rt/media/equiangular.h"

#include <algorithm>
#include <cmath>

namespace rt {

equiangular::equiangular(const point3& origin, const vec3& unit_direction, const point3& center,
                         real lo, real hi)
    : s_min(lo), s_max(hi) {
    const vec3 to_center = center - origin;
    foot                 = dot(to_center, unit_direction);
    // |to_center x direction|, not sqrt(|to_center|^2 - foot^2): that difference cancels when
    // the light lies far along the ray.
    height    = cross(to_center, unit_direction).length();
    angle_min = std::atan2(s_min - foot, height);
    angle_max = std::atan2(s_max - foot, height);
    // The density peaks at 1 / (height (angle_max - angle_min)) over a stretch of about the
    // height: below a millionth of the stretch it is a spike, and a center on the line has none.
    usable_ = std::isfinite(s_max) && s_min < s_max && height > real(1e-6) * (s_max - s_min) &&
              angle_min < angle_max;
}

real equiangular::sample(real u) const {
    const real angle = angle_min + u * (angle_max - angle_min);
    return std::clamp(foot + height * std::tan(angle), s_min, s_max);
}

real equiangular::pdf(real s) const {
    if (!(s >= s_min && s <= s_max)) return 0;
    const real along = s - foot;
    return height / ((angle_max - angle_min) * (height * height + along * along));
}

}  // namespace rt
