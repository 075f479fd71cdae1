#include "rt/geometry/sphere.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rt/core/exercise.h"
#include "rt/core/validate.h"

namespace rt {

namespace {

// How far p = center + radius * n can be from the true sphere, in units of radius + |p|: n's
// length is 1 to within about 3 eps (a sum of squares, a square root and a division), radius * n
// rounds by eps / 2 of the radius, and the sum with the center by eps / 2 of each coordinate of
// p. The next ray's test of this sphere adds about eps * radius (the cancellation in
// |origin - center|^2 - radius^2). Twice those, so that an origin moved off by this bound is off
// for sure (test_spawn_ray). Why |p| and not |center|: a big sphere's center lies far from the
// point. A bound by |center| would move float rays off the ground of radius 1000 at
// (0, -1000, 0) by 0.015, into the small spheres resting on it, and darken their contact
// shadows.
constexpr real sphere_error_scale = 8 * std::numeric_limits<real>::epsilon();

// Both roots, t_near <= t_far, of solve_sphere_quadratic()'s equation for a ray that may cross.
// Stable: q never cancels, since b and sign(b) sqrt(...) add with the same sign.
// sqrt(b^2 - a c) = sqrt(a * discriminant) = sqrt(a2_discriminant / a).
inline void sphere_roots(real a, real b, real c, real a2_discriminant, real& t_near, real& t_far) {
    // [exercise sphere_roots begin]
    real q = -(b + std::copysign(std::sqrt(a2_discriminant / a), b));
    t_far  = q / a;
    // q = 0 only for a ray that starts on the sphere and grazes it: both roots are then 0.
    t_near = q != 0 ? c / q : t_far;
    if (t_near > t_far) std::swap(t_near, t_far);
    // [exercise sphere_roots end]
}

// The root a hit inside ray_t takes: the nearer one if ray_t holds it, else the farther.
inline bool first_root_inside(real t_near, real t_far, interval ray_t, real& root) {
    root = t_near;
    if (ray_t.surrounds(root)) return true;
    root = t_far;
    return ray_t.surrounds(root);
}

}  // namespace

// Out of line on purpose (noinline): the common miss, inlined wherever spheres are tested, then
// stays short.
[[gnu::noinline]] bool record_sphere_hit(const point3& center, real radius, const ray& r,
                                         interval ray_t, hit_record& rec, real a, real b, real c,
                                         real a2_discriminant) {
    real t_near = 0, t_far = 0, root = 0;
    sphere_roots(a, b, c, a2_discriminant, t_near, t_far);
    if (!first_root_inside(t_near, t_far, ray_t, root)) return false;

    rec.t = root;
    // Project the point back onto the sphere: p then lies within a few ulps of the surface
    // whatever the distance travelled, which keeps the spawn offset small.
    vec3 from_center = r.at(root) - center;
    real distance    = from_center.length();
    // A sphere smaller than the rounding of its own position (radius far below an ulp of its
    // center) can put the hit exactly at its center: 0/0. Its normal then faces the ray, so no
    // NaN reaches a pixel.
    vec3 outward_normal = distance > 0 ? from_center / distance : -unit_vector(r.direction());
    rec.p               = center + radius * outward_normal;
    rec.p_error         = sphere_error_scale * (radius + max_abs_component(rec.p));
    rec.set_face_normal(r, outward_normal);
    rec.local = outward_normal;  // [ch08] what the texture coordinates come from
    return true;
}

sphere::sphere(const point3& center, real radius) : center_(center), radius_(radius) {
    require_positive(radius, "sphere radius");
}

// [ch03 begin]
sphere::sphere(const point3& center, real radius, std::shared_ptr<material> m)
    : sphere(center, radius) {
    require_given(m, "sphere material");
    mat = std::move(m);
}
// [ch03 end]

bool sphere::hit(const ray& r, interval ray_t, hit_record& rec) const {
    if (!hit_sphere(center_, radius_, r, ray_t, rec)) return false;
    rec.mat    = mat.get();  // [ch03]
    rec.object = this;       // [ch08]
    return true;
}

// [ch12 begin]
// What hit() would find over interval::universe() and then after that hit, from one quadratic
// instead of two, and no hit records: the same two numbers, bit for bit.
bool sphere::crossing(const ray& r, interval& inside) const {
    return solve_sphere_quadratic(center_, radius_, r, [&](real a, real b, real c, real a2_disc) {
        real t_near = 0, t_far = 0, entry = 0, exit = 0;
        sphere_roots(a, b, c, a2_disc, t_near, t_far);
        if (!first_root_inside(t_near, t_far, interval::universe(), entry)) return false;
        if (!first_root_inside(t_near, t_far, interval(entry, infinity), exit)) return false;
        inside = interval(entry, exit);
        return true;
    });
}
// [ch12 end]

// [ch08 begin]
surface_uv sphere::uv_from_normal(const vec3& n) {
    // [exercise sphere::uv_from_normal begin]
    real theta = std::acos(std::clamp(-n.y(), real(-1), real(1)));
    real phi   = std::atan2(-n.z(), n.x()) + pi;
    return {phi / (2 * pi), theta / pi};
    // [exercise sphere::uv_from_normal end]
}
// [ch08 end]

}  // namespace rt
