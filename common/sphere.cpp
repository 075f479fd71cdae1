#include "sphere.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "error.h"

namespace rt {

sphere::sphere(const point3& center, real radius, std::shared_ptr<material> m)
    : sphere(center, center, radius, std::move(m)) {}

sphere::sphere(const point3& c0, const point3& c1, real radius, std::shared_ptr<material> m)
    : center0(c0),
      center1(c1),
      velocity(c1 - c0),
      is_moving(!(c0.x() == c1.x() && c0.y() == c1.y() && c0.z() == c1.z())),
      radius_(radius),
      mat(std::move(m)) {
    if (!(radius > 0) || !std::isfinite(radius)) {
        std::ostringstream message;
        message << "sphere radius must be positive and finite, got " << radius;
        throw user_error(message.str());
    }
    if (!mat) throw user_error("sphere needs a material");
    needs_uv = mat->uses_uv();
}

bool sphere::hit(const ray& r, interval ray_t, hit_record& rec) const {
    // With f = A - C: a t^2 + 2 b t + c = 0, a = b.b, b = f.b, c = f.f - r^2.
    const vec3& d = r.direction();
    // Static spheres (most of them) skip the motion: the branch is predictable in any list.
    point3 center = is_moving ? center_at(r.time()) : center0;
    vec3 f        = r.origin() - center;
    real a        = dot(d, d);
    real b        = dot(f, d);
    real c        = dot(f, f) - radius_ * radius_;

    // Most spheres of a big list are clearly missed. The textbook discriminant b^2 - a c says so
    // cheaply, but it cancels badly (distant or grazing spheres); trust its "miss" only when it
    // is below minus its own rounding-error bound.
    real bb = b * b, ac = a * c;
    if (bb - ac < -8 * std::numeric_limits<real>::epsilon() * (bb + std::fabs(ac))) return false;

    // b^2 - a c = a (r^2 - |f_perp|^2), where f_perp = f - (b/a) d is f minus its part along the
    // ray: this form avoids subtracting two huge, nearly equal numbers. Scaled by a^2
    // (g = a f_perp) so that it needs no division.
    vec3 g               = a * f - b * d;
    real a2_discriminant = radius_ * radius_ * a * a - dot(g, g);
    if (a2_discriminant < 0) return false;
    return record_hit(r, ray_t, rec, center, a, b, c, a2_discriminant);
}

// The rarer half of hit(), kept out of line so the common miss stays a short function.
bool sphere::record_hit(const ray& r, interval ray_t, hit_record& rec, const point3& center, real a,
                        real b, real c, real a2_discriminant) const {
    // Stable roots: q never cancels, since b and sign(b) sqrt(...) add with the same sign.
    // sqrt(b^2 - a c) = sqrt(a * discriminant) = sqrt(a2_discriminant / a).
    real q     = -(b + std::copysign(std::sqrt(a2_discriminant / a), b));
    real t_far = q / a;
    // q = 0 only for a ray that starts on the sphere and grazes it: both roots are then 0.
    real t_near = q != 0 ? c / q : t_far;
    if (t_near > t_far) std::swap(t_near, t_far);

    real root = t_near;
    if (!ray_t.surrounds(root)) {
        root = t_far;
        if (!ray_t.surrounds(root)) return false;
    }

    rec.t = root;
    // Project the point back onto the sphere: p then lies within a few ulps of the surface
    // whatever the distance travelled, which keeps the spawn offset small.
    vec3 from_center    = r.at(root) - center;
    vec3 outward_normal = from_center / from_center.length();
    rec.p               = center + radius_ * outward_normal;
    rec.p_error         = spawn_offset_scale * (max_abs_component(center) + radius_);
    rec.set_face_normal(r, outward_normal);
    if (needs_uv)
        uv_from_normal(outward_normal, rec.u, rec.v);
    else
        rec.u = rec.v = 0;
    rec.mat = mat.get();
    return true;
}

aabb sphere::bounding_box() const {
    vec3 extent(radius_, radius_, radius_);
    aabb at_start(center0 - extent, center0 + extent);
    return aabb(at_start, aabb(center1 - extent, center1 + extent));
}

void sphere::uv_from_normal(const vec3& n, real& u, real& v) {
    real theta = std::acos(std::clamp(-n.y(), real(-1), real(1)));
    real phi   = std::atan2(-n.z(), n.x()) + pi;
    u          = phi / (2 * pi);
    v          = theta / pi;
}

}  // namespace rt
