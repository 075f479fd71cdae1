// Tests for bvh.h (chapter 07). The BVH must answer exactly as the brute-force hittable_list:
// both report the object whose nearest root in ray_t is the smallest, and that object computes
// its hit from the ray alone, so t, p, the normal and the material agree bit for bit, hit or
// miss (chapter 08's test_bvh adds what the surface coordinates are computed from). [hardcase]
// compares them on 300,000 random rays over random scenes; the unit tests feed the builder the
// inputs that break binned SAH builders (no objects, coincident centers, tiny next to huge,
// collinear, exponentially spaced, flat boxes) and check the tree's shape.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "rt/accel/bvh.h"
#include "rt/core/rng.h"
#include "rt/geometry/moving_sphere.h"
#include "rt/geometry/quad.h"
#include "rt/geometry/sphere.h"
#include "rt/materials/lambertian.h"
#include "rt/scene/hittable_list.h"
#include "test_helpers.h"

namespace {

using rt::aabb, rt::interval, rt::point3, rt::real, rt::vec3;
using object_list = std::vector<rt::bounded_object>;

const interval forward(0, rt::infinity);

// Every object gets its own material, so the material pointer of a hit names the object.
std::shared_ptr<rt::material> own_material() {
    return std::make_shared<rt::lambertian>(rt::color(0.5, 0.5, 0.5));
}

std::shared_ptr<rt::sphere> sphere_at(const point3& center, real radius) {
    return std::make_shared<rt::sphere>(center, radius, own_material());
}

// The brute-force answer: the same objects in a plain list.
rt::hittable_list list_of(const object_list& objects) {
    rt::hittable_list list;
    for (const auto& o : objects) list.add(o.object);
    return list;
}

// The union of the objects' boxes: what the tree's root box must be.
aabb union_of(const object_list& objects) {
    aabb all;
    for (const auto& o : objects) all = aabb(all, o.box);
    return all;
}

using rt_test::exactly, rt_test::random_in_cube, rt_test::random_unit, rt_test::uniform;

real log_uniform(rt::pcg32& rng, real lo, real hi) {
    return lo * std::pow(hi / lo, rng.uniform());
}

point3 random_point(rt::pcg32& rng, const point3& center, real half_side) {
    return center + random_in_cube(rng, half_side);
}

point3 random_point_in(rt::pcg32& rng, const aabb& box) {
    real x = uniform(rng, box.x.min, box.x.max);
    real y = uniform(rng, box.y.min, box.y.max);
    return point3(x, y, uniform(rng, box.z.min, box.z.max));
}

bool same_hit(const rt::hit_record& a, const rt::hit_record& b) {
    return a.t == b.t && a.mat == b.mat && exactly(a.p, b.p) && exactly(a.normal, b.normal) &&
           a.front_face == b.front_face && a.p_error == b.p_error;
}

// Runs one ray through both and counts disagreements; reports the first few.
struct comparison {
    long long rays = 0, hits = 0, mismatches = 0;

    void check(const rt::hittable& list, const rt::bvh& tree, const rt::ray& r, interval ray_t) {
        rt::hit_record expected, got;
        const bool list_hit = list.hit(r, ray_t, expected);
        const bool bvh_hit  = tree.hit(r, ray_t, got);
        ++rays;
        hits += list_hit;
        if (list_hit == bvh_hit && (!list_hit || same_hit(expected, got))) return;
        if (++mismatches <= 5) {
            UNSCOPED_INFO(
                "ray " << r.origin() << " + t " << r.direction() << " at time " << r.time()
                       << ", t in [" << ray_t.min << ", " << ray_t.max << "]: list "
                       << (list_hit ? "hits" : "misses") << " at t = " << expected.t << ", bvh "
                       << (bvh_hit ? "hits" : "misses") << " at t = " << got.t
                       << (list_hit && bvh_hit && expected.mat != got.mat ? " (another object)"
                                                                          : ""));
        }
    }
};

// A ray for a scene inside `bounds`: from outside (on a sphere around the scene) or from a random
// point inside; aimed at a random point of the scene, or (every other ray, so that a sparse scene
// is hit often enough) at a random point of one object's box. Directions are not unit length;
// some are parallel to one or two axes (1 / direction infinite in the BVH). Times are uniform in
// [0, 1); a fifth of the rays get a random finite interval.
struct ray_and_interval {
    rt::ray r;
    interval ray_t;
};

ray_and_interval random_ray(rt::pcg32& rng, const aabb& bounds, const std::vector<aabb>& boxes,
                            long long i) {
    const point3 center = bounds.centroid();
    const real reach    = (point3(bounds.x.max, bounds.y.max, bounds.z.max) - center).length();
    const point3 origin = i % 4 < 2 ? center + (real(1.5) * reach + 1) * random_unit(rng)
                                    : random_point_in(rng, bounds);
    vec3 d;
    if (i % 2 == 0 && !boxes.empty()) {
        d = random_point_in(rng, boxes[rng.next_u32() % boxes.size()]) - origin;
    } else if (i % 4 == 1) {
        d = random_point_in(rng, bounds) - origin;
    } else {
        d = random_unit(rng);
    }
    d = log_uniform(rng, real(0.1), 10) * rt::unit_vector(d);
    if (i % 10 == 3) d[int(i / 10 % 3)] = 0;
    if (i % 20 == 7) {
        const int axis = int(i / 20 % 3);
        const vec3 along(d[0], d[1], d[2]);
        d       = vec3(0, 0, 0);
        d[axis] = along[axis] < 0 ? real(-1) : real(1);
    }
    const real time = rng.uniform();
    interval ray_t  = forward;
    if (i % 5 == 4) {
        const real scale = 2 * (reach + 1) / d.length();  // a t that crosses the scene
        const real lo    = uniform(rng, 0, real(0.5)) * scale;
        ray_t            = interval(lo, lo + uniform(rng, 0, 1) * scale);
    }
    return {rt::ray(origin, d, time), ray_t};
}

std::vector<aabb> boxes_of(const object_list& objects) {
    std::vector<aabb> boxes;
    for (const auto& o : objects) {
        if (!o.box.empty()) boxes.push_back(o.box);
    }
    return boxes;
}

// Compares the BVH over `objects` with the list on n random rays.
comparison compare_random(const object_list& objects, long long n, std::uint64_t seed) {
    const rt::hittable_list list = list_of(objects);
    const rt::bvh tree(objects);
    rt::pcg32 rng(seed, 99);
    comparison c;
    const aabb bounds             = union_of(objects);
    const std::vector<aabb> boxes = boxes_of(objects);
    for (long long i = 0; i < n; ++i) {
        auto [r, ray_t] = random_ray(rng, bounds, boxes, i);
        c.check(list, tree, r, ray_t);
    }
    return c;
}

enum class layout { spread, clustered, moving_and_quads };

// n objects: spheres spread over a 20-unit cube (radii 0.05..2); or in five tight clusters
// (radii 0.01..0.2, overlapping); or spread with a third of the spheres moving up to 3 units
// during the shutter and a quarter of the objects quads of random orientation.
object_list random_scene(rt::pcg32& rng, int n, layout kind) {
    object_list objects;
    point3 clusters[5];
    for (auto& c : clusters) c = random_point(rng, point3(0, 0, 0), 10);
    for (int i = 0; i < n; ++i) {
        switch (kind) {
            case layout::spread: {
                const point3 c = random_point(rng, point3(0, 0, 0), 10);
                objects.push_back(sphere_at(c, log_uniform(rng, real(0.05), 2)));
                break;
            }
            case layout::clustered: {
                const point3 c = random_point(rng, clusters[i % 5], real(0.3));
                objects.push_back(sphere_at(c, log_uniform(rng, real(0.01), real(0.2))));
                break;
            }
            case layout::moving_and_quads: {
                const point3 c = random_point(rng, point3(0, 0, 0), 10);
                if (i % 4 == 1) {
                    const real lu = log_uniform(rng, real(0.2), 3);
                    const vec3 u  = lu * random_unit(rng);
                    const real lv = log_uniform(rng, real(0.2), 3);
                    const vec3 v  = lv * random_unit(rng);
                    if (cross(u, v).length() > real(0.05) * u.length() * v.length()) {
                        objects.push_back(std::make_shared<rt::quad>(c, u, v, own_material()));
                        break;
                    }
                }
                const real radius = log_uniform(rng, real(0.05), 2);
                if (i % 3 == 0) {
                    const real travel = uniform(rng, 0, 3);
                    const point3 c1   = c + travel * random_unit(rng);
                    objects.push_back(
                        std::make_shared<rt::moving_sphere>(c, c1, radius, own_material()));
                } else {
                    objects.push_back(sphere_at(c, radius));
                }
                break;
            }
        }
    }
    return objects;
}

void compare_layout(layout kind, std::uint64_t seed) {
    // 20,000 rays per scene, 5 sizes: 100,000 rays per layout, 300,000 in all. The list tests
    // every object, so the 1000-object scenes dominate the run time (2e7 object tests, about
    // 0.2 s per layout in Release).
    rt::pcg32 rng(seed, 1);
    for (int n : {1, 2, 7, 100, 1000}) {
        const object_list objects = random_scene(rng, n, kind);
        const comparison c        = compare_random(objects, 20000, seed * 1000 + std::uint64_t(n));
        INFO(n << " objects: " << c.rays << " rays, " << c.hits << " hits, " << c.mismatches
               << " disagreements");
        CHECK(c.mismatches == 0);
        // Neither answer dominates, so both are compared. (A moving sphere fills a small part
        // of its swept box at any one time, and a tilted quad of its box: with two objects, a
        // tenth of the rays hit.)
        CHECK(c.hits > c.rays / 20);
        CHECK(c.hits < c.rays * 19 / 20);
    }
}

int log2_ceil(std::size_t n) {
    int k = 0;
    while ((std::size_t(1) << k) < n) ++k;
    return k;
}

// The shape every tree must have: a full binary tree (node_count = 2 leaves - 1) whose leaves
// hold 1 to 4 objects, so n/4 <= leaves <= n; its box is the exact union of the objects' boxes.
void check_shape(const rt::bvh& tree, const object_list& objects) {
    const std::size_t n = objects.size();
    CHECK(tree.object_count() == n);
    CHECK(tree.node_count() % 2 == 1);
    CHECK(tree.node_count() <= 2 * n - 1);
    CHECK(tree.node_count() >= 2 * ((n + 3) / 4) - 1);
    const aabb want = union_of(objects), got = tree.bounding_box();
    for (int axis = 0; axis < 3; ++axis) {
        CHECK(got.axis_interval(axis).min == want.axis_interval(axis).min);
        CHECK(got.axis_interval(axis).max == want.axis_interval(axis).max);
    }
}

}  // namespace

TEST_CASE("bvh: same closest hit as the list over spread-out random spheres", "[hardcase][ch07]") {
    compare_layout(layout::spread, 11);
}

TEST_CASE("bvh: same closest hit as the list over clustered, overlapping spheres",
          "[hardcase][ch07]") {
    compare_layout(layout::clustered, 12);
}

TEST_CASE("bvh: same closest hit as the list over moving spheres and quads at random times",
          "[hardcase][ch07]") {
    compare_layout(layout::moving_and_quads, 13);
}

TEST_CASE("bvh: an empty bvh is missed by everything and has an empty box", "[ch07]") {
    const rt::bvh tree(object_list{});
    CHECK(tree.node_count() == 0);
    CHECK(tree.object_count() == 0);
    CHECK(tree.depth() == 0);
    CHECK(tree.bounding_box().empty());
    rt::hit_record rec;
    rec.t = -7;
    CHECK_FALSE(tree.hit(rt::ray(point3(0, 0, 0), vec3(1, 0, 0)), interval::universe(), rec));
    CHECK(rec.t == -7);
}

TEST_CASE("bvh: one object is a single leaf, and a miss leaves the record untouched", "[ch07]") {
    const object_list one = {sphere_at(point3(0, 0, -3), 1)};
    const rt::bvh tree(one);
    CHECK(tree.node_count() == 1);
    CHECK(tree.depth() == 1);
    check_shape(tree, one);
    rt::hit_record rec;
    REQUIRE(tree.hit(rt::ray(point3(0, 0, 0), vec3(0, 0, -1)), forward, rec));
    CHECK(rec.t == 2);
    rec.t = -7;
    CHECK_FALSE(tree.hit(rt::ray(point3(0, 0, 0), vec3(0, 0, 1)), forward, rec));
    CHECK(rec.t == -7);
}

TEST_CASE("bvh: objects that share one center (stacked spheres) build a shallow tree", "[ch07]") {
    // No split plane separates coincident centroids: the builder must stop or split by count,
    // never recurse on the same set or leave an empty node.
    rt::pcg32 rng(3, 3);
    const point3 center(1.25, -0.5, 3);
    for (int n : {5, 16, 100, 1000}) {
        CAPTURE(n);
        // Concentric spheres of different radii: the nearest hit is unique.
        object_list concentric;
        for (int i = 0; i < n; ++i) concentric.push_back(sphere_at(center, real(0.1 + 0.01 * i)));
        // Their box centroids differ in the last bits (c - r + c + r rounds differently for
        // each r), enough for the SAH to split on: only the general bound applies.
        const rt::bvh tree(concentric);
        check_shape(tree, concentric);
        CHECK(tree.depth() < 3 * log2_ceil(std::size_t(n)) + 4);
        const rt::hittable_list list = list_of(concentric);
        comparison c;
        for (int i = 0; i < 2000; ++i) {
            // From inside the stack and from far away; aimed at the center half of the time.
            const point3 o = random_point(rng, center, i % 4 < 2 ? real(0.1) : real(30));
            const vec3 d   = i % 2 ? random_unit(rng) : random_point(rng, center, real(0.05)) - o;
            c.check(list, tree, rt::ray(o, d), forward);
        }
        CHECK(c.mismatches == 0);
        CHECK(c.hits > 1000);

        // Identical spheres: bit-identical centroids, so only a split by count can help, and
        // the depth is exactly that of halving down to leaves of at most 4: after k halvings the
        // largest part holds ceil(n / 2^k), so k = ceil(log2(ceil(n / 4))) and the depth k + 1.
        // Every sphere is hit at the same t; any of them is a right answer.
        object_list identical;
        for (int i = 0; i < n; ++i) identical.push_back(sphere_at(center, 1));
        const rt::bvh same(identical);
        check_shape(same, identical);
        CHECK(same.depth() == log2_ceil(std::size_t(n + 3) / 4) + 1);
        rt::hit_record rec;
        REQUIRE(same.hit(rt::ray(center + vec3(0, 0, 5), vec3(0, 0, -1)), forward, rec));
        CHECK(rec.t == 4);
        CHECK(rec.mat != nullptr);
    }
}

TEST_CASE("bvh: many tiny spheres beside or inside one huge sphere", "[ch07]") {
    // 500 spheres of radius 1e-3 in a unit cube, with a sphere of radius 1e3 below them (the
    // book's ground) or around them (the rays start inside it). Rays aim at a tiny sphere half
    // the time, so tiny hits are compared too.
    rt::pcg32 rng(5, 5);
    for (bool enclosing : {false, true}) {
        CAPTURE(enclosing);
        object_list objects;
        std::vector<point3> centers;
        for (int i = 0; i < 500; ++i) {
            centers.push_back(random_point(rng, point3(0, 0, 0), real(0.5)));
            objects.push_back(sphere_at(centers.back(), real(1e-3)));
        }
        objects.push_back(sphere_at(enclosing ? point3(0, 0, 0) : point3(0, -1000.5, 0), 1000));
        const rt::bvh tree(objects);
        check_shape(tree, objects);
        const rt::hittable_list list = list_of(objects);
        comparison c;
        int tiny_hits = 0;
        for (int i = 0; i < 10000; ++i) {
            const point3 o = random_point(rng, point3(0, 1, 0), 2);
            vec3 d         = random_unit(rng);
            if (i % 2 == 0) {
                const point3 target =
                    centers[std::size_t(i / 2) % centers.size()] + real(9e-4) * random_unit(rng);
                d = target - o;
            }
            c.check(list, tree, rt::ray(o, d), forward);
            rt::hit_record rec;
            if (tree.hit(rt::ray(o, d), forward, rec) && rec.t * d.length() < 10) ++tiny_hits;
        }
        CHECK(c.mismatches == 0);
        CHECK(tiny_hits > 2000);
    }
}

TEST_CASE("bvh: collinear objects", "[ch07]") {
    // Centroids on a line along an axis, and along the diagonal where every axis ties.
    rt::pcg32 rng(6, 6);
    for (const vec3& step : {vec3(0.5, 0, 0), vec3(0.375, 0.375, 0.375), vec3(0, 0, -2)}) {
        CAPTURE(step);
        object_list objects;
        for (int i = 0; i < 300; ++i)
            objects.push_back(sphere_at(point3(0, 0, 0) + real(i) * step, real(0.2)));
        const rt::bvh tree(objects);
        check_shape(tree, objects);
        CHECK(tree.depth() < 3 * log2_ceil(objects.size()) + 4);
        const comparison c = compare_random(objects, 5000, 61);
        CHECK(c.mismatches == 0);
        CHECK(c.hits > 500);
    }
}

TEST_CASE("bvh: exponentially spaced objects keep the depth within the traversal stack", "[ch07]") {
    // 1024 centers in geometric progression, radius a fifth of the gap to the next: the top bin
    // of any split (the last 1/12 of the extent) holds only the few farthest objects, so every
    // SAH split can only peel those off, one level each. The builder switches to median splits
    // below level 40, so the depth stays within the 64 entries of the traversal stack.
    // The scales span 2^-e .. 2^e with e an eighth of the scalar's exponent range: the sphere
    // test squares |d|^2 r, and (2^e)^6 must not overflow (nor (2^-e)^6 underflow). 4 centers
    // per octave (ratio 1.19): 1024 objects for a double, only 128 for a float.
    const int e          = std::numeric_limits<real>::max_exponent / 8;  // 128 or 16
    const int per_octave = 4;
    const real ratio     = std::exp2(real(1) / real(per_octave));
    object_list objects;
    std::vector<real> scales;
    for (int k = -per_octave * e; k < per_octave * e; ++k) {
        scales.push_back(std::exp2(real(k) / real(per_octave)));
        objects.push_back(
            sphere_at(point3(scales.back(), 0, 0), real(0.2) * (ratio - 1) * scales.back()));
    }
    const rt::bvh tree(objects);
    INFO(objects.size() << " objects: depth " << tree.depth() << ", " << tree.node_count()
                        << " nodes");
    check_shape(tree, objects);
    // The SAH did peel a few at a time, as intended here (a float's 128 objects are too few to
    // show it).
    if (objects.size() >= 1024) CHECK(tree.depth() > 40);
    CHECK(tree.depth() <= 64);

    // Rays at every scale: from beside sphere j (2 radii from its center) through sphere k (at
    // 0.8 radii from its center), with j within 2 octaves of k. Not across many scales: a ray
    // from 2^50 through the tiny spheres near 0 reaches them all at the same rounded t, and then
    // any of the tied objects is a right answer.
    const rt::hittable_list list = list_of(objects);
    rt::pcg32 rng(7, 7);
    comparison c;
    const auto n = std::uint32_t(scales.size()), span = std::uint32_t(2 * per_octave);
    const real radius_ratio = real(0.2) * (ratio - 1);
    for (int i = 0; i < 5000; ++i) {
        const std::uint32_t k = span + rng.next_u32() % (n - 2 * span);
        const std::uint32_t j = k - span + rng.next_u32() % (2 * span + 1);
        const point3 o = point3(scales[j], 0, 0) + 2 * radius_ratio * scales[j] * random_unit(rng);
        const point3 target =
            point3(scales[k], 0, 0) + real(0.8) * radius_ratio * scales[k] * random_unit(rng);
        c.check(list, tree, rt::ray(o, target - o), forward);
    }
    CHECK(c.mismatches == 0);
    CHECK(c.hits == c.rays);  // every ray passes through sphere k, if nothing nearer
}

TEST_CASE("bvh: coplanar quads (flat boxes in y = 0) from above, below and grazing", "[ch07]") {
    // A 20 x 20 grid of squares with gaps, all in the plane y = 0: every box is flat (zero
    // thickness, not padded), and every centroid has y = 0.
    object_list objects;
    for (int i = 0; i < 20; ++i)
        for (int j = 0; j < 20; ++j)
            objects.push_back(std::make_shared<rt::quad>(
                point3(real(i), 0, real(j)), vec3(0.875, 0, 0), vec3(0, 0, 0.875), own_material()));
    const rt::bvh tree(objects);
    check_shape(tree, objects);
    CHECK(tree.depth() < 3 * log2_ceil(objects.size()) + 4);
    const rt::hittable_list list = list_of(objects);
    rt::pcg32 rng(8, 8);
    comparison c;
    for (int i = 0; i < 20000; ++i) {
        const real x = uniform(rng, -1, 21), z = uniform(rng, -1, 21);
        const point3 target(x, 0, z);
        const real heading = uniform(rng, 0, 2 * rt::pi);
        // Angles to the plane from 90 degrees down to 1e-6 radians; the last tenth of the rays
        // lie in the plane itself, where every quad is parallel to the ray.
        const real angle = i % 10 == 9 ? 0 : std::pow(real(10), uniform(rng, -6, real(0.196)));
        const real side  = i % 2 ? 1 : -1;
        const vec3 d(std::cos(angle) * std::cos(heading), -side * std::sin(angle),
                     std::cos(angle) * std::sin(heading));
        c.check(list, tree, rt::ray(target - uniform(rng, real(0.1), 30) * d, d), forward);
    }
    CHECK(c.mismatches == 0);
    CHECK(c.hits > 10000);
}

TEST_CASE("bvh: boxes of zero thickness (flat, line and point boxes) build without dividing by 0",
          "[ch07]") {
    // Boxes are not padded, so they can be flat (a quad in a coordinate plane: the area of its
    // face), lines (a moving sphere much thinner than an ulp of its center, moving along an
    // axis) or points (such a sphere at rest: center -+ radius rounds to the center). A node
    // whose boxes all lie on one line, or are one point, has zero area, so every SAH cost is
    // 0 / 0 = NaN: no split may be chosen for it and nothing may loop; the builder splits such
    // a node at the median.
    const real r      = real(1e-30);
    auto point_sphere = [&](const point3& c) { return sphere_at(c, r); };
    auto line_sphere  = [&](const point3& c, real length) {
        return std::make_shared<rt::moving_sphere>(c, c + vec3(length, 0, 0), r, own_material());
    };
    // The boxes really are points and lines.
    REQUIRE(rt::bounded_object(point_sphere(point3(1.5, 2, 3))).box.half_area() == 0);
    REQUIRE(rt::bounded_object(line_sphere(point3(1.5, 2, 3), 1)).box.half_area() == 0);
    REQUIRE(rt::bounded_object(line_sphere(point3(1.5, 2, 3), 1)).box.x.size() == 1);

    // 300 points on one line along x: every node has zero area. Split at the median, the tree
    // is exactly as deep as halving 300 down to leaves of at most 4.
    object_list on_a_line;
    for (int i = 0; i < 300; ++i)
        on_a_line.push_back(point_sphere(point3(1 + real(0.5) * real(i), 2, 3)));
    const rt::bvh line_tree(on_a_line);
    check_shape(line_tree, on_a_line);
    CHECK(line_tree.bounding_box().half_area() == 0);
    CHECK(line_tree.depth() == log2_ceil(std::size_t(300 + 3) / 4) + 1);
    // 100 segments along one line (overlapping), and 100 identical points: zero area again,
    // and coincident centroids for the points.
    object_list segments, same_point;
    rt::pcg32 rng(16, 16);
    for (int i = 0; i < 100; ++i) {
        segments.push_back(line_sphere(point3(uniform(rng, 1, 10), -4, 5), uniform(rng, 0, 3)));
        same_point.push_back(point_sphere(point3(-2, 7, 1)));
    }
    for (const object_list* objects : {&segments, &same_point}) {
        const rt::bvh tree(*objects);
        check_shape(tree, *objects);
        CHECK(tree.bounding_box().half_area() == 0);
        CHECK(tree.depth() < 3 * log2_ceil(objects->size()) + 4);
    }

    // All kinds together with ordinary spheres: flat quads in the three coordinate planes,
    // points and lines; the same closest hits as the list. Rays aim at the spheres and quads,
    // not at the tiny spheres: only a ray through a tiny sphere's very center (one aimed at its
    // box) can hit it, and then p - center = 0 and the sphere's p and normal are NaN, a limit
    // of the sphere's own arithmetic (radius far below an ulp of its center), not of the tree.
    object_list mixed         = random_scene(rng, 200, layout::spread);
    std::vector<aabb> targets = boxes_of(mixed);
    for (int i = 0; i < 200; ++i) {
        const point3 c = random_point(rng, point3(0, 0, 0), 10);
        const int axis = i % 3;
        vec3 u(0, 0, 0), v(0, 0, 0);
        u[(axis + 1) % 3] = uniform(rng, real(0.2), 3);
        v[(axis + 2) % 3] = uniform(rng, real(0.2), 3);
        mixed.push_back(std::make_shared<rt::quad>(c, u, v, own_material()));
        targets.push_back(mixed.back().box);
        const point3 elsewhere = random_point(rng, point3(0, 0, 0), 10);
        if (i % 2)
            mixed.push_back(point_sphere(elsewhere));
        else
            mixed.push_back(line_sphere(elsewhere, uniform(rng, 0, 2)));
    }
    const rt::bvh tree(mixed);
    check_shape(tree, mixed);
    CHECK(tree.depth() < 3 * log2_ceil(mixed.size()) + 4);
    const rt::hittable_list list = list_of(mixed);
    const aabb bounds            = union_of(mixed);
    comparison c;
    for (long long i = 0; i < 20000; ++i) {
        auto [ray, ray_t] = random_ray(rng, bounds, targets, i);
        c.check(list, tree, ray, ray_t);
    }
    CHECK(c.mismatches == 0);
    CHECK(c.hits > 5000);
}

TEST_CASE("bvh: objects with empty boxes (empty bvhs) among others", "[ch07]") {
    // An empty bvh's box is empty and its centroid NaN; such an object can never be hit, and
    // must not disturb the build of the others.
    rt::pcg32 rng(9, 9);
    object_list objects = random_scene(rng, 50, layout::spread);
    objects.insert(objects.begin() + 10, std::make_shared<rt::bvh>(object_list{}));
    objects.push_back(std::make_shared<rt::bvh>(object_list{}));
    objects.insert(objects.begin(), std::make_shared<rt::bvh>(object_list{}));
    CHECK(std::isnan(objects.front().box.centroid().x()));
    const rt::bvh tree(objects);
    CHECK(tree.depth() < 64);
    const comparison c = compare_random(objects, 5000, 91);
    CHECK(c.mismatches == 0);
    CHECK(c.hits > 1000);
    // Only empty objects: nothing can be hit.
    const rt::bvh nothing(object_list{std::make_shared<rt::bvh>(object_list{}),
                                      std::make_shared<rt::bvh>(object_list{})});
    rt::hit_record rec;
    CHECK_FALSE(nothing.hit(rt::ray(point3(0, 0, 0), vec3(1, 1, 1)), interval::universe(), rec));
}

TEST_CASE("bvh: a bvh of bvhs answers as the flat list", "[ch07]") {
    rt::pcg32 rng(10, 10);
    object_list all, groups;
    for (int g = 0; g < 8; ++g) {
        object_list part = random_scene(rng, 40, g % 2 ? layout::clustered : layout::spread);
        all.insert(all.end(), part.begin(), part.end());
        groups.push_back(std::make_shared<rt::bvh>(part));
    }
    const rt::hittable_list flat = list_of(all);
    const rt::bvh nested(groups);
    rt::pcg32 rays(10, 11);
    comparison c;
    const aabb bounds             = union_of(all);
    const std::vector<aabb> boxes = boxes_of(all);
    for (long long i = 0; i < 5000; ++i) {
        auto [r, ray_t] = random_ray(rays, bounds, boxes, i);
        c.check(flat, nested, r, ray_t);
    }
    CHECK(c.mismatches == 0);
    CHECK(c.hits > 1000);
}

TEST_CASE("bvh: node count and depth are those of a balanced tree over random spheres", "[ch07]") {
    // A SAH tree over uniformly scattered spheres is close to balanced: about log2(n / leaf
    // size) levels. 3 log2(n) + 4 leaves room for SAH's uneven splits but not for a degenerate
    // chain (depth ~ n / 4).
    rt::pcg32 rng(12, 12);
    for (int n : {3, 10, 100, 1000, 10000}) {
        const object_list objects = random_scene(rng, n, layout::spread);
        const rt::bvh tree(objects);
        INFO(n << " spheres: depth " << tree.depth() << ", " << tree.node_count() << " nodes");
        check_shape(tree, objects);
        CHECK(tree.depth() >= log2_ceil(std::size_t(n + 3) / 4) + 1);
        CHECK(tree.depth() < 3 * log2_ceil(std::size_t(n)) + 4);
    }
}

TEST_CASE("bvh: a ray through a large scene tests few of its objects", "[ch07]") {
    // What the tree is for. Counting wrappers record every object test; over 10,000 spheres of
    // radius 0.05..2 in a 20-unit cube a ray tests about 8 of them (measured), not thousands.
    // 40 leaves room for another SAH variant, not for a tree that fails to cull.
    struct counted : rt::bounded_hittable {
        std::shared_ptr<rt::hittable> inner;
        aabb box;
        long long* tests;
        counted(const rt::bounded_object& o, long long* t)
            : inner(o.object), box(o.box), tests(t) {}
        bool hit(const rt::ray& r, interval ray_t, rt::hit_record& rec) const override {
            ++*tests;
            return inner->hit(r, ray_t, rec);
        }
        aabb bounding_box() const override { return box; }
    };
    long long tests = 0;
    rt::pcg32 rng(13, 13);
    object_list objects;
    for (auto& o : random_scene(rng, 10000, layout::spread))
        objects.push_back(std::make_shared<counted>(o, &tests));
    const rt::bvh tree(objects);
    const aabb bounds             = tree.bounding_box();
    const std::vector<aabb> boxes = boxes_of(objects);
    const int rays                = 2000;
    for (int i = 0; i < rays; ++i) {
        auto [r, ray_t] = random_ray(rng, bounds, boxes, i);
        rt::hit_record rec;
        tree.hit(r, ray_t, rec);
    }
    INFO("mean object tests per ray: " << double(tests) / rays);
    CHECK(tests < 40 * rays);
}
