#include "rt/lights/rectangle_light.h"

#include <cmath>
#include <limits>

#include "rt/lights/spherical_rectangle.h"

namespace rt {

rectangle_light::rectangle_light(const quad& q)
    : quad_light(q),
      unit_normal(unit_vector(cross(q.edge_u(), q.edge_v()))),
      longer_edge(std::fmax(q.edge_u().length(), q.edge_v().length())) {}

bool rectangle_light::is_rectangle(const quad& q) {
    real lengths = q.edge_u().length() * q.edge_v().length();
    return lengths > 0 && std::fabs(dot(q.edge_u(), q.edge_v())) <=
                              64 * std::numeric_limits<real>::epsilon() * lengths;
}

std::unique_ptr<light> rectangle_light::make(const quad& q) {
    if (is_rectangle(q)) return std::make_unique<rectangle_light>(q);
    return std::make_unique<quad_light>(q);
}

bool rectangle_light::near(const point3& ref) const {
    return std::fabs(dot(ref - shape->corner(), unit_normal)) < near_share * longer_edge;
}

bool rectangle_light::sample(const point3& ref, sample2 u, light_sample& out) const {
    if (!near(ref)) return quad_light::sample(ref, u, out);
    spherical_rectangle seen(ref, shape->corner(), shape->edge_u(), shape->edge_v());
    if (!seen.by_solid_angle()) return quad_light::sample(ref, u, out);
    return aim_at(ref, seen.sample(u), out, 1 / seen.solid_angle());
}

real rectangle_light::pdf_at(const point3& ref, const vec3& wi, const hit_record& hit) const {
    // The same decision as sample() makes from the same ref: the two always agree.
    if (!near(ref)) return quad_light::pdf_at(ref, wi, hit);
    spherical_rectangle seen(ref, shape->corner(), shape->edge_u(), shape->edge_v());
    if (!seen.by_solid_angle()) return quad_light::pdf_at(ref, wi, hit);
    return 1 / seen.solid_angle();
}

}  // namespace rt
