// Tests for hittable::transmittance (chapter 14): the fraction of light that travels along a ray
// through ray_t unscattered. A medium of density rho crossed for a length L passes exp(-rho L)
// (whatever the length of the ray's direction, for a ray that starts inside, and only for the
// part within ray_t); a surface in the way passes nothing; a list or a BVH passes the product of
// its parts; translate and rotate ask the object in its own frame. And it is exactly the
// probability that constant_medium::hit lets a ray through: over many random rays, the fraction
// that pass matches the mean transmittance within 5 standard errors (statistics.h).
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>
#include <vector>

#include "ch03/material_helpers.h"
#include "rt/accel/bvh.h"
#include "rt/geometry/box.h"
#include "rt/geometry/instance.h"
#include "rt/geometry/quad.h"
#include "rt/geometry/sphere.h"
#include "rt/media/constant_medium.h"
#include "rt/scene/hittable_list.h"
#include "statistics.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::point3, rt::real, rt::vec3;
using rt_test::any_material;

const rt::interval forward(0, rt::infinity);
constexpr real rho = real(0.7);

// A medium filling the box [lo, hi].
std::shared_ptr<rt::constant_medium> medium(const point3& lo, const point3& hi, real density) {
    return std::make_shared<rt::constant_medium>(rt::box(lo, hi, any_material()), density,
                                                 color(0.5, 0.5, 0.5));
}

// The 2 x 2 x 2 cube [0, 2]^3.
std::shared_ptr<rt::constant_medium> cube(real density = rho) {
    return medium(point3(0, 0, 0), point3(2, 2, 2), density);
}

// exp(-rho L): the tolerance is a few ulps of t in a float build, where the crossing points are
// rounded; any wrong factor (a density, the speed of the ray) is far outside it.
Approx passes(double density, double length) {
    return Approx(std::exp(-density * length)).epsilon(1e-5);
}

}  // namespace

TEST_CASE("transmittance: a medium passes exp(-density * length inside)", "[ch14]") {
    auto m = cube();
    // Straight through, with a direction of length 3: the length inside is 2, not 2/3 or 6.
    CHECK(m->transmittance(rt::ray(point3(-1, 1, 1), vec3(3, 0, 0)), forward) == passes(rho, 2));
    // Obliquely: in through x = 0 at t = 1, out through x = 2 at t = 3.
    const vec3 d(1, 0.2, 0.1);
    CHECK(m->transmittance(rt::ray(point3(-1, 0.5, 0.7), d), forward) ==
          passes(rho, 2 * std::sqrt(1.05)));
    // From inside: only what lies ahead.
    CHECK(m->transmittance(rt::ray(point3(0.5, 1, 1), vec3(1, 0, 0)), forward) == passes(rho, 1.5));
    CHECK(m->transmittance(rt::ray(point3(0.5, 1, 1), vec3(0, 0, -0.25)), forward) ==
          passes(rho, 1));
    // A density of 3.5 passes exp(-7).
    CHECK(cube(real(3.5))->transmittance(rt::ray(point3(1, -4, 1), vec3(0, 2, 0)), forward) ==
          passes(3.5, 2));
}

TEST_CASE("transmittance: only the part of the ray within ray_t counts", "[ch14]") {
    auto m = cube();
    const rt::ray r(point3(-1, 1, 1), vec3(1, 0, 0));  // inside for 1 < t < 3
    CHECK(m->transmittance(r, rt::interval(0, real(2.2))) == passes(rho, 1.2));
    CHECK(m->transmittance(r, rt::interval(real(1.5), 10)) == passes(rho, 1.5));
    CHECK(m->transmittance(r, rt::interval(real(1.25), real(1.75))) == passes(rho, 0.5));
    // Before it, after it, away from it, beside it: everything passes.
    CHECK(m->transmittance(r, rt::interval(0, real(0.5))) == 1);
    CHECK(m->transmittance(r, rt::interval(4, 10)) == 1);
    CHECK(m->transmittance(rt::ray(point3(-1, 1, 1), vec3(-1, 0, 0)), forward) == 1);
    CHECK(m->transmittance(rt::ray(point3(-1, 5, 1), vec3(1, 0, 0)), forward) == 1);
    // Nothing behind the origin counts, whatever interval is passed.
    CHECK(m->transmittance(rt::ray(point3(1.5, 1, 1), vec3(1, 0, 0)), rt::interval(-10, 10)) ==
          passes(rho, 0.5));
}

TEST_CASE("transmittance: a surface in the way passes nothing", "[ch14]") {
    auto ball = std::make_shared<rt::sphere>(point3(5, 1, 1), 1, any_material());
    auto wall =
        std::make_shared<rt::quad>(point3(8, -1, -1), vec3(0, 4, 0), vec3(0, 0, 4), any_material());
    const rt::ray r(point3(-1, 1, 1), vec3(1, 0, 0));
    CHECK(ball->transmittance(r, forward) == 0);
    CHECK(ball->transmittance(r, rt::interval(0, 3)) == 1);  // it lies beyond ray_t
    CHECK(ball->transmittance(rt::ray(point3(-1, 5, 1), vec3(1, 0, 0)), forward) == 1);
    CHECK(wall->transmittance(r, forward) == 0);
    CHECK(wall->transmittance(r, rt::interval(0, 8)) == 1);

    rt::hittable_list list;
    list.add(cube());
    list.add(ball);
    CHECK(list.transmittance(r, forward) == 0);
    CHECK(list.transmittance(r, rt::interval(0, 3.5)) == passes(rho, 2));
    // An empty list passes everything.
    CHECK(rt::hittable_list().transmittance(r, forward) == 1);
}

TEST_CASE("transmittance: lists and BVHs multiply what their parts pass", "[ch14]") {
    // Two media along the x axis and a third overlapping the first, a ball off the path.
    auto first   = cube(real(0.7));
    auto second  = medium(point3(4, 0, 0), point3(5, 2, 2), real(1.3));
    auto overlap = medium(point3(1, 0.5, 0.5), point3(4.5, 1.5, 1.5), real(0.2));
    auto aside   = std::make_shared<rt::sphere>(point3(3, 8, 1), 1, any_material());
    auto blocker = std::make_shared<rt::sphere>(point3(7, 1, 1), real(0.5), any_material());
    const rt::ray r(point3(-1, 1, 1), vec3(2, 0, 0));
    const double expected = std::exp(-0.7 * 2 - 1.3 * 1 - 0.2 * 3.5);

    rt::hittable_list list;
    for (auto& part : std::vector<std::shared_ptr<rt::hittable>>{first, second, overlap, aside})
        list.add(part);
    CHECK(list.transmittance(r, forward) == Approx(expected).epsilon(1e-5));

    rt::bvh tree(std::vector<rt::bounded_object>{first, second, overlap, aside});
    CHECK(tree.transmittance(r, forward) == Approx(expected).epsilon(1e-5));
    // A limit inside the second medium: half of it.
    CHECK(tree.transmittance(r, rt::interval(0, real(2.75))) ==
          Approx(std::exp(-0.7 * 2 - 1.3 * 0.5 - 0.2 * 3.5)).epsilon(1e-5));

    // A blocker anywhere along the ray, in front of or behind the media in the tree: 0.
    rt::bvh blocked(std::vector<rt::bounded_object>{first, second, overlap, aside, blocker});
    CHECK(blocked.transmittance(r, forward) == 0);
    CHECK(blocked.transmittance(rt::ray(point3(10, 1, 1), vec3(-1, 0, 0)), forward) == 0);
    // ... but not when it lies beyond ray_t.
    CHECK(blocked.transmittance(r, rt::interval(0, 3)) == Approx(expected).epsilon(1e-5));
    // A BVH nested in a list.
    rt::hittable_list outer;
    outer.add(std::make_shared<rt::bvh>(std::vector<rt::bounded_object>{first, second}));
    outer.add(overlap);
    CHECK(outer.transmittance(r, forward) == Approx(expected).epsilon(1e-5));
}

TEST_CASE("transmittance: translate and rotate ask the medium in its own frame", "[ch14]") {
    rt::translate moved(cube(), vec3(10, 0, 0));
    CHECK(moved.transmittance(rt::ray(point3(5, 1, 1), vec3(1, 0, 0)), forward) == passes(rho, 2));
    CHECK(moved.transmittance(rt::ray(point3(5, 1, 1), vec3(1, 0, 0)), rt::interval(0, 6)) ==
          passes(rho, 1));
    CHECK(moved.transmittance(rt::ray(point3(-1, 1, 1), vec3(1, 0, 0)), rt::interval(0, 4)) == 1);

    // The cube [-1, 1]^3 turned 45 degrees about y: in the xz plane a diamond |x| + |z| <=
    // sqrt(2), which a ray along x at height z crosses for 2 (sqrt(2) - |z|). (Not at z = 0:
    // that ray runs through the diamond's corners, the edges of the box, where a hit is a
    // matter of rounding.)
    rt::rotate turned(medium(point3(-1, -1, -1), point3(1, 1, 1), rho), rt::axis::y, 45);
    CHECK(turned.transmittance(rt::ray(point3(-5, 0.3, 0.2), vec3(1, 0, 0)), forward) ==
          passes(rho, 2 * (std::sqrt(2.0) - 0.2)));
    // Nearer its corner, at z = 1.2, beyond where the unturned cube would end.
    CHECK(turned.transmittance(rt::ray(point3(-5, 0.3, 1.2), vec3(1, 0, 0)), forward) ==
          passes(rho, 2 * (std::sqrt(2.0) - 1.2)));
    // A surface inside an instance still blocks.
    rt::translate moved_ball(std::make_shared<rt::sphere>(point3(0, 0, 0), 1, any_material()),
                             vec3(0, 5, 0));
    CHECK(moved_ball.transmittance(rt::ray(point3(-3, 5, 0), vec3(1, 0, 0)), forward) == 0);
    CHECK(moved_ball.transmittance(rt::ray(point3(-3, 0, 0), vec3(1, 0, 0)), forward) == 1);
}

TEST_CASE("transmittance: is the probability that the media let a random ray through", "[ch14]") {
    // For each random ray (through, from inside, and clipped by ray_t), the indicator "hit()
    // found no scattering" minus transmittance() has mean 0; over 100000 rays the mean must be
    // within 5 standard errors of it. Two media overlap, so the list's product is checked too
    // (each medium draws its own number).
    auto a = cube(real(0.6));
    auto b = medium(point3(1, -0.5, 0.5), point3(3, 1.5, 2.5), real(0.9));
    rt::hittable_list both;
    both.add(a);
    both.add(b);
    rt::pcg32 rng(91, 5);
    rt_test::running_mean single, pair;
    long long passed = 0;
    for (int k = 0; k < 100000; ++k) {
        point3 origin;
        rt::interval ray_t = forward;
        if (k % 3 == 0) {
            origin = point3(1, 1, 1) + 6 * rt_test::random_unit(rng);  // outside
        } else {
            origin = point3(rt_test::uniform(rng, 0, 2), rt_test::uniform(rng, 0, 2),
                            rt_test::uniform(rng, 0, 2));  // inside
        }
        const point3 target(rt_test::uniform(rng, 0, 2), rt_test::uniform(rng, 0, 2),
                            rt_test::uniform(rng, 0, 2));
        const vec3 d = rt_test::uniform(rng, real(0.5), 2) * (target - origin);
        if (k % 3 == 2) ray_t = rt::interval(0, rt_test::uniform(rng, real(0.5), 3));
        const rt::ray r(origin, d);
        rt::hit_record rec;
        const bool through = !a->hit(r, ray_t, rec);
        passed += through;
        single.add(double(through) - double(a->transmittance(r, ray_t)));
        pair.add(double(!both.hit(r, ray_t, rec)) - double(both.transmittance(r, ray_t)));
    }
    INFO(passed << " of 100000 rays passed the cube");
    auto one = rt_test::mean_within_tolerance(single.estimate(), 0, 5);
    auto two = rt_test::mean_within_tolerance(pair.estimate(), 0, 5);
    INFO(one.summary);
    INFO(two.summary);
    CHECK(one.passed);
    CHECK(two.passed);
}
