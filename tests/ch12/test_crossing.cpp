// Tests for hittable::crossing (hittable.h, chapter 12): the stretch of a ray inside a medium's
// boundary. The default asks hit() twice (the nearest hit at any t, then the next one after it);
// a sphere solves one quadratic for both, and an instance hands the question to its object.
// Renders must not change by that shortcut, so every answer is compared bit for bit with the
// default's, called on the same object: over random spheres of every scale, rays from outside,
// from inside, from the surface, aimed through the center, tangent, missing, and of any length.
#include <catch2/catch.hpp>
#include <iomanip>
#include <memory>
#include <sstream>
#include <string>

#include "ch03/material_helpers.h"
#include "rt/geometry/box.h"
#include "rt/geometry/instance.h"
#include "rt/geometry/sphere.h"
#include "test_helpers.h"

namespace {

using rt::point3, rt::real, rt::vec3;
using rt_test::any_material, rt_test::log_uniform, rt_test::random_in_cube, rt_test::random_unit;

// How object's own crossing() and the default's two hit() calls disagree ("" when they agree
// exactly: the same answer and, when there is a stretch, the same two numbers).
std::string mismatch(const rt::hittable& object, const rt::ray& r) {
    rt::interval fast(-1, -2), slow(-1, -2);
    const bool fast_found = object.crossing(r, fast);
    const bool slow_found = object.hittable::crossing(r, slow);
    if (fast_found == slow_found && (!fast_found || (fast.min == slow.min && fast.max == slow.max)))
        return "";
    std::ostringstream why;
    why << std::setprecision(17) << "crossing " << fast_found << " [" << fast.min << ", "
        << fast.max << "], two hits " << slow_found << " [" << slow.min << ", " << slow.max << "]";
    return why.str();
}

// A ray towards or near a sphere (center, radius) of one of the kinds listed above.
rt::ray ray_near_sphere(rt::pcg32& rng, const point3& center, real radius, int kind) {
    const real length = log_uniform(rng, -3, 3);  // directions need not be unit
    const vec3 toward = random_unit(rng);
    switch (kind) {
        case 0:  // from outside, anywhere around
            return rt::ray(center + random_in_cube(rng, 4 * radius), length * toward);
        case 1:  // from inside
            return rt::ray(center + random_in_cube(rng, radius / 2), length * toward);
        case 2:  // from the surface
            return rt::ray(center + radius * random_unit(rng), length * toward);
        case 3: {  // through the center, from far away
            const point3 origin = center + 10 * radius * random_unit(rng);
            return rt::ray(origin, length * (center - origin));
        }
        default: {  // tangent: along the tangent plane at a point of the surface
            const vec3 n = random_unit(rng);
            return rt::ray(center + radius * n - 3 * radius * rt_test::random_tangent(rng, n),
                           length * rt_test::random_tangent(rng, n));
        }
    }
}

}  // namespace

TEST_CASE("crossing: a sphere's one quadratic gives the two hits' numbers bit for bit",
          "[crossing][hardcase][ch12]") {
    rt::pcg32 rng(1201, 7);
    int stretches = 0, none = 0;
    for (int i = 0; i < 20000; ++i) {
        const real radius   = log_uniform(rng, -3, 3);
        const point3 center = random_in_cube(rng, log_uniform(rng, -2, 4));
        const rt::sphere ball(center, radius, any_material());
        const rt::ray r = ray_near_sphere(rng, center, radius, i % 5);
        INFO("ray " << i << ", radius " << radius << ", kind " << i % 5);
        REQUIRE(mismatch(ball, r) == "");
        rt::interval inside;
        (ball.crossing(r, inside) ? stretches : none) += 1;
    }
    // Both answers come up often, so the comparison covers both.
    CHECK(stretches > 5000);
    CHECK(none > 1000);
}

TEST_CASE("crossing: instances hand the question to their object, in its own frame",
          "[crossing][ch12]") {
    rt::pcg32 rng(1202, 7);
    auto ball    = std::make_shared<rt::sphere>(point3(1, 2, 3), 2.5, any_material());
    auto turned  = std::make_shared<rt::rotate>(ball, rt::axis::y, 37);
    auto placed  = std::make_shared<rt::translate>(turned, vec3(-40, 5, 12));
    auto box     = rt::box(point3(0, 0, 0), point3(165, 330, 165), any_material());
    auto box_set = std::make_shared<rt::translate>(
        std::make_shared<rt::rotate>(box, rt::axis::y, 15), vec3(265, 0, 295));
    const point3 ball_center = placed->bounding_box().centroid();
    const point3 box_center  = box_set->bounding_box().centroid();
    int stretches            = 0;
    for (int i = 0; i < 4000; ++i) {
        const rt::ray near_ball = ray_near_sphere(rng, ball_center, 2.5, i % 5);
        INFO("ray " << i);
        REQUIRE(mismatch(*placed, near_ball) == "");
        const rt::ray near_box = ray_near_sphere(rng, box_center, 200, i % 4);
        REQUIRE(mismatch(*box_set, near_box) == "");
        rt::interval inside;
        stretches += placed->crossing(near_ball, inside) ? 1 : 0;
    }
    CHECK(stretches > 1000);
}

TEST_CASE("crossing: exact tangents, rays from the surface and rays of no length",
          "[crossing][hardcase][ch12]") {
    // Radii and offsets that are powers of two make the discriminant exactly 0: both roots are
    // one number, so there is no second hit after the first, and no stretch.
    for (real radius : {real(0.125), real(1), real(64)}) {
        const rt::sphere ball(point3(0, 0, 0), radius, any_material());
        for (real direction_length : {real(0.5), real(1), real(4)}) {
            const rt::ray tangent(point3(-4 * radius, radius, 0), vec3(direction_length, 0, 0));
            INFO("radius " << radius << ", direction length " << direction_length);
            rt::interval inside;
            CHECK_FALSE(ball.crossing(tangent, inside));
            CHECK(mismatch(ball, tangent) == "");
            // Leaving the surface straight out: the entry is the origin itself, behind nothing.
            const rt::ray leaving(point3(radius, 0, 0), vec3(direction_length, 0, 0));
            CHECK(mismatch(ball, leaving) == "");
        }
    }
    // No direction: no quadratic (0/0), no stretch, and no NaN in the answer.
    const rt::sphere ball(point3(1, 2, 3), 2, any_material());
    const rt::ray still(point3(1, 2, 3), vec3(0, 0, 0));
    rt::interval inside(-1, -2);
    CHECK_FALSE(ball.crossing(still, inside));
    CHECK(inside.min == -1);
    CHECK(mismatch(ball, still) == "");
}
