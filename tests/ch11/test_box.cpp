// Tests for box.h (chapter 11): six quads whose normals u x v point out of the box, so a ray from
// outside sees front_face true and the outward normal, and one from inside sees every face's
// back. The box's corners are dyadic, so face centers and normals come out exactly.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "ch03/material_helpers.h"
#include "rt/core/error.h"
#include "rt/core/rng.h"
#include "rt/geometry/box.h"
#include "rt/scene/hittable_list.h"
#include "test_helpers.h"

namespace {

using rt::point3, rt::real, rt::vec3;

constexpr real eps = std::numeric_limits<real>::epsilon();
const rt::interval forward(0, rt::infinity);

using rt_test::any_material, rt_test::exactly, rt_test::random_unit;

// The box [-1, 1.5] x [0.5, 2] x [2, 3] (all three sides different) and its six faces.
const point3 lo(-1, 0.5, 2), hi(1.5, 2, 3);
const point3 center = 0.5 * (lo + hi);

struct face {
    vec3 normal;    // outward
    point3 middle;  // the face's center
};

std::vector<face> faces_of(const point3& a, const point3& b) {
    point3 c = 0.5 * (a + b);
    return {{vec3(1, 0, 0), point3(b.x(), c.y(), c.z())},
            {vec3(-1, 0, 0), point3(a.x(), c.y(), c.z())},
            {vec3(0, 1, 0), point3(c.x(), b.y(), c.z())},
            {vec3(0, -1, 0), point3(c.x(), a.y(), c.z())},
            {vec3(0, 0, 1), point3(c.x(), c.y(), b.z())},
            {vec3(0, 0, -1), point3(c.x(), c.y(), a.z())}};
}

point3 random_in_box(rt::pcg32& rng, const point3& a, const point3& b) {
    real x = a.x() + (b.x() - a.x()) * rng.uniform();
    real y = a.y() + (b.y() - a.y()) * rng.uniform();
    return point3(x, y, a.z() + (b.z() - a.z()) * rng.uniform());
}

}  // namespace

TEST_CASE("box: six faces, each hit at its center from outside with the outward normal", "[ch11]") {
    auto faces = rt::box_faces(lo, hi, any_material());
    REQUIRE(faces.size() == 6);
    auto b = rt::box(lo, hi, any_material());
    for (const face& f : faces_of(lo, hi)) {
        INFO("face with outward normal " << f.normal);
        // Straight in along -normal, and tilted (the tilt keeps the aim point on the face).
        for (const vec3& tilt : {vec3(0, 0, 0), vec3(0.25, -0.125, 0.5)}) {
            point3 origin = f.middle + 4 * f.normal + tilt;
            rt::ray r(origin, f.middle - origin);
            rt::hit_record rec;
            REQUIRE(b->hit(r, forward, rec));
            CHECK(rec.front_face);
            CHECK(exactly(rec.normal, f.normal));
            // Rounded at the scale of the coordinates (~4): 64 ulps of that is generous.
            CHECK((rec.p - f.middle).length() <= 64 * eps * 4);
            // Face by face: a line through a convex box crosses its surface twice, going in
            // (the nearest, this face, from the front) and coming out (from behind).
            int hit_faces = 0, entering = 0;
            real nearest       = rt::infinity;
            bool nearest_front = false;
            for (const auto& q : faces) {
                rt::hit_record one;
                if (!q.object->hit(r, forward, one)) continue;
                ++hit_faces;
                entering += one.front_face;
                if (one.t < nearest) {
                    nearest       = one.t;
                    nearest_front = one.front_face;
                }
            }
            CHECK(hit_faces == 2);
            CHECK(entering == 1);
            CHECK(nearest == rec.t);
            CHECK(nearest_front);
        }
    }
}

TEST_CASE("box: from inside every face is hit from behind (front_face false)", "[ch11]") {
    auto b = rt::box(lo, hi, any_material());
    for (const face& f : faces_of(lo, hi)) {
        INFO("face with outward normal " << f.normal);
        rt::hit_record rec;
        REQUIRE(b->hit(rt::ray(center, f.middle - center), forward, rec));
        CHECK_FALSE(rec.front_face);
        CHECK(exactly(rec.normal, -f.normal));  // facing the ray, against the outward normal
        CHECK(rec.t == 1);                      // the direction reaches the face center at t = 1
        CHECK(exactly(rec.p, f.middle));
    }
    // Random directions from random inside points: always one hit, always from behind.
    rt::pcg32 rng(11, 0);
    int wrong = 0;
    for (int k = 0; k < 10000; ++k) {
        rt::ray r(random_in_box(rng, lo, hi), random_unit(rng));
        rt::hit_record rec;
        if (!b->hit(r, forward, rec) || rec.front_face) ++wrong;
    }
    CHECK(wrong == 0);
}

TEST_CASE("box: a flat box (two corners sharing a coordinate) throws a user_error", "[ch11]") {
    auto m = any_material();
    CHECK_THROWS_AS(rt::box(point3(1, 0, 0), point3(1, 2, 3), m), rt::user_error);
    CHECK_THROWS_AS(rt::box(point3(0, 2, 0), point3(1, 2, 3), m), rt::user_error);
    CHECK_THROWS_AS(rt::box(point3(0, 0, -3), point3(1, 2, -3), m), rt::user_error);
    CHECK_THROWS_AS(rt::box(point3(1, 2, 3), point3(1, 2, 3), m), rt::user_error);
    CHECK_THROWS_AS(rt::box_faces(point3(1, 0, 0), point3(1, 2, 3), m), rt::user_error);
    CHECK_THROWS_WITH(rt::box(point3(1, 0, 0), point3(1, 2, 3), m),
                      Catch::Contains("box corners must differ in every coordinate (not a flat "
                                      "box), got (1, 0, 0) and (1, 2, 3)"));
    const real nan = std::numeric_limits<real>::quiet_NaN();
    CHECK_THROWS_AS(rt::box(point3(nan, 0, 0), point3(1, 2, 3), m), rt::user_error);
    CHECK_NOTHROW(rt::box(point3(0, 0, 0), point3(real(1e-6), 2, 3), m));
}

TEST_CASE("box: corners given in any order make the same box", "[ch11]") {
    // All eight ways to take each coordinate from one corner or the other name the same box.
    auto reference = rt::box(lo, hi, any_material());
    std::vector<std::shared_ptr<rt::bvh>> variants;
    for (int mask = 1; mask < 8; ++mask) {
        point3 a(mask & 1 ? hi.x() : lo.x(), mask & 2 ? hi.y() : lo.y(),
                 mask & 4 ? hi.z() : lo.z());
        point3 b(mask & 1 ? lo.x() : hi.x(), mask & 2 ? lo.y() : hi.y(),
                 mask & 4 ? lo.z() : hi.z());
        variants.push_back(rt::box(a, b, any_material()));
    }
    rt::pcg32 rng(12, 0);
    int hits = 0, mismatches = 0;
    for (int k = 0; k < 2000; ++k) {
        // From a sphere of radius 4 around the box toward a random point near it.
        point3 origin = center + 4 * random_unit(rng);
        point3 target = random_in_box(rng, lo - vec3(0.5, 0.5, 0.5), hi + vec3(0.5, 0.5, 0.5));
        rt::ray r(origin, target - origin);
        rt::hit_record want;
        bool hit = reference->hit(r, forward, want);
        hits += hit;
        for (const auto& v : variants) {
            rt::hit_record got;
            bool same = v->hit(r, forward, got) == hit;
            if (hit && same)
                same = got.t == want.t && exactly(got.p, want.p) &&
                       exactly(got.normal, want.normal) && got.front_face == want.front_face;
            mismatches += !same;
        }
    }
    INFO(hits << " of 2000 rays hit");
    CHECK(hits > 500);
    CHECK(mismatches == 0);
}

TEST_CASE("box: box() (a BVH of the faces) and box_faces() in a list find the same closest hits",
          "[ch11]") {
    rt::pcg32 rng(13, 0);
    // A second, elongated box far from the origin checks the same at another scale.
    const point3 far_lo(300, -200, 1000), far_hi(300.5, -150, 1064);
    for (const auto& corners : {std::pair(lo, hi), std::pair(far_lo, far_hi)}) {
        const point3 a = corners.first, b = corners.second;
        auto bvh_box = rt::box(a, b, any_material());
        rt::hittable_list list;
        for (const auto& f : rt::box_faces(a, b, any_material())) list.add(f.object);
        const point3 c   = 0.5 * (a + b);
        const real reach = (b - a).length();
        int hits = 0, mismatches = 0;
        std::string first;
        for (int k = 0; k < 10000; ++k) {
            // Half the rays start outside, half inside; they aim at points in and around the box.
            point3 origin = k % 2 == 0 ? c + reach * random_unit(rng) : random_in_box(rng, a, b);
            point3 target = random_in_box(rng, a - (b - a) / 4, b + (b - a) / 4);
            rt::ray r(origin, target - origin);
            rt::hit_record x, y;
            bool hx = bvh_box->hit(r, forward, x), hy = list.hit(r, forward, y);
            hits += hx;
            // Identical quads compute identical hits: the nearest one must match bit for bit.
            bool same =
                hx == hy && (!hx || (x.t == y.t && exactly(x.p, y.p) &&
                                     exactly(x.normal, y.normal) && x.front_face == y.front_face));
            if (!same && mismatches++ == 0) {
                std::ostringstream what;
                what.precision(17);
                what << "ray " << r.origin() << " -> " << r.direction() << ": bvh " << hx << " t "
                     << x.t << ", list " << hy << " t " << y.t;
                first = what.str();
            }
        }
        INFO("box " << a << " to " << b << ": " << hits << " of 10000 rays hit; " << mismatches
                    << " mismatches, first: " << first);
        CHECK(hits > 5000);
        CHECK(mismatches == 0);
    }
}

TEST_CASE("box: its bounding box is the box, widened only by the faces' padding", "[ch11]") {
    // Each face's own box is flat and aabb pads a flat axis to 1e-4 (aabb.h), so the union may
    // reach 5e-5 past each side of the box, but never less than the box itself. The faces'
    // boxes together make the same box as the BVH of them.
    auto b      = rt::box(lo, hi, any_material());
    rt::aabb bb = b->bounding_box();
    rt::aabb faces;
    for (const auto& f : rt::box_faces(lo, hi, any_material())) faces = rt::aabb(faces, f.box);
    for (int axis = 0; axis < 3; ++axis) {
        CHECK(faces.axis_interval(axis).min == bb.axis_interval(axis).min);
        CHECK(faces.axis_interval(axis).max == bb.axis_interval(axis).max);
    }
    const real padding = real(1e-4) / 2 * real(1 + 1e-3);  // half the pad, plus its rounding
    for (int axis = 0; axis < 3; ++axis) {
        INFO("axis " << axis);
        const rt::interval& i = bb.axis_interval(axis);
        CHECK(i.min <= lo[axis]);
        CHECK(i.min >= lo[axis] - padding);
        CHECK(i.max >= hi[axis]);
        CHECK(i.max <= hi[axis] + padding);
    }
}
