// What the tests of quad lights share (chapter 14's quad_light, chapter 17's rectangle_light;
// included as "ch14/quad_checks.h"): a tilted lamp and the bins of directions that hold it.
#pragma once

#include <cmath>
#include <memory>

#include "ch14/light_checks.h"
#include "rt/geometry/quad.h"
#include "rt/materials/diffuse_light.h"

namespace rt_test::quad_checks {

using rt::point3, rt::real, rt::vec3;

// A tilted 2.5 x 2.15 lamp, well off every axis: its corners are at different distances from
// the points below, so d^2 and cos theta_light vary across it. Its edges are perpendicular (a
// rectangle, as chapter 17's lights by solid angle need).
inline std::shared_ptr<rt::quad> tilted_quad(const rt::color& radiance) {
    return std::make_shared<rt::quad>(point3(-1, 2, -1.5), vec3(2.5, 0, 0), vec3(0, 0.8, 2),
                                      std::make_shared<rt::diffuse_light>(radiance));
}

inline point3 center_of(const rt::quad& q) {
    return q.corner() + real(0.5) * q.edge_u() + real(0.5) * q.edge_v();
}

// Bins about the direction from ref to the quad's center, wide enough (1.25 times the largest
// 1 - cos theta of a corner) that the quad's whole outline lies inside them.
inline direction_checks::direction_bins bins_around(const rt::quad& q, const point3& ref) {
    direction_checks::direction_bins probe(center_of(q) - ref, 2, 1, 1);
    double widest = 0;
    for (int i = 0; i < 4; ++i) {
        point3 corner = q.corner() + real(i & 1) * q.edge_u() + real(i >> 1) * q.edge_v();
        widest        = std::fmax(widest, probe.x_of(corner - ref));
    }
    return direction_checks::direction_bins(center_of(q) - ref, std::fmin(2.0, 1.25 * widest), 12,
                                            16);
}

}  // namespace rt_test::quad_checks
