// Tests for the shape of bvh.h's tree (chapter 07): the split rule that gives small flat objects
// their own boxes, and trees of every small size. test_bvh.cpp checks that the answers equal the
// flat list's bit for bit; chapter 17's tests hold the wide BVH packed from this tree to the
// same hits.
#include <catch2/catch.hpp>
#include <memory>
#include <vector>

#include "ch03/material_helpers.h"
#include "rt/accel/bvh.h"
#include "rt/core/rng.h"
#include "rt/geometry/quad.h"
#include "rt/geometry/sphere.h"
#include "rt/scene/hittable_list.h"
#include "test_helpers.h"

namespace {

using rt::aabb, rt::interval, rt::point3, rt::real, rt::vec3;
using rt_test::any_material, rt_test::random_unit, rt_test::uniform;

// A point uniform in the cube [lo, hi)^3, one draw per statement (so the order is fixed).
point3 random_point(rt::pcg32& rng, real lo, real hi) {
    const real x = uniform(rng, lo, hi);
    const real y = uniform(rng, lo, hi);
    return point3(x, y, uniform(rng, lo, hi));
}

// Wraps an object and counts how often it is asked for a hit.
struct counted : rt::bounded_hittable {
    std::shared_ptr<rt::hittable> inner;
    aabb box;
    long long* tests;
    counted(const rt::bounded_object& o, long long* t) : inner(o.object), box(o.box), tests(t) {}
    bool hit(const rt::ray& r, interval ray_t, rt::hit_record& rec) const override {
        ++*tests;
        return inner->hit(r, ray_t, rec);
    }
    aabb bounding_box() const override { return box; }
};

}  // namespace

TEST_CASE("bvh: the walls of a room each get their own box, so a ray tests about one", "[ch07]") {
    // Six flat quads whose union box is the whole room: split only by their union boxes, the
    // surface area heuristic would keep them in one leaf (a split's halves are as big as the
    // room) and every ray would test four to six walls. Each in its own box, a ray from inside
    // tests the wall it leaves by, and those it meets beyond it only by chance.
    long long tests = 0;
    const real s    = 10;
    const point3 o(0, 0, 0);
    std::vector<rt::bounded_object> walls;
    auto wall = [&](const point3& q, const vec3& u, const vec3& v) {
        const rt::bounded_object face(std::make_shared<rt::quad>(q, u, v, any_material()));
        walls.emplace_back(std::make_shared<counted>(face, &tests));
    };
    wall(o, vec3(s, 0, 0), vec3(0, s, 0));
    wall(point3(0, 0, s), vec3(0, s, 0), vec3(s, 0, 0));
    wall(o, vec3(0, s, 0), vec3(0, 0, s));
    wall(point3(s, 0, 0), vec3(0, 0, s), vec3(0, s, 0));
    wall(o, vec3(0, 0, s), vec3(s, 0, 0));
    wall(point3(0, s, 0), vec3(s, 0, 0), vec3(0, 0, s));
    const rt::bvh room(walls);
    rt::pcg32 rng(21, 7);
    const int rays = 2000;
    int hits       = 0;
    for (int i = 0; i < rays; ++i) {
        const point3 from = random_point(rng, 1, 9);
        rt::hit_record rec;
        hits += room.hit(rt::ray(from, random_unit(rng)), interval(0, rt::infinity), rec);
    }
    CHECK(hits == rays);  // a closed room: every ray leaves by a wall
    INFO("wall tests per ray: " << double(tests) / rays);
    CHECK(tests < rays + rays / 5);
}

TEST_CASE("bvh: a tree of one leaf and a tree of many answer alike at every depth", "[ch07]") {
    // Trees of 1 to 40 objects: a root that is a leaf, leaves at every depth, splits by the
    // heuristic and by the median. Each must agree with the list.
    rt::pcg32 rng(23, 7);
    for (int n = 1; n <= 40; ++n) {
        std::vector<rt::bounded_object> objects;
        rt::hittable_list list;
        for (int i = 0; i < n; ++i) {
            const point3 c = random_point(rng, -5, 5);
            auto s = std::make_shared<rt::sphere>(c, uniform(rng, real(0.2), 1), any_material());
            objects.emplace_back(s);
            list.add(s);
        }
        const rt::bvh tree(objects);
        int disagreements = 0;
        for (int i = 0; i < 500; ++i) {
            const point3 from = 15 * random_unit(rng);
            const point3 aim  = random_point(rng, -5, 5);
            const rt::ray r(from, aim - from);
            rt::hit_record a, b;
            const bool in_bvh  = tree.hit(r, interval(0, rt::infinity), a);
            const bool in_list = list.hit(r, interval(0, rt::infinity), b);
            if (in_bvh != in_list || (in_bvh && (a.t != b.t || a.mat != b.mat))) ++disagreements;
        }
        INFO(n << " objects");
        CHECK(disagreements == 0);
    }
}
