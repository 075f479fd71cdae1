#include "constant_medium.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "error.h"
#include "isotropic.h"
#include "rng.h"
#include "validate.h"

namespace rt {

constant_medium::constant_medium(std::shared_ptr<hittable> b, real density, const color& albedo)
    : constant_medium(std::move(b), density, std::make_shared<solid_color>(albedo)) {
    require_reflectance(albedo, "medium albedo");
}

constant_medium::constant_medium(std::shared_ptr<hittable> b, real density,
                                 std::shared_ptr<texture> albedo)
    : boundary(std::move(b)),
      neg_inv_density(-1 / density),
      phase_function(std::make_shared<isotropic>(std::move(albedo))) {
    if (!boundary) throw user_error("constant_medium needs a boundary");
    if (!(density > 0) || !std::isfinite(density)) {
        std::ostringstream message;
        message << "medium density must be positive and finite, got " << density;
        throw user_error(message.str());
    }
    aabb box = boundary->bounding_box();
    id       = hash_values(bits_of(density),
                           hash_values(bits_of(box.x.min), bits_of(box.y.min), bits_of(box.z.min)),
                           hash_values(bits_of(box.x.max), bits_of(box.y.max), bits_of(box.z.max)));
}

bool constant_medium::hit(const ray& r, interval ray_t, hit_record& rec) const {
    hit_record entry, exit;
    if (!boundary->hit(r, interval::universe(), entry)) return false;
    if (!boundary->hit(r, interval(entry.t, infinity), exit)) return false;

    // Nothing behind the ray's origin counts, whatever interval the caller passes.
    real t_in  = std::fmax(entry.t, std::fmax(ray_t.min, real(0)));
    real t_out = std::fmin(exit.t, ray_t.max);
    if (!(t_in < t_out)) return false;

    const real speed  = r.direction().length();
    const real inside = (t_out - t_in) * speed;
    // xi in (0, 1]: the top 53 (or 24) bits of the hash; never 0, so the log stays finite.
    const std::uint64_t h = hash_values(r.random_key(), id, 0);
    const real xi         = (real(h >> (64 - std::numeric_limits<real>::digits)) + 1) *
                    std::ldexp(real(1), -std::numeric_limits<real>::digits);
    const real distance = neg_inv_density * std::log(xi);
    if (distance > inside) return false;

    rec.t          = t_in + distance / speed;
    rec.p          = r.at(rec.t);
    rec.normal     = vec3(1, 0, 0);  // arbitrary: a medium has no surface
    rec.front_face = true;
    rec.u = rec.v = 0;
    rec.p_error   = 0;
    rec.mat       = phase_function.get();
    return true;
}

}  // namespace rt
