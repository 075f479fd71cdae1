#include "rt/media/constant_medium.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "rt/core/exercise.h"
#include "rt/core/rng.h"
#include "rt/core/validate.h"
#include "rt/media/isotropic.h"

namespace rt {

constant_medium::constant_medium(const bounded_object& b, real density, const color& albedo)
    : constant_medium(b, density, std::make_shared<solid_color>(albedo)) {
    require_reflectance(albedo, "medium albedo");
}

constant_medium::constant_medium(const bounded_object& b, real density,
                                 std::shared_ptr<texture> albedo)
    : boundary(b.object), box(b.box), neg_inv_density(-1 / density) {
    require_positive(density, "medium density");
    given_density  = density;  // [ch17]
    phase_function = std::make_shared<isotropic>(std::move(albedo));
    id             = hash_values(bits_of(density),
                                 hash_values(bits_of(box.x.min), bits_of(box.y.min), bits_of(box.z.min)),
                                 hash_values(bits_of(box.x.max), bits_of(box.y.max), bits_of(box.z.max)));
}

bool constant_medium::inside_stretch(const ray& r, interval ray_t, real& t_in, real& t_out) const {
    // [exercise constant_medium::inside_stretch begin]
    interval inside;
    if (!boundary->crossing(r, inside)) return false;

    // Nothing behind the ray's origin counts, whatever interval the caller passes.
    t_in  = std::fmax(inside.min, std::fmax(ray_t.min, real(0)));
    t_out = std::fmin(inside.max, ray_t.max);
    return t_in < t_out;
    // [exercise constant_medium::inside_stretch end]
}

bool constant_medium::hit(const ray& r, interval ray_t, hit_record& rec) const {
    // [exercise constant_medium::hit begin]
    real t_in = 0, t_out = 0;
    if (!inside_stretch(r, ray_t, t_in, t_out)) return false;

    const real speed    = r.direction().length();
    const real inside   = (t_out - t_in) * speed;
    const real distance = neg_inv_density * std::log(random_for(r));
    if (distance > inside) return false;

    rec.t          = t_in + distance / speed;
    rec.p          = r.at(rec.t);
    rec.normal     = vec3(1, 0, 0);  // arbitrary: a medium has no surface
    rec.front_face = true;
    rec.p_error    = 0;
    rec.mat        = phase_function.get();
    rec.object     = this;    // no surface: (u, v) = (0, 0)
    rec.local      = vec3();  // nor coordinates on one; a candidate's would otherwise remain
    return true;
    // [exercise constant_medium::hit end]
}

// [ch14 begin]
real constant_medium::transmittance(const ray& r, interval ray_t) const {
    real t_in = 0, t_out = 0;
    if (!inside_stretch(r, ray_t, t_in, t_out)) return 1;
    return std::exp((t_out - t_in) * r.direction().length() / neg_inv_density);
}
// [ch14 end]

real constant_medium::random_for(const ray& r) const {
    // [exercise constant_medium::random_for begin]
    const point3& o = r.origin();
    const vec3& d   = r.direction();
    std::uint64_t h = hash_values(hash_values(bits_of(o.x()), bits_of(o.y()), bits_of(o.z())),
                                  hash_values(bits_of(d.x()), bits_of(d.y()), bits_of(d.z())),
                                  hash_values(bits_of(r.time()), id, 0));
    // The top 53 (or 24) bits, plus one: in (0, 1], never 0, so the log stays finite.
    return (real(h >> (64 - std::numeric_limits<real>::digits)) + 1) *
           std::ldexp(real(1), -std::numeric_limits<real>::digits);
    // [exercise constant_medium::random_for end]
}

}  // namespace rt
