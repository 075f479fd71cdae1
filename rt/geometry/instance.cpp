#include "rt/geometry/instance.h"

#include <cmath>
#include <limits>

#include "rt/core/exercise.h"
#include "rt/core/validate.h"

namespace rt {

translate::translate(const bounded_object& obj, const vec3& displacement)
    : object(obj.object), offset(displacement) {
    const aabb& b = obj.box;
    if (b.empty()) return;  // nothing to bound
    box = aabb(interval(b.x.min + offset.x(), b.x.max + offset.x()),
               interval(b.y.min + offset.y(), b.y.max + offset.y()),
               interval(b.z.min + offset.z(), b.z.max + offset.z()));
    // Each moved side is rounded to nearest, up to half an ulp inside the exact one, and hit()
    // moves the ray with the same rounding: a ray grazing the object's edge far from the origin
    // could miss the box yet hit the object. 4 eps of the box's magnitude covers both, at any
    // scale.
    box = box.widened(4 * std::numeric_limits<real>::epsilon() * box.magnitude());
}

bool translate::hit(const ray& r, interval ray_t, hit_record& rec) const {
    // [exercise translate::hit begin]
    if (!object->hit(r.continued(r.origin() - offset, r.direction()), ray_t, rec)) return false;
    rec.p += offset;
    // Adding the offset rounds p once more, by up to half an ulp of its new size.
    rec.p_error += spawn_offset_scale * max_abs_component(rec.p);
    return true;
    // [exercise translate::hit end]
}

rotate::rotate(const bounded_object& obj, axis turn_about, real degrees)
    : object(obj.object), about(turn_about), angle(degrees) {
    require(std::isfinite(degrees), "rotation angle", "be finite", degrees);
    real radians = degrees_to_radians(degrees);
    sin_theta    = std::sin(radians);
    cos_theta    = std::cos(radians);

    // The world box: the box of the object's box's eight corners, turned, then widened on every
    // side by 4 eps M, M the largest |coordinate| of those corners. Why: a turned coordinate
    // cos x - sin y is rounded three times (two products and a difference), off by at most
    // eps (|cos x| + |sin y|) <= sqrt(2) eps M, so a turned corner can land inside the exact
    // turned box, and a ray grazing the object's edge would miss the box yet hit the object.
    // 4 eps M covers that error and the rounding of the widening itself (half an ulp of
    // sqrt(2) M), with room for the turn of the ray in hit() (the same rounding, for an origin
    // about as far out as the object). The turn's own axis is copied exactly, but it is widened
    // too: hit() asks the object itself, not its box, and an object may answer a ray up to an
    // ulp or so outside its box (a quad rounds its (alpha, beta) before comparing them with 0
    // and 1). Relative to M, so the box stays tight at every scale and far from the origin.
    // [exercise rotate::rotate begin]
    const aabb& ob = obj.box;
    if (ob.empty()) return;  // nothing to bound (turning +-inf corners would make NaN)
    real largest = 0;
    for (int i = 0; i < 8; ++i) {
        point3 corner(i & 1 ? ob.x.max : ob.x.min, i & 2 ? ob.y.max : ob.y.min,
                      i & 4 ? ob.z.max : ob.z.min);
        point3 turned = to_world(corner);
        box           = aabb(box, aabb(turned, turned));
        largest       = std::fmax(largest, max_abs_component(corner));
    }
    box = box.widened(4 * std::numeric_limits<real>::epsilon() * largest);
    // [exercise rotate::rotate end]
}

vec3 rotate::turn(const vec3& v, real sin_angle) const {
    // The two coordinates (p, q) that turn go to (cos p - sin q, sin p + cos q), like x -> y
    // about z. Written out per axis rather than indexed by the axis at run time, which would
    // keep v in memory instead of registers (a Cornell box renders 3.6 % faster so).
    // [exercise rotate::turn begin]
    auto turned_p = [&](real p, real q) { return cos_theta * p - sin_angle * q; };
    auto turned_q = [&](real p, real q) { return sin_angle * p + cos_theta * q; };
    switch (about) {
        case axis::z:  // (p, q) = (x, y)
            return vec3(turned_p(v.x(), v.y()), turned_q(v.x(), v.y()), v.z());
        case axis::x:  // (y, z)
            return vec3(v.x(), turned_p(v.y(), v.z()), turned_q(v.y(), v.z()));
        case axis::y:  // (z, x)
            break;
    }
    return vec3(turned_q(v.z(), v.x()), v.y(), turned_p(v.z(), v.x()));
    // [exercise rotate::turn end]
}

bool rotate::hit(const ray& r, interval ray_t, hit_record& rec) const {
    // [exercise rotate::hit begin]
    if (!object->hit(r.continued(to_object(r.origin()), to_object(r.direction())), ray_t, rec))
        return false;
    rec.p      = to_world(rec.p);
    rec.normal = to_world(rec.normal);
    // Turning p rounds it again: a few ulps of its size (two products and a sum per coordinate).
    rec.p_error += spawn_offset_scale * max_abs_component(rec.p);
    return true;
    // [exercise rotate::hit end]
}

}  // namespace rt
