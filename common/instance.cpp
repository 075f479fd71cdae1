#include "instance.h"

#include <cmath>

#include "error.h"
#include "rng.h"

namespace rt {

namespace {

// The ray inside an instance: its frame, and a key of its own. Mixing (not just xoring) keeps
// two nested placements with the same salt from cancelling back to the outer key.
ray inside(const ray& r, const point3& origin, const vec3& direction, std::uint64_t salt) {
    ray local(origin, direction, r.time());
    local.set_random_key(mix_bits(r.random_key() ^ salt));
    return local;
}

}  // namespace

translate::translate(std::shared_ptr<hittable> obj, const vec3& displacement)
    : object(std::move(obj)), offset(displacement) {
    if (!object) throw user_error("translate needs an object");
    aabb b = object->bounding_box();
    box    = aabb(interval(b.x.min + offset.x(), b.x.max + offset.x()),
                  interval(b.y.min + offset.y(), b.y.max + offset.y()),
                  interval(b.z.min + offset.z(), b.z.max + offset.z()));
    salt   = hash_values(bits_of(offset.x()), bits_of(offset.y()), bits_of(offset.z()));
}

bool translate::hit(const ray& r, interval ray_t, hit_record& rec) const {
    if (!object->hit(inside(r, r.origin() - offset, r.direction(), salt), ray_t, rec)) return false;
    rec.p += offset;
    // Adding the offset rounds p once more, by up to half an ulp of its new size.
    rec.p_error += spawn_offset_scale * max_abs_component(rec.p);
    return true;
}

rotate::rotate(std::shared_ptr<hittable> obj, axis about, real degrees) : object(std::move(obj)) {
    if (!object) throw user_error("rotate needs an object");
    if (!std::isfinite(degrees)) throw user_error("rotation angle must be finite");
    // For a rotation about axis k, coordinates a -> b turn like x -> y about z.
    a            = about == axis::x ? 1 : (about == axis::y ? 2 : 0);
    b            = about == axis::x ? 2 : (about == axis::y ? 0 : 1);
    real radians = degrees_to_radians(degrees);
    sin_theta    = std::sin(radians);
    cos_theta    = std::cos(radians);
    // The axis goes in too: equal turns about different axes are different placements.
    salt = hash_values(bits_of(sin_theta), bits_of(cos_theta), std::uint64_t(a));

    // The world box: the box of the object's box's eight corners, turned.
    aabb ob = object->bounding_box();
    for (int i = 0; i < 8; ++i) {
        point3 corner(i & 1 ? ob.x.max : ob.x.min, i & 2 ? ob.y.max : ob.y.min,
                      i & 4 ? ob.z.max : ob.z.min);
        point3 turned = to_world(corner);
        box           = aabb(box, aabb(turned, turned));
    }
}

vec3 rotate::turn(const vec3& v, real sin_angle) const {
    vec3 out = v;
    out[a]   = cos_theta * v[a] - sin_angle * v[b];
    out[b]   = sin_angle * v[a] + cos_theta * v[b];
    return out;
}

bool rotate::hit(const ray& r, interval ray_t, hit_record& rec) const {
    if (!object->hit(inside(r, to_object(r.origin()), to_object(r.direction()), salt), ray_t, rec))
        return false;
    rec.p      = to_world(rec.p);
    rec.normal = to_world(rec.normal);
    // Turning p rounds it again: a few ulps of its size (two products and a sum per coordinate).
    rec.p_error += spawn_offset_scale * max_abs_component(rec.p);
    return true;
}

}  // namespace rt
