// Tests for mesh_bvh.h (chapter 18): a mesh's tree packed eight boxes wide in floats, with its
// leaves' triangles tested four at a time, finds every ray's nearest hit as a loop over every
// triangle does, and answers exactly as chapter 07's tree over the same triangles wherever that
// finds the same hit (it can lose one within rounding of the interval's end): the same triangle
// at the same t to the bit, the same record, on shared edges and vertices (where two triangles may
// report the same t and the first in the tree's order must win), on rays in a box's face plane or
// along an axis, from far away, with a direction too small for floats, and inside intervals that
// end before a hit. It packs only trees of one mesh's triangles, and the fast traversal uses it for
// exactly those.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "ch03/material_helpers.h"
#include "ch18/mesh_helpers.h"
#include "rt/accel/fast_traversal.h"
#include "rt/accel/mesh_bvh.h"
#include "rt/accel/wide_bvh.h"
#include "rt/core/rng.h"
#include "rt/geometry/instance.h"
#include "rt/geometry/sphere.h"
#include "rt/geometry/triangle_mesh.h"
#include "rt/scene/hittable_list.h"
#include "test_helpers.h"

namespace {

using rt::point3, rt::real, rt::vec3;
using rt_test::exactly, rt_test::log_uniform, rt_test::random_in_cube, rt_test::random_unit;

struct comparison {
    long long rays = 0, hits = 0, mismatches = 0;
    long long lost_by_binary = 0;  // hits the binary tree loses to its box test's rounding
    std::string first;
};

bool same_record(const rt::hit_record& a, const rt::hit_record& b) {
    return a.object == b.object && a.t == b.t && exactly(a.p, b.p) && exactly(a.normal, b.normal) &&
           a.front_face == b.front_face && exactly(a.local, b.local) && a.p_error == b.p_error &&
           a.mat == b.mat;
}

// The order in which the binary tree would visit its objects for rays of an octant (bit k: the
// ray runs towards smaller coordinates on axis k), were no box missed: at each node the first
// child first, unless the ray runs the other way on the node's split axis.
std::map<const rt::hittable*, std::size_t> visiting_order(const rt::bvh& tree, int octant) {
    std::map<const rt::hittable*, std::size_t> rank;
    auto visit = [&](auto&& self, std::uint32_t i) -> void {
        const rt::bvh::node& n = tree.nodes()[i];
        if (n.count > 0) {
            for (std::uint32_t k = n.offset; k < n.offset + n.count; ++k)
                rank.emplace(tree.objects()[k].get(), rank.size());
            return;
        }
        const bool flipped = octant >> n.axis & 1;
        self(self, flipped ? n.offset : i + 1);
        self(self, flipped ? i + 1 : n.offset);
    };
    if (!tree.nodes().empty()) visit(visit, 0);
    return rank;
}

// Asks every triangle alone (mesh_triangle::hit), the binary tree and its packed form the same
// ray in the same interval. The packed tree must find the loop's nearest t, on a triangle the
// loop found at that t, with that triangle's own record; and the binary tree's very record,
// unless the binary tree lost a hit the packed tree found: a nearer one, or at the same t one
// that comes earlier in the binary tree's own visiting order (so that the binary tree, had its
// box test not rounded it away, would have kept it).
void compare(const rt::triangle_mesh& mesh, const rt::bvh& binary, const rt::mesh_bvh& packed,
             const rt::ray& r, rt::interval ray_t, comparison& c) {
    ++c.rays;
    bool any     = false;
    real nearest = ray_t.max;
    std::vector<rt::hit_record> at_nearest;
    for (const rt::mesh_triangle& face : mesh.faces()) {
        rt::hit_record rec;
        if (!face.hit(r, ray_t, rec)) continue;
        if (!any || rec.t < nearest) at_nearest.clear();
        if (!any || rec.t <= nearest) {
            any     = true;
            nearest = rec.t;
            at_nearest.push_back(rec);
        }
    }
    rt::hit_record want, got;
    const bool wanted = binary.hit(r, ray_t, want);
    const bool found  = packed.hit(r, ray_t, got);
    std::ostringstream what;
    what.precision(17);
    what << "origin " << r.origin() << ", direction " << r.direction() << ", t in [" << ray_t.min
         << ", " << ray_t.max << "]: ";
    if (found != any) {
        what << "the packed tree " << (found ? "hit" : "missed") << ", the loop did not";
    } else if (!found) {
        return;
    } else {
        ++c.hits;
        bool own = false;
        for (const rt::hit_record& rec : at_nearest) own = own || same_record(got, rec);
        if (own && wanted && same_record(got, want)) return;
        bool lost = !wanted || want.t > got.t;
        if (own && wanted && want.t == got.t) {
            int octant = 0;
            for (int k = 0; k < 3; ++k) octant |= 1 / r.direction()[k] < 0 ? 1 << k : 0;
            const auto rank = visiting_order(binary, octant);
            lost            = rank.at(got.object) < rank.at(want.object);
        }
        if (own && lost) {
            ++c.lost_by_binary;
            return;
        }
        what << "t " << got.t << " against the loop's " << nearest
             << (own ? ", another triangle than the binary tree's" : "");
    }
    if (c.mismatches++ == 0) c.first = what.str();
}

// Every ray as it should be, and the binary tree's lost hits rare: rays through a shared vertex
// or edge on a box's face, or ending on a triangle (its box test widens where a ray leaves a
// box, not where it enters).
void require_same(const comparison& c) {
    INFO(c.mismatches << " of " << c.rays << " rays differ (first: " << c.first << "); the binary "
                      << "tree lost " << c.lost_by_binary << " hits");
    CHECK(c.mismatches == 0);
    CHECK(c.lost_by_binary * 1000 <= c.rays);
}

std::shared_ptr<rt::triangle_mesh> mesh_of(rt::mesh_data data) {
    return std::make_shared<rt::triangle_mesh>(std::move(data), rt_test::any_material());
}

// Rays at every vertex, at points along every edge, and at random points of random triangles,
// from random origins around `center`; each also along its nearest axis only (two components
// 0), and in intervals that start later or end early.
void rays_at_features(const rt::triangle_mesh& mesh, const point3& center, real reach,
                      rt::pcg32& rng, comparison& c) {
    auto tree = rt::mesh_tree(mesh);
    const rt::mesh_bvh packed(tree);
    const rt::mesh_data& m = mesh.data();
    std::vector<point3> aims(m.positions.begin(), m.positions.end());
    for (const auto& e : rt_test::edges_of(m))
        for (real f : {real(0.5), real(0.25), real(1) / 3})
            aims.push_back(m.positions[e.a] + f * (m.positions[e.b] - m.positions[e.a]));
    for (int i = 0; i < 500; ++i) {
        const auto f = std::size_t(rng.uniform() * real(m.triangles.size())) % m.triangles.size();
        aims.push_back(rt_test::random_point_in(m, f, rng));
    }
    for (const point3& aim : aims) {
        const point3 origin = center + reach * random_unit(rng);
        const vec3 d        = aim - origin;
        compare(mesh, *tree, packed, rt::ray(origin, d), rt::interval(0, rt::infinity), c);
        // Along the axis nearest d, from beside the aim: a ray in the plane of many boxes' faces.
        int axis = 0;
        for (int k = 1; k < 3; ++k)
            if (std::fabs(d[k]) > std::fabs(d[axis])) axis = k;
        vec3 along(0, 0, 0);
        along[axis]   = d[axis] > 0 ? 1 : -1;
        point3 behind = aim;
        behind[axis]  = aim[axis] - along[axis] * reach;
        compare(mesh, *tree, packed, rt::ray(behind, along), rt::interval(0, rt::infinity), c);
        const real length = d.length();
        compare(mesh, *tree, packed, rt::ray(origin, d), rt::interval(real(0.5), real(0.999)), c);
        compare(mesh, *tree, packed, rt::ray(origin, d / length),
                rt::interval(length * real(0.5), length), c);
    }
}

}  // namespace

TEST_CASE(
    "mesh_bvh: on icospheres near and far, grids and a box, rays aimed at vertices, edges and "
    "faces, or "
    "along an axis, get the loop's nearest hit and the binary tree's record where it finds it",
    "[ch18]") {
    rt::pcg32 rng(20251203, 1);
    comparison c;
    rays_at_features(*mesh_of(rt_test::icosphere(point3(0.1, -0.3, 0.7), real(1.3), 3)),
                     point3(0.1, -0.3, 0.7), 4, rng, c);
    rays_at_features(*mesh_of(rt_test::quad_grid(point3(-1, 0.1, -1), vec3(0.1, 0, 0.02),
                                                 vec3(0, 0.013, 0.1), 20)),
                     point3(0, 0.3, 0), 3, rng, c);
    // An axis-aligned grid: its triangles' boxes are flat, and share faces with each other.
    rays_at_features(
        *mesh_of(rt_test::quad_grid(point3(-1, -1, 0.1), vec3(0.1, 0, 0), vec3(0, 0.1, 0), 20)),
        point3(0, 0, 0.1), 3, rng, c);
    rays_at_features(*mesh_of(rt_test::box_mesh(point3(-0.3, 0.1, 1.0 / 3), point3(0.7, 2, 1))),
                     point3(0.2, 1, 0.6), 3, rng, c);
    // Far from the world's origin, seen from near: a float box rounded to the nearest float there
    // (half a float's step at 1000, 3e-5) is off by far more than the slab distances' margins.
    rays_at_features(*mesh_of(rt_test::icosphere(point3(1000.1, -999.7, 1000.3), real(1.3), 2)),
                     point3(1000.1, -999.7, 1000.3), 4, rng, c);
    require_same(c);
    CHECK(c.hits > c.rays / 3);
}

TEST_CASE(
    "mesh_bvh: on a soup of 3000 random triangles of every size, random rays get the loop's "
    "nearest hit and the binary tree's record where it finds it",
    "[ch18]") {
    rt::pcg32 rng(20251203, 2);
    const rt::mesh_data data = rt_test::triangle_soup(rng, 3000, 10, -3, 1);
    auto mesh                = mesh_of(data);
    auto tree                = rt::mesh_object(mesh);
    const rt::mesh_bvh packed(tree);
    comparison c;
    for (int i = 0; i < 10000; ++i) {
        const point3 origin = random_in_cube(rng, 14);
        vec3 direction      = log_uniform(rng, -3, 3) * random_unit(rng);
        if (i % 2 == 1) {
            const auto f = std::size_t(rng.uniform() * 3000) % 3000;
            direction    = rt_test::random_point_in(data, f, rng) - origin;
        }
        compare(*mesh, *tree, packed, rt::ray(origin, direction), rt::interval(0, rt::infinity), c);
    }
    require_same(c);
    CHECK(c.hits > c.rays / 3);
}

TEST_CASE(
    "mesh_bvh: rays from far away, with a direction component too small for floats, or from "
    "an origin beyond them, get the loop's nearest hit and the binary tree's record",
    "[ch18]") {
    rt::pcg32 rng(20251203, 3);
    auto mesh = mesh_of(rt_test::icosphere(point3(0, 0, 0), 1, 2));
    auto tree = rt::mesh_object(mesh);
    const rt::mesh_bvh packed(tree);
    comparison c;
    const real big = std::numeric_limits<real>::max() / 4;
    for (int i = 0; i < 2000; ++i) {
        const point3 aim = real(0.9) * random_unit(rng);
        // Far away (beyond float's range in the double build).
        for (real far : {real(1e6), real(1e30), big}) {
            const vec3 from = random_unit(rng);
            compare(*mesh, *tree, packed, rt::ray(aim + far * from, -from),
                    rt::interval(0, rt::infinity), c);
        }
        // Two components tiny: from the smallest float's neighbourhood to below float's range.
        for (real tiny : {real(1e-30), real(1e-38), std::numeric_limits<real>::denorm_min()}) {
            vec3 d(tiny, -tiny, 1);
            d[i % 3]          = i % 2 ? 1 : -1;
            d[(i + 1) % 3]    = tiny;
            d[(i + 2) % 3]    = -tiny;
            const point3 from = aim - real(3) * d;
            compare(*mesh, *tree, packed, rt::ray(from, d), rt::interval(0, rt::infinity), c);
        }
    }
    require_same(c);
    CHECK(c.hits > c.rays / 2);
}

TEST_CASE(
    "mesh_bvh: meshes of one to four triangles (the tree one leaf) and of five to nine give "
    "the loop's nearest hits and the binary tree's records",
    "[ch18]") {
    rt::pcg32 rng(20251203, 4);
    const rt::mesh_data grid = rt_test::quad_grid(point3(-1, -1, 0), vec3(0.5, 0, 0.1),
                                                  vec3(0, 0.5, 0.05), 3);  // 18 triangles
    for (std::size_t n = 1; n <= 9; ++n) {
        rt::mesh_data some = grid;
        some.triangles.resize(n);
        auto mesh = mesh_of(some);
        auto tree = rt::mesh_object(mesh);
        const rt::mesh_bvh packed(tree);
        comparison c;
        for (int i = 0; i < 2000; ++i) {
            const auto f        = std::size_t(rng.uniform() * real(n)) % n;
            const point3 origin = point3(0, 0, 3) + random_in_cube(rng, 1);
            compare(*mesh, *tree, packed,
                    rt::ray(origin, rt_test::random_point_in(some, f, rng) - origin),
                    rt::interval(0, rt::infinity), c);
        }
        INFO(n << " triangles");
        require_same(c);
        CHECK(c.hits > c.rays / 2);
    }
}

TEST_CASE(
    "mesh_bvh: its box, transmittance and parts are the binary tree's, and it packs only a tree "
    "of one mesh's triangles",
    "[ch18]") {
    auto mesh = mesh_of(rt_test::icosphere(point3(1, 2, 3), 1, 1));
    auto tree = rt::mesh_object(mesh);
    const rt::mesh_bvh packed(tree);
    for (int axis = 0; axis < 3; ++axis) {
        CHECK(packed.bounding_box().axis_interval(axis).min ==
              tree->bounding_box().axis_interval(axis).min);
        CHECK(packed.bounding_box().axis_interval(axis).max ==
              tree->bounding_box().axis_interval(axis).max);
    }
    const rt::ray through(point3(1, 2, -3), vec3(0, 0, 1)), beside(point3(5, 2, -3), vec3(0, 0, 1));
    CHECK(packed.transmittance(through, rt::interval(0, rt::infinity)) == 0);
    CHECK(packed.transmittance(beside, rt::interval(0, rt::infinity)) == 1);
    struct count_parts : rt::part_visitor {
        std::size_t n = 0;
        void visit(const rt::hittable&) override { ++n; }
    } parts;
    packed.visit_parts(parts);
    CHECK(parts.n == mesh->triangle_count());

    CHECK(rt::mesh_bvh::packs(*tree));
    auto other = mesh_of(rt_test::octahedron(point3(0, 0, 0), 1));
    std::vector<rt::bounded_object> two_meshes, with_a_sphere;
    for (const auto& face : tree->objects()) {
        two_meshes.emplace_back(std::static_pointer_cast<rt::bounded_hittable>(face));
        with_a_sphere.emplace_back(std::static_pointer_cast<rt::bounded_hittable>(face));
    }
    const auto other_tree = rt::mesh_object(other);
    for (const auto& face : other_tree->objects())
        two_meshes.emplace_back(std::static_pointer_cast<rt::bounded_hittable>(face));
    with_a_sphere.emplace_back(
        std::make_shared<rt::sphere>(point3(0, 0, 0), 1, rt_test::any_material()));
    auto mixed = std::make_shared<rt::bvh>(two_meshes);
    auto round = std::make_shared<rt::bvh>(with_a_sphere);
    CHECK_FALSE(rt::mesh_bvh::packs(*mixed));
    CHECK_FALSE(rt::mesh_bvh::packs(*round));
    CHECK_FALSE(rt::mesh_bvh::packs(rt::bvh({})));
    CHECK_THROWS_AS(rt::mesh_bvh(mixed), std::invalid_argument);
    CHECK_THROWS_AS(rt::mesh_bvh(nullptr), std::invalid_argument);
    CHECK(rt::mesh_bvh::packer()(round) == nullptr);
    CHECK(rt::mesh_bvh::packer()(tree) != nullptr);
}

TEST_CASE(
    "mesh_bvh: the fast traversal packs each mesh's tree with it, in a list and inside an "
    "instance, and other trees as chapter 17 does",
    "[ch18]") {
    auto mesh  = mesh_of(rt_test::icosphere(point3(0, 0, 0), 1, 1));
    auto world = std::make_shared<rt::hittable_list>();
    world->add(rt::mesh_object(mesh));
    world->add(std::make_shared<rt::translate>(rt::mesh_object(mesh), vec3(3, 0, 0)));
    world->add(std::make_shared<rt::bvh>(std::vector<rt::bounded_object>{
        std::make_shared<rt::sphere>(point3(-3, 0, 0), 1, rt_test::any_material())}));
    const auto fast = std::dynamic_pointer_cast<rt::hittable_list>(
        rt::with_wide_bvhs(world, {}, {rt::mesh_bvh::packer()}));
    REQUIRE(fast != nullptr);
    REQUIRE(fast->objects.size() == 3);
    CHECK(dynamic_cast<const rt::mesh_bvh*>(fast->objects[0].get()) != nullptr);
    const auto* moved = dynamic_cast<const rt::translate*>(fast->objects[1].get());
    REQUIRE(moved != nullptr);
    CHECK(dynamic_cast<const rt::mesh_bvh*>(moved->placed().get()) != nullptr);
    CHECK(dynamic_cast<const rt::mesh_bvh*>(fast->objects[2].get()) == nullptr);
    CHECK(dynamic_cast<const rt::wide_bvh*>(fast->objects[2].get()) != nullptr);
}
