// Tests for how bvh.h stores its tree for speed (chapter 07): wide nodes of up to four boxes, the
// split rule that gives small flat objects their own boxes, and leaves that keep spheres and quads
// by type.
// test_bvh.cpp checks that the answers equal the flat list's bit for bit; these check that the
// speed-ups do what they are for, and that only exact spheres and quads skip the virtual call.
#include <catch2/catch.hpp>
#include <memory>
#include <vector>

#include "ch03/material_helpers.h"
#include "rt/accel/wide_bvh.h"
#include "rt/core/rng.h"
#include "rt/geometry/moving_sphere.h"
#include "rt/geometry/quad.h"
#include "rt/geometry/sphere.h"
#include "rt/scene/hittable_list.h"
#include "test_helpers.h"

namespace {

using rt::aabb, rt::interval, rt::point3, rt::real, rt::vec3;
using rt_test::any_material, rt_test::exactly, rt_test::random_unit, rt_test::uniform;

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

// A sphere type of its own (derived from rt::sphere) that counts its tests.
struct counting_sphere : rt::sphere {
    long long* tests;
    counting_sphere(const point3& c, real radius, long long* t)
        : rt::sphere(c, radius, any_material()), tests(t) {}
    bool hit(const rt::ray& r, interval ray_t, rt::hit_record& rec) const override {
        ++*tests;
        return rt::sphere::hit(r, ray_t, rec);
    }
};

// A quad type of its own (derived from rt::quad) that counts its tests.
struct counting_quad : rt::quad {
    long long* tests;
    counting_quad(const point3& q, const vec3& u, const vec3& v, long long* t)
        : rt::quad(q, u, v, any_material()), tests(t) {}
    bool hit(const rt::ray& r, interval ray_t, rt::hit_record& rec) const override {
        ++*tests;
        return rt::quad::hit(r, ray_t, rec);
    }
};

}  // namespace

TEST_CASE("bvh: the walls of a room each get their own box, so a ray tests about one", "[ch07]") {
    // Six flat quads whose union box is the whole room: split only by their union boxes, the
    // surface area heuristic would keep them in one leaf (a split's halves are as big as the
    // room) and every ray would test four to six walls. Each in its own box of a wide node, a
    // ray from inside tests the wall it leaves by, and those it meets beyond it only by chance.
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

TEST_CASE("bvh: only exact spheres, moving spheres and quads skip hit(), derived types are asked",
          "[ch07]") {
    // The leaves test spheres and quads from copies of their fields, as sphere::hit and
    // quad::hit would. A type derived from either may answer differently, so the tree must ask
    // it through its own hit().
    long long tests = 0;
    std::vector<rt::bounded_object> objects;
    rt::hittable_list list;
    rt::pcg32 rng(22, 7);
    for (int i = 0; i < 100; ++i) {
        const point3 c    = random_point(rng, -10, 10);
        const real radius = uniform(rng, real(0.3), 2);
        const vec3 u      = 2 * radius * random_unit(rng);
        const vec3 v      = 2 * radius * random_unit(rng);
        std::shared_ptr<rt::hittable> shape;
        if (i % 5 == 0) {
            auto s = std::make_shared<counting_sphere>(c, radius, &tests);
            objects.emplace_back(std::static_pointer_cast<rt::sphere>(s));
            shape = s;
        } else if (i % 5 == 3) {
            auto q = std::make_shared<rt::quad>(c, u, v, any_material());
            objects.emplace_back(q);
            shape = q;
        } else if (i % 5 == 4) {
            auto q = std::make_shared<counting_quad>(c, u, v, &tests);
            objects.emplace_back(std::static_pointer_cast<rt::quad>(q));
            shape = q;
        } else if (i % 5 == 1) {
            auto m =
                std::make_shared<rt::moving_sphere>(c, c + vec3(0, 1, 0), radius, any_material());
            objects.emplace_back(m);
            shape = m;
        } else {
            auto s = std::make_shared<rt::sphere>(c, radius, any_material());
            objects.emplace_back(s);
            shape = s;
        }
        list.add(shape);
    }
    const rt::bvh tree(objects);
    long long tree_tests = 0;
    int hits             = 0;
    for (int i = 0; i < 3000; ++i) {
        const point3 from  = 30 * random_unit(rng);
        const point3 aim   = random_point(rng, -10, 10);
        const real instant = rng.uniform();
        const rt::ray r(from, aim - from, instant);
        rt::hit_record a, b;
        tests             = 0;
        const bool in_bvh = tree.hit(r, interval(0, rt::infinity), a);
        tree_tests += tests;
        const bool in_list = list.hit(r, interval(0, rt::infinity), b);
        REQUIRE(in_bvh == in_list);
        if (in_bvh) {  // the whole record, as the object's own hit() writes it
            ++hits;
            CHECK(a.t == b.t);
            CHECK(exactly(a.p, b.p));
            CHECK(a.p_error == b.p_error);
            CHECK(exactly(a.normal, b.normal));
            CHECK(a.front_face == b.front_face);
            CHECK(exactly(a.local, b.local));
            CHECK(a.mat == b.mat);
            CHECK(a.object == b.object);
        }
    }
    CHECK(hits > 100);
    CHECK(tree_tests > 0);  // the derived spheres and quads were asked
}

TEST_CASE("bvh: wide nodes expand their widest lanes first, so a ray tests fewer of them",
          "[ch07]") {
    // A room of five walls and two boxes in it, each face a quad: the Cornell box unturned.
    std::vector<rt::bounded_object> room;
    const real s = 555;
    auto add     = [&](const point3& q, const vec3& u, const vec3& v) {
        room.emplace_back(std::make_shared<rt::quad>(q, u, v, any_material()));
    };
    add(point3(s, 0, 0), vec3(0, s, 0), vec3(0, 0, s));
    add(point3(0, 0, 0), vec3(0, s, 0), vec3(0, 0, s));
    add(point3(0, 0, 0), vec3(s, 0, 0), vec3(0, 0, s));
    add(point3(s, s, s), vec3(-s, 0, 0), vec3(0, 0, -s));
    add(point3(0, 0, s), vec3(s, 0, 0), vec3(0, s, 0));
    auto add_box = [&](const point3& lo, const point3& hi) {  // six faces, as chapter 11's box
        const vec3 dx(hi.x() - lo.x(), 0, 0), dy(0, hi.y() - lo.y(), 0), dz(0, 0, hi.z() - lo.z());
        add(point3(lo.x(), lo.y(), hi.z()), dx, dy);
        add(point3(hi.x(), lo.y(), hi.z()), -dz, dy);
        add(point3(hi.x(), lo.y(), lo.z()), -dx, dy);
        add(lo, dz, dy);
        add(point3(lo.x(), hi.y(), hi.z()), dx, -dz);
        add(lo, dx, dz);
    };
    add_box(point3(265, 0, 295), point3(430, 330, 460));
    add_box(point3(130, 0, 65), point3(295, 165, 230));
    const rt::bvh cornell(room);
    // Each quad is a leaf of its own (the walls test above). Folding a fixed two binary levels
    // into each wide node leaves lanes empty where a child is a leaf: 4.01 wide-node tests per
    // random ray here. Expanding the widest lane while there is room: 3.45. The root is always
    // tested.
    INFO("wide-node tests per random ray: " << cornell.expected_node_tests());
    CHECK(cornell.expected_node_tests() < 3.6);
    CHECK(cornell.expected_node_tests() >= 1);
}

TEST_CASE("bvh: a tree of one leaf and a tree of many answer alike at every depth", "[ch07]") {
    // Wide nodes fold up to four descendants of a binary node into one: trees of 1 to 40 objects
    // give wide trees with one, two and three levels, with unused lanes, with lanes one, two and
    // three binary levels down, and with leaves directly below the root. Each must agree with
    // the list.
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
