// Tests for bvh.h with chapter 08's surface coordinates: a hit names the shape that recorded it
// and its local point, from which (u, v) are computed later, for the nearest hit only. The BVH
// must leave exactly what the brute-force list leaves: the same object, the same local point
// bit for bit, so the same (u, v). Chapter 07's test_bvh compares the rest of the record.
#include <catch2/catch.hpp>
#include <memory>
#include <vector>

#include "ch03/material_helpers.h"
#include "rt/accel/bvh.h"
#include "rt/core/rng.h"
#include "rt/geometry/moving_sphere.h"
#include "rt/geometry/quad.h"
#include "rt/geometry/sphere.h"
#include "rt/scene/hittable_list.h"
#include "test_helpers.h"

namespace {

using rt::point3, rt::real, rt::vec3;

using rt_test::any_material, rt_test::exactly, rt_test::random_in_cube, rt_test::random_unit,
    rt_test::uniform;

}  // namespace

TEST_CASE(
    "bvh: the nearest hit names the same object and local point as the list, so the same "
    "(u, v)",
    "[ch08]") {
    // 300 spheres, moving spheres and quads in a 20-unit cube, overlapping often, so that many
    // rays hit several objects and only the nearest may leave its coordinates.
    rt::pcg32 rng(84, 5);
    std::vector<rt::bounded_object> objects;
    rt::hittable_list list;
    for (int i = 0; i < 300; ++i) {
        const point3 c    = random_in_cube(rng, 10);
        const real radius = uniform(rng, real(0.2), 2);
        if (i % 3 == 0) {
            const vec3 u = uniform(rng, real(0.5), 3) * random_unit(rng);
            const vec3 v = uniform(rng, real(0.5), 3) * random_unit(rng);
            if (cross(u, v).length() > real(0.05) * u.length() * v.length()) {
                objects.push_back(std::make_shared<rt::quad>(c, u, v, any_material()));
                list.add(objects.back().object);
                continue;
            }
        }
        if (i % 3 == 1) {
            const point3 c1 = c + uniform(rng, 0, 3) * random_unit(rng);
            objects.push_back(std::make_shared<rt::moving_sphere>(c, c1, radius, any_material()));
        } else {
            objects.push_back(std::make_shared<rt::sphere>(c, radius, any_material()));
        }
        list.add(objects.back().object);
    }
    const rt::bvh tree(objects);
    int hits = 0, differ = 0;
    for (int k = 0; k < 20000; ++k) {
        const point3 o = k % 2 ? random_in_cube(rng, 10) : point3(0, 0, 0) + 25 * random_unit(rng);
        const point3 target = random_in_cube(rng, 10);
        const rt::ray r(o, target - o, rng.uniform());
        rt::hit_record a, b;
        const bool ha = list.hit(r, rt::interval(0, rt::infinity), a);
        const bool hb = tree.hit(r, rt::interval(0, rt::infinity), b);
        hits += ha;
        if (ha != hb) {
            ++differ;
        } else if (ha) {
            const rt::surface_uv ua = a.uv(), ub = b.uv();
            if (a.object != b.object || a.object == nullptr || !exactly(a.local, b.local) ||
                ua.u != ub.u || ua.v != ub.v)
                ++differ;
        }
    }
    INFO(hits << " of 20000 rays hit");
    CHECK(hits > 5000);
    CHECK(differ == 0);
}
