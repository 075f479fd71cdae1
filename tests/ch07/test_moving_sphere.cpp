// Tests for moving_sphere.h (chapter 07). The center moves linearly, C(t) = C0 + t (C1 - C0),
// over the shutter interval [0, 1]; a ray carries the time it travels at, and meets the sphere
// where it is at that time. Both ends are exact, so at times 0 and 1 the moving sphere answers
// bit for bit as a static sphere at C0 or C1; its box holds it at every time.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>

#include "ch03/material_helpers.h"
#include "rt/accel/bounded.h"
#include "rt/core/error.h"
#include "rt/core/rng.h"
#include "rt/geometry/moving_sphere.h"
#include "rt/geometry/sphere.h"
#include "test_helpers.h"

namespace {

using rt::point3, rt::real, rt::vec3;

constexpr real eps = std::numeric_limits<real>::epsilon();
const rt::interval forward(0, rt::infinity);

using rt_test::any_material, rt_test::exactly, rt_test::random_in_cube, rt_test::random_unit,
    rt_test::uniform;

rt::moving_sphere make_moving(const point3& c0, const point3& c1, real radius) {
    return rt::moving_sphere(c0, c1, radius, any_material());
}

// Distance of p from the surface of the sphere (center, radius).
real off_surface(const point3& p, const point3& center, real radius) {
    return std::fabs((p - center).length() - radius);
}

// A point with full-precision coordinates (53 random bits for a double; uniform() alone has
// 32, and the difference of two such numbers is always exact in a double, which would hide the
// rounding of C1 - C0) at magnitudes from 1e-3 to 1e3, so that the two ends of a motion often
// differ by more than a factor 2, where C1 - C0 is rounded.
point3 full_precision_point(rt::pcg32& rng) {
    point3 p;
    for (int a = 0; a < 3; ++a) {
        const double high = rng.next_u32(), low = rng.next_u32();
        const double unit      = (high + low * 0x1p-32) * 0x1p-32;  // in [0, 1)
        const double magnitude = std::pow(10.0, double(rng.next_u32() % 7) - 3);
        p[a]                   = real((2 * unit - 1) * magnitude);
    }
    return p;
}

// Whether box holds the ball (center, radius), compared exactly: the box's ends are
// min(C0, C1) - r and max(C0, C1) + r, rounded the same way as center - r and center + r.
bool holds(const rt::aabb& box, const point3& center, real radius) {
    for (int a = 0; a < 3; ++a) {
        const rt::interval& slab = box.axis_interval(a);
        if (!(slab.min <= center[a] - radius && center[a] + radius <= slab.max)) return false;
    }
    return true;
}

// Whether two hit records agree in every field a shape fills, bit for bit.
bool same_hit(const rt::hit_record& a, const rt::hit_record& b) {
    return a.t == b.t && exactly(a.p, b.p) && exactly(a.normal, b.normal) &&
           a.front_face == b.front_face && a.p_error == b.p_error && a.mat == b.mat;
}

}  // namespace

TEST_CASE("moving_sphere: the center is C0 at time 0, C1 at time 1 and halfway at 0.5", "[ch07]") {
    // Dyadic centers: every step is exact.
    auto s = make_moving(point3(1, 2, 3), point3(3, -2, 4.5), 1);
    CHECK(exactly(s.center_at(0), point3(1, 2, 3)));
    CHECK(exactly(s.center_at(1), point3(3, -2, 4.5)));
    CHECK(exactly(s.center_at(0.5), point3(2, 0, 3.75)));
    CHECK(exactly(s.center_at(0.25), point3(1.5, 1, 3.375)));
    // A sphere whose ends coincide never moves, at any time (its velocity is exactly 0).
    const point3 somewhere(real(0.1), real(-0.7), real(0.3));
    auto still = make_moving(somewhere, somewhere, 1);
    for (real t : {real(0), real(0.3), real(0.5), real(0.999), real(1)})
        CHECK(exactly(still.center_at(t), somewhere));

    // Random centers of all magnitudes: the ends are exact though C1 - C0 is rounded (the book's
    // C0 + 1 (C1 - C0) misses C1 by an ulp in 8 of 10 of these). The midpoint takes two
    // roundings, in C1 - C0 and in the sum: within an ulp of |C0| + |C1| of (C0 + C1) / 2.
    rt::pcg32 rng(70, 1);
    int wrong_ends = 0, wrong_middle = 0;
    for (int i = 0; i < 10000; ++i) {
        const point3 c0 = full_precision_point(rng), c1 = full_precision_point(rng);
        auto m = make_moving(c0, c1, 1);
        if (!exactly(m.center_at(0), c0) || !exactly(m.center_at(1), c1)) ++wrong_ends;
        const point3 mid = m.center_at(0.5);
        for (int a = 0; a < 3; ++a) {
            const real exact_mid = (c0[a] + c1[a]) / 2;
            if (std::fabs(mid[a] - exact_mid) > eps * (std::fabs(c0[a]) + std::fabs(c1[a])))
                ++wrong_middle;
        }
    }
    CHECK(wrong_ends == 0);
    CHECK(wrong_middle == 0);
}

TEST_CASE("moving_sphere: a ray at time t hits the sphere where it is at t, not where it was",
          "[ch07]") {
    // From (0,0,0) at time 0 to (0,4,0) at time 1, radius 1. A ray along +z at height y = 2
    // meets the center at time 0.5 head-on (t = 4, as for the static sphere), and passes 2
    // radii away from it at times 0 and 1.
    auto s = make_moving(point3(0, 0, 0), point3(0, 4, 0), 1);
    const point3 origin(0, 2, -5);
    const vec3 plus_z(0, 0, 1);
    rt::hit_record rec;
    REQUIRE(s.hit(rt::ray(origin, plus_z, 0.5), forward, rec));
    CHECK(rec.t == 4);
    CHECK(exactly(rec.p, point3(0, 2, -1)));
    CHECK(exactly(rec.normal, vec3(0, 0, -1)));
    CHECK_FALSE(s.hit(rt::ray(origin, plus_z, 0), forward, rec));
    CHECK_FALSE(s.hit(rt::ray(origin, plus_z, 1), forward, rec));
    // A ray without a time is at time 0: where the sphere starts.
    CHECK_FALSE(s.hit(rt::ray(origin, plus_z), forward, rec));
    REQUIRE(s.hit(rt::ray(point3(0, 0, -5), plus_z), forward, rec));
    CHECK(rec.t == 4);
    // At time 0.375 the center is at y = 1.5: the ray passes 0.5 from it, t = 5 - sqrt(0.75).
    REQUIRE(s.hit(rt::ray(origin, plus_z, 0.375), forward, rec));
    CHECK(rec.t == Approx(5 - std::sqrt(real(0.75))).epsilon(4 * eps));

    // Random motions and times. A ray aimed within 0.9 r of the center at time t hits, on the
    // sphere as it is at t. At another random time the same ray must hit exactly when its line
    // passes within r of the center at that time (ahead of the origin, which is outside):
    // checked where the distance is clearly below or above r (by 1e-6 r).
    rt::pcg32 rng(71, 2);
    int missed = 0, off = 0, wrong_other = 0, other_hits = 0, other_misses = 0;
    for (int i = 0; i < 5000; ++i) {
        const point3 c0 = random_in_cube(rng, 5), c1 = random_in_cube(rng, 5);
        const real radius = uniform(rng, real(0.1), 1);
        auto m            = make_moving(c0, c1, radius);
        const real t      = rng.uniform();
        const point3 c    = m.center_at(t);
        const real away   = uniform(rng, 2, 10);
        const point3 o    = c + away * radius * random_unit(rng);
        const vec3 d      = c + real(0.9) * radius * random_unit(rng) - o;
        if (!m.hit(rt::ray(o, d, t), forward, rec)) {
            ++missed;
        } else if (off_surface(rec.p, c, radius) > rec.p_error) {
            ++off;
        }
        const real other        = rng.uniform();
        const vec3 to_center    = m.center_at(other) - o;
        const real along        = dot(to_center, d) / dot(d, d);
        const real distance     = (to_center - along * d).length();
        const bool origin_out   = to_center.length() > radius * (1 + real(1e-6));
        const bool clearly_hit  = origin_out && along > 0 && distance < radius * (1 - real(1e-6));
        const bool clearly_miss = origin_out && distance > radius * (1 + real(1e-6));
        if (!clearly_hit && !clearly_miss) continue;
        (clearly_hit ? other_hits : other_misses) += 1;
        if (m.hit(rt::ray(o, d, other), forward, rec) != clearly_hit) ++wrong_other;
    }
    CHECK(missed == 0);
    CHECK(off == 0);
    CHECK(wrong_other == 0);
    CHECK(other_hits > 100);  // both outcomes are well represented
    CHECK(other_misses > 1000);
}

TEST_CASE(
    "moving_sphere: at times 0 and 1 (and any t) it is hit bit for bit as a static sphere "
    "at C0, C1 (and C(t))",
    "[ch07]") {
    // Both share hit_sphere(), and center_at() returns the ends exactly, so a moving sphere
    // photographed at time 0 or 1 is the static sphere there, to the last bit: t, p, normal,
    // front face, error bound and material. At a time in between, the static sphere at C(t).
    rt::pcg32 rng(73, 4);
    int hits = 0, misses = 0, differ = 0;
    for (int i = 0; i < 6000; ++i) {
        const point3 c0 = full_precision_point(rng), c1 = full_precision_point(rng);
        const real radius = uniform(rng, real(0.01), 3);
        const auto mat    = any_material();
        const rt::moving_sphere m(c0, c1, radius, mat);
        const real time = i % 3 == 0 ? real(0) : (i % 3 == 1 ? real(1) : rng.uniform());
        const point3 c  = i % 3 == 0 ? c0 : (i % 3 == 1 ? c1 : m.center_at(time));
        const rt::sphere still(c, radius, mat);
        // From outside or inside, aimed near the sphere (half of the rays miss it).
        const point3 o =
            c + (i % 4 == 0 ? real(0.5) : uniform(rng, 2, 20)) * radius * random_unit(rng);
        const vec3 d = c + real(1.8) * radius * random_unit(rng) - o;
        const rt::ray r(o, d, time);
        rt::hit_record a, b;
        const bool ha = m.hit(r, forward, a), hb = still.hit(r, forward, b);
        (ha ? hits : misses) += 1;
        if (ha != hb || (ha && !same_hit(a, b))) ++differ;
    }
    INFO(hits << " hits, " << misses << " misses");
    CHECK(differ == 0);
    CHECK(hits > 1000);
    CHECK(misses > 1000);
}

TEST_CASE("moving_sphere: the bounding box holds the sphere at every time", "[ch07]") {
    rt::pcg32 rng(72, 3);
    int not_held = 0, not_tight = 0;
    for (int i = 0; i < 2000; ++i) {
        const point3 c0 = full_precision_point(rng), c1 = full_precision_point(rng);
        const real radius  = uniform(rng, real(0.01), 3);
        auto m             = make_moving(c0, c1, radius);
        const rt::aabb box = m.bounding_box();
        // Both ends and 64 times in between, including the ends of the shutter.
        for (int k = 0; k <= 64; ++k) {
            const real t = k == 64 ? real(1) : (real(k) + rng.uniform()) / 64;
            if (!holds(box, m.center_at(t), radius)) ++not_held;
        }
        if (!holds(box, c0, radius) || !holds(box, c1, radius)) ++not_held;
        // And no bigger than that (the box of both end spheres, exactly).
        for (int a = 0; a < 3; ++a) {
            if (box.axis_interval(a).min != std::min(c0[a], c1[a]) - radius ||
                box.axis_interval(a).max != std::max(c0[a], c1[a]) + radius)
                ++not_tight;
        }
    }
    CHECK(not_held == 0);
    CHECK(not_tight == 0);
    // A static sphere's box is center -+ radius.
    const rt::aabb still = rt::bounding_box(rt::sphere(point3(1, -2, 3), 0.5, any_material()));
    CHECK(still.x.min == 0.5);
    CHECK(still.x.max == 1.5);
    CHECK(still.y.min == -2.5);
    CHECK(still.z.max == 3.5);
}

TEST_CASE("moving_sphere: a radius that is not positive and finite, or no material, throws",
          "[ch07]") {
    const real nan = std::numeric_limits<real>::quiet_NaN();
    for (real bad : {real(0), real(-1), nan, rt::infinity}) {
        INFO("radius " << bad);
        CHECK_THROWS_WITH(make_moving(point3(0, 0, 0), point3(1, 0, 0), bad),
                          Catch::Contains("sphere radius must be positive and finite"));
    }
    CHECK_THROWS_AS(rt::moving_sphere(point3(0, 0, 0), point3(1, 0, 0), 1, nullptr),
                    rt::user_error);
}
