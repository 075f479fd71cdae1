// Tests for bounded.h (chapter 07): the boxes a BVH is built from. A sphere's box is center -+
// radius; a quad's is the box of its four corners, flat (zero thickness, not padded) when the
// quad lies in a coordinate plane, and hit by the rays the quad answers; a moving sphere's holds
// both ends; a bvh's is the union of its objects' boxes. A bounded_object made from any of them
// carries that box and the object itself, and refuses a missing object.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "ch03/material_helpers.h"
#include "rt/accel/bounded.h"
#include "rt/accel/bvh.h"
#include "rt/core/error.h"
#include "rt/core/rng.h"
#include "rt/geometry/moving_sphere.h"
#include "rt/geometry/quad.h"
#include "rt/geometry/sphere.h"

namespace {

using rt::aabb, rt::point3, rt::real, rt::vec3;
using rt_test::any_material;

constexpr real eps = std::numeric_limits<real>::epsilon();

// Whether two boxes have the same ends on every axis, bit for bit.
bool same_box(const aabb& a, const aabb& b) {
    for (int axis = 0; axis < 3; ++axis) {
        if (a.axis_interval(axis).min != b.axis_interval(axis).min ||
            a.axis_interval(axis).max != b.axis_interval(axis).max)
            return false;
    }
    return true;
}

// The quad Q + a u + b v in the plane z = 3: x in [1, 3], y in [-2, 2].
// A bound of a quad's box: at most 4 eps of the box's magnitude outside the exact corner value
// (bounded.cpp widens a quad's box by that much for its own rounding), never inside it.
bool widened_min(real got, real exact, real magnitude) {
    return got <= exact && got >= exact - 4 * eps * magnitude * (1 + 4 * eps);
}
bool widened_max(real got, real exact, real magnitude) {
    return got >= exact && got <= exact + 4 * eps * magnitude * (1 + 4 * eps);
}

const point3 corner(1, -2, 3);
const vec3 edge_u(2, 0, 0), edge_v(0, 4, 0);

}  // namespace

TEST_CASE(
    "bounded: a bounded_object carries its object and the box of a sphere, a quad, a "
    "moving sphere or a bvh",
    "[ch07]") {
    // Dyadic centers and radii: every end is exact.
    auto ball = std::make_shared<rt::sphere>(point3(1, 2, 3), 0.5, any_material());
    const rt::bounded_object from_ball = ball;
    CHECK(from_ball.object.get() == ball.get());
    CHECK(same_box(from_ball.box, aabb(point3(0.5, 1.5, 2.5), point3(1.5, 2.5, 3.5))));

    auto floor = std::make_shared<rt::quad>(corner, edge_u, edge_v, any_material());
    const rt::bounded_object from_floor = floor;
    CHECK(from_floor.object.get() == floor.get());
    CHECK(widened_min(from_floor.box.x.min, 1, 3));
    CHECK(widened_max(from_floor.box.x.max, 3, 3));
    CHECK(widened_min(from_floor.box.y.min, -2, 3));
    CHECK(widened_max(from_floor.box.y.max, 2, 3));
    CHECK(widened_min(from_floor.box.z.min, 3, 3));  // flat: its plane, a few ulps wide
    CHECK(widened_max(from_floor.box.z.max, 3, 3));

    // From (-2, 0, 0) at time 0 to (-2, 0, 6) at time 1: the box holds both ends.
    auto mover =
        std::make_shared<rt::moving_sphere>(point3(-2, 0, 0), point3(-2, 0, 6), 1, any_material());
    const rt::bounded_object from_mover = mover;
    CHECK(from_mover.object.get() == mover.get());
    CHECK(same_box(from_mover.box, aabb(point3(-3, -1, -1), point3(-1, 1, 7))));
    CHECK(same_box(from_mover.box, mover->bounding_box()));

    // A bvh of the three: the union, the same as the tree's own box.
    auto tree = std::make_shared<rt::bvh>(
        std::vector<rt::bounded_object>{from_ball, from_floor, from_mover});
    const rt::bounded_object from_tree = tree;
    CHECK(from_tree.object.get() == tree.get());
    CHECK(same_box(from_tree.box, tree->bounding_box()));
    CHECK(same_box(from_tree.box, aabb(aabb(from_ball.box, from_floor.box), from_mover.box)));
    CHECK(from_tree.box.x.min == -3);
    CHECK(from_tree.box.z.max == 7);

    // A missing object has no box: a user error, not a crash.
    CHECK_THROWS_AS(rt::bounded_object(std::shared_ptr<rt::sphere>()), rt::user_error);
    CHECK_THROWS_AS(rt::bounded_object(std::shared_ptr<rt::quad>()), rt::user_error);
    CHECK_THROWS_AS(rt::bounded_object(std::shared_ptr<rt::bvh>()), rt::user_error);
    CHECK_THROWS_WITH(rt::bounded_object(std::shared_ptr<rt::moving_sphere>()),
                      Catch::Contains("missing"));
}

TEST_CASE("bounded: a quad's box is the box of its four corners, flat where the quad is",
          "[ch07]") {
    // The floor quad in z = 3: x in [1, 3], y in [-2, 2], and z exactly 3: zero thickness (the
    // slab test hits it from any side without padding; see test_aabb).
    const aabb box = rt::bounding_box(rt::quad(corner, edge_u, edge_v, any_material()));
    CHECK(widened_min(box.x.min, 1, 3));
    CHECK(widened_max(box.x.max, 3, 3));
    CHECK(widened_min(box.y.min, -2, 3));
    CHECK(widened_max(box.y.max, 2, 3));
    CHECK(widened_min(box.z.min, 3, 3));
    CHECK(widened_max(box.z.max, 3, 3));
    CHECK(box.z.size() <= 8 * eps * 3 * (1 + 4 * eps));     // a few ulps thick, no absolute pad
    CHECK(box.half_area() == Approx(8).epsilon(64 * eps));  // its one face, 2 x 4, to the widening

    // A tilted quad whose corners are extreme on different axes: Q, Q+u, Q+v, Q+u+v each hold
    // some bound, so a box of Q and Q+u+v alone would miss some. u = (1, 2, -0.5),
    // v = (-0.5, 0.25, 1.5) from Q = (-3, 1.5, 2): corners (-3, 1.5, 2), (-2, 3.5, 1.5),
    // (-3.5, 1.75, 3.5), (-2.5, 3.75, 3); all exact.
    const aabb tilted = rt::bounding_box(
        rt::quad(point3(-3, 1.5, 2), vec3(1, 2, -0.5), vec3(-0.5, 0.25, 1.5), any_material()));
    CHECK(widened_min(tilted.x.min, -3.5, 3.75));
    CHECK(widened_max(tilted.x.max, -2, 3.75));
    CHECK(widened_min(tilted.y.min, 1.5, 3.75));
    CHECK(widened_max(tilted.y.max, 3.75, 3.75));
    CHECK(widened_min(tilted.z.min, 1.5, 3.75));
    CHECK(widened_max(tilted.z.max, 3.5, 3.75));
}

TEST_CASE("bounded: a bvh's box is the union of its objects' boxes, and a nested bvh's the same",
          "[ch07]") {
    using objects = std::vector<rt::bounded_object>;
    CHECK(rt::bvh(objects{}).bounding_box().empty());  // nothing to bound

    objects list{std::make_shared<rt::sphere>(point3(1, 2, 3), 0.5, any_material())};
    aabb box = rt::bvh(list).bounding_box();
    CHECK(box.x.min == 0.5);
    CHECK(box.x.max == 1.5);
    CHECK(box.z.max == 3.5);

    // A moving sphere (both ends count), a quad in y = -4 (flat), and an empty bvh, which adds
    // nothing.
    list.push_back(
        std::make_shared<rt::moving_sphere>(point3(-2, 0, 0), point3(-2, 0, 6), 1, any_material()));
    list.push_back(
        std::make_shared<rt::quad>(point3(0, -4, 0), vec3(5, 0, 0), vec3(0, 0, 2), any_material()));
    list.push_back(std::make_shared<rt::bvh>(objects{}));
    box = rt::bvh(list).bounding_box();
    CHECK(box.x.min == -3);
    CHECK(widened_max(box.x.max, 5, 5));   // the quad's corner, a few ulps out
    CHECK(widened_min(box.y.min, -4, 5));  // the quad's plane, not padded by an absolute amount
    CHECK(box.y.max == 2.5);
    CHECK(box.z.min == -1);
    CHECK(box.z.max == 7);

    // A bvh inside a bvh gives the same box.
    const rt::bvh outer(objects{std::make_shared<rt::bvh>(list)});
    CHECK(same_box(outer.bounding_box(), box));
}

TEST_CASE(
    "bounded: a flat quad's box is hit by every ray the quad answers, at scales 1e-4 to 1e4, "
    "far from the origin, from both sides and at grazing angles",
    "[hardcase][ch07]") {
    // Quads in the three coordinate planes, of size s = 1e-4 .. 1e4, at the origin or up to
    // 1e6 s from it (any sign), edges of either sign; their boxes are flat. Rays aimed at a point
    // 1% to 99% along each edge, from either side, at 90 degrees to the plane down to 1e-6
    // radians, from 0.01 s to 1e3 s away, some with a zero (or -0) component. The box, which has
    // no thickness to spare, must hit every ray the quad answers. (Within a few ulps of an edge
    // a quad, which rounds its (alpha, beta), may answer a ray that passes just outside its exact
    // box: those rays are for test_aabb's exact cases, not here.) A float holds less: quads up
    // to 1e2 s out, rays from at most 1e2 s and at least 0.01 radians to the plane.
    const bool is_double = std::numeric_limits<real>::digits >= 53;
    const real far_exp   = is_double ? 6 : 2;
    const real reach_exp = is_double ? 3 : 2;
    const real grazing   = is_double ? -6 : -2;
    rt::pcg32 rng(15, 3);
    auto uniform   = [&](real lo, real hi) { return lo + (hi - lo) * rng.uniform(); };
    long long rays = 0, quad_hits = 0, box_misses = 0, tmax_misses = 0;
    for (int i = 0; i < 100000; ++i) {
        const real s = std::pow(real(10), uniform(-4, 4));
        const int k = i % 3, a1 = (k + 1) % 3, a2 = (k + 2) % 3;
        point3 Q;
        const real far = i % 4 == 0 ? 0 : s * std::pow(real(10), uniform(0, far_exp));
        for (int a = 0; a < 3; ++a) Q[a] = far * uniform(-1, 1) + s * uniform(-1, 1);
        vec3 u(0, 0, 0), v(0, 0, 0);
        u[a1] = s * uniform(real(0.5), 2) * (rng.uniform() < 0.5 ? -1 : 1);
        v[a2] = s * uniform(real(0.5), 2) * (rng.uniform() < 0.5 ? -1 : 1);
        const rt::quad q(Q, u, v, any_material());
        const aabb box = rt::bounding_box(q);
        // Flat: its plane, widened only by ulps of the quad's own magnitude.
        REQUIRE(widened_min(box.axis_interval(k).min, Q[k], box.magnitude()));
        REQUIRE(widened_max(box.axis_interval(k).max, Q[k], box.magnitude()));

        const point3 target =
            Q + uniform(real(0.01), real(0.99)) * u + uniform(real(0.01), real(0.99)) * v;
        // A direction at `angle` to the plane, on either side, heading anywhere along it.
        const real angle   = std::pow(real(10), uniform(grazing, real(0.196)));
        const real heading = uniform(0, 2 * rt::pi);
        vec3 d;
        d[k]  = std::sin(angle) * (i % 2 == 0 ? 1 : -1);
        d[a1] = std::cos(angle) * std::cos(heading);
        d[a2] = std::cos(angle) * std::sin(heading);
        if (i % 7 == 0) d[a1] = i % 2 == 0 ? real(0) : -real(0);
        d *= std::pow(real(10), uniform(-2, 2));  // not unit length
        const point3 o =
            target - s * std::pow(real(10), uniform(-2, reach_exp)) * rt::unit_vector(d);
        const rt::ray r(o, d);
        ++rays;
        rt::hit_record rec;
        if (!q.hit(r, rt::interval(0, rt::infinity), rec)) continue;
        ++quad_hits;
        const vec3 inv_dir(1 / d.x(), 1 / d.y(), 1 / d.z());
        if (!box.hit(o, inv_dir, rt::interval(0, rt::infinity))) {
            if (++box_misses <= 5)
                UNSCOPED_INFO("box missed: quad " << Q << " + " << u << ", " << v << "; ray " << o
                                                  << " + t " << d << ", t = " << rec.t);
        }
        // Within an interval that ends at the quad's own t, the box is hit too, up to the quad's
        // rounding of t: its unit normal and D = n.Q are rounded, so its t = (D - n.o) / (n.d)
        // is off by a few ulps of (|Q_k| + |o_k|) / |d_k|, besides a few of t. (The book's
        // 1e-4 padding hid this, as long as 1e-4 was larger than that; the quad's box would
        // need a pad of a few ulps of |Q_k| to absorb it.)
        const real t_error =
            4 * eps * (rec.t + (std::fabs(Q[k]) + std::fabs(o[k])) / std::fabs(d[k]));
        if (!box.hit(o, inv_dir, rt::interval(0, rec.t + t_error))) ++tmax_misses;
    }
    INFO(quad_hits << " of " << rays << " rays answered by the quad; " << box_misses
                   << " of those missed by its box, " << tmax_misses
                   << " when ray_t ends at the quad's t");
    CHECK(quad_hits == rays);  // aimed well inside: every one hits
    CHECK(box_misses == 0);
    CHECK(tmax_misses == 0);
}
