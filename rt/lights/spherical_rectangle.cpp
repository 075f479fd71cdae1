#include "rt/lights/spherical_rectangle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace rt {

namespace {

// The inner angle between two great circles, from their planes' unit normals (each pointing
// out of the spherical polygon).
// Where the sine of the elevation is this near to 1, the height is the far edge itself.
constexpr real near_one = 64 * std::numeric_limits<real>::epsilon();

real inner_angle(const vec3& n_in, const vec3& n_out) {
    return std::acos(std::clamp(-dot(n_in, n_out), real(-1), real(1)));
}

}  // namespace

spherical_rectangle::spherical_rectangle(const point3& from, const point3& corner,
                                         const vec3& edge_u, const vec3& edge_v)
    : ref(from) {
    real width = edge_u.length(), height = edge_v.length();
    x      = edge_u / width;
    y      = edge_v / height;
    z      = cross(x, y);
    vec3 d = corner - ref;
    x0     = dot(d, x);
    y0     = dot(d, y);
    z0     = dot(d, z);
    // Seen from the other side, the frame's z turns round, so that z0 <= 0 either way.
    if (z0 > 0) {
        z  = -z;
        z0 = -z0;
    }
    x1 = x0 + width;
    y1 = y0 + height;
    if (!(z0 < 0)) return;  // ref in the rectangle's plane: it sees no solid angle

    // The planes through ref and each edge, their normals pointing out of the rectangle: the
    // cross products of the corners' directions, in order round the rectangle, simplified.
    vec3 n0 = unit_vector(vec3(0, z0, -y0));  // the edge y = y0
    vec3 n1 = unit_vector(vec3(-z0, 0, x1));  // x = x1
    vec3 n2 = unit_vector(vec3(0, -z0, y1));  // y = y1
    vec3 n3 = unit_vector(vec3(z0, 0, -x0));  // x = x0
    real g0 = inner_angle(n0, n1), g1 = inner_angle(n1, n2);
    real g2 = inner_angle(n2, n3), g3 = inner_angle(n3, n0);
    solid_angle_ = std::max(real(0), g0 + g1 + g2 + g3 - 2 * std::numbers::pi_v<real>);
    b0           = n0.z();
    b1           = n2.z();
    k            = 2 * std::numbers::pi_v<real> - g2 - g3;
}

point3 spherical_rectangle::sample(sample2 u) const {
    // The column: the part of the solid angle left of the column x is a spherical polygon
    // whose area is u.u * solid_angle; its last inner angle au follows, and from it the cosine
    // cu of the column's plane with the rectangle's x axis, then the column itself.
    real au = u.u * solid_angle_ + k;
    real fu = (std::cos(au) * b0 - b1) / std::sin(au);
    real cu =
        std::clamp(std::copysign(real(1), fu) / std::sqrt(fu * fu + b0 * b0), real(-1), real(1));
    real xu = std::clamp(-(cu * z0) / std::sqrt(std::max(real(0), 1 - cu * cu)), x0, x1);
    // The height on that column: uniform in the sine of the elevation seen along it.
    real dd  = std::sqrt(xu * xu + z0 * z0);
    real h0  = y0 / std::sqrt(dd * dd + y0 * y0);
    real h1  = y1 / std::sqrt(dd * dd + y1 * y1);
    real hv  = h0 + u.v * (h1 - h0);
    real hv2 = hv * hv;
    real yv  = hv2 < 1 - near_one ? std::clamp(hv * dd / std::sqrt(1 - hv2), y0, y1) : y1;
    return ref + xu * x + yv * y + z0 * z;
}

}  // namespace rt
