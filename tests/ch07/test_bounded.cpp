// Tests for bounded.h (chapter 07): the boxes a BVH is built from. A sphere's box is center -+
// radius; a quad's is the box of its four corners, padded where flat; a moving sphere's holds
// both ends; a bvh's is the union of its objects' boxes. A bounded_object made from any of them
// carries that box and the object itself, and refuses a missing object.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "ch03/material_helpers.h"
#include "common/bounded.h"
#include "common/bvh.h"
#include "common/error.h"
#include "common/moving_sphere.h"
#include "common/quad.h"
#include "common/sphere.h"

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
    CHECK(from_floor.box.x.min == 1);
    CHECK(from_floor.box.x.max == 3);
    CHECK(from_floor.box.y.min == -2);
    CHECK(from_floor.box.y.max == 2);
    CHECK(from_floor.box.z.surrounds(3));  // flat: padded around its plane

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

TEST_CASE("bounded: a quad's box is the box of its four corners, padded where flat", "[ch07]") {
    // The floor quad in z = 3: x in [1, 3], y in [-2, 2], and z padded to 1e-4 around 3 (so
    // the slab test can hit it from any side; see test_aabb).
    const aabb box = rt::bounding_box(rt::quad(corner, edge_u, edge_v, any_material()));
    CHECK(box.x.min == 1);
    CHECK(box.x.max == 3);
    CHECK(box.y.min == -2);
    CHECK(box.y.max == 2);
    CHECK(box.z.min < 3);
    CHECK(box.z.max > 3);
    CHECK(box.z.size() >= real(1e-4) - 8 * eps);  // the minimum, up to rounding around 3
    CHECK(box.z.size() < real(2e-4));

    // A tilted quad whose corners are extreme on different axes: Q, Q+u, Q+v, Q+u+v each hold
    // some bound, so a box of Q and Q+u+v alone would miss some. u = (1, 2, -0.5),
    // v = (-0.5, 0.25, 1.5) from Q = (-3, 1.5, 2): corners (-3, 1.5, 2), (-2, 3.5, 1.5),
    // (-3.5, 1.75, 3.5), (-2.5, 3.75, 3); all exact.
    const aabb tilted = rt::bounding_box(
        rt::quad(point3(-3, 1.5, 2), vec3(1, 2, -0.5), vec3(-0.5, 0.25, 1.5), any_material()));
    CHECK(tilted.x.min == -3.5);
    CHECK(tilted.x.max == -2);
    CHECK(tilted.y.min == 1.5);
    CHECK(tilted.y.max == 3.75);
    CHECK(tilted.z.min == 1.5);
    CHECK(tilted.z.max == 3.5);
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

    // A moving sphere (both ends count), a quad in y = -4 (padded), and an empty bvh, which
    // adds nothing.
    list.push_back(
        std::make_shared<rt::moving_sphere>(point3(-2, 0, 0), point3(-2, 0, 6), 1, any_material()));
    list.push_back(
        std::make_shared<rt::quad>(point3(0, -4, 0), vec3(5, 0, 0), vec3(0, 0, 2), any_material()));
    list.push_back(std::make_shared<rt::bvh>(objects{}));
    box = rt::bvh(list).bounding_box();
    CHECK(box.x.min == -3);
    CHECK(box.x.max == 5);
    CHECK(box.y.min < -4);  // the quad's padding, a fraction of 1e-4
    CHECK(box.y.min > -4 - real(1e-4));
    CHECK(box.y.max == 2.5);
    CHECK(box.z.min == -1);
    CHECK(box.z.max == 7);

    // A bvh inside a bvh gives the same box.
    const rt::bvh outer(objects{std::make_shared<rt::bvh>(list)});
    CHECK(same_box(outer.bounding_box(), box));
}
