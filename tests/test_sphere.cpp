// Tests for sphere.h (chapter 02). First the exact cases of The Ray Tracer Challenge, where every
// number is representable and the solver must return it bit for bit; then [hardcase] tests of the
// stable solver (Ray Tracing Gems ch. 7) on distant, tiny, huge and grazing spheres.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>

#include "common/error.h"
#include "common/lambertian.h"
#include "common/normal_shading.h"
#include "common/rng.h"
#include "common/sampling.h"
#include "common/sphere.h"
#include "test_helpers.h"

namespace {

using rt::point3, rt::real, rt::vec3;

constexpr real eps = std::numeric_limits<real>::epsilon();
const rt::interval forward(0, rt::infinity);

rt::sphere make_sphere(const point3& center, real radius) {
    return rt::sphere(center, radius, std::make_shared<rt::normal_shading>());
}

using rt_test::exactly, rt_test::random_in_cube, rt_test::random_tangent, rt_test::random_unit,
    rt_test::uniform;

bool finite(const vec3& v) {
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

// Every field of a hit record is a number, and the normal is a unit vector (4 ulps: one rounding
// in each of the three squares, their sum and the division that normalized it).
bool well_formed(const rt::hit_record& rec) {
    return finite(rec.p) && finite(rec.normal) && std::isfinite(rec.t) &&
           std::isfinite(rec.p_error) && rec.p_error >= 0 && rec.mat != nullptr &&
           std::fabs(rec.normal.length() - 1) <= 4 * eps;
}

// A record holding values no hit produces, to see that a miss leaves it untouched.
rt::hit_record sentinel() {
    rt::hit_record rec;
    rec.p          = point3(7, 7, 7);
    rec.normal     = vec3(0, 0, 7);
    rec.t          = -123;
    rec.p_error    = 42;
    rec.front_face = false;
    return rec;
}

bool is_sentinel(const rt::hit_record& rec) {
    return exactly(rec.p, point3(7, 7, 7)) && exactly(rec.normal, vec3(0, 0, 7)) && rec.t == -123 &&
           rec.p_error == 42 && !rec.front_face && rec.mat == nullptr;
}

// Distance of p from the surface of the sphere (center, radius).
real off_surface(const point3& p, const point3& center, real radius) {
    return std::fabs((p - center).length() - radius);
}

// The hard cases reach 1e6..1e7 radii and margins of 1e-6 radii, beyond float's 24 bits (its
// ulp at 1e6 is 0.06): they test the double build, the default. A float build (RT_SCALAR=float)
// says so instead of failing on arithmetic it cannot do.
using rt_test::needs_double;

}  // namespace

TEST_CASE("sphere: a ray through the center hits at t = 4, and at the far root 6 past it",
          "[ch02]") {
    auto s = make_sphere(point3(0, 0, 0), 1);
    rt::ray r(point3(0, 0, -5), vec3(0, 0, 1));

    rt::hit_record rec;
    REQUIRE(s.hit(r, forward, rec));
    CHECK(rec.t == 4);
    CHECK(exactly(rec.p, point3(0, 0, -1)));
    CHECK(exactly(rec.normal, vec3(0, 0, -1)));
    CHECK(rec.front_face);
    CHECK(rec.mat != nullptr);

    // interval::surrounds is open, so (4, inf) excludes the near root itself.
    for (real t_min : {real(4), real(4.5)}) {
        INFO("t_min = " << t_min);
        REQUIRE(s.hit(r, rt::interval(t_min, rt::infinity), rec));
        CHECK(rec.t == 6);
        CHECK(exactly(rec.p, point3(0, 0, 1)));
        CHECK_FALSE(rec.front_face);                 // leaving the sphere
        CHECK(exactly(rec.normal, vec3(0, 0, -1)));  // still faces the ray
    }
    rec = sentinel();
    CHECK_FALSE(s.hit(r, rt::interval(6, rt::infinity), rec));
    CHECK(is_sentinel(rec));
}

TEST_CASE("sphere: tangent hit gives t = 5 twice", "[ch02]") {
    auto s = make_sphere(point3(0, 0, 0), 1);
    rt::ray r(point3(0, 1, -5), vec3(0, 0, 1));

    rt::hit_record rec;
    REQUIRE(s.hit(r, forward, rec));
    CHECK(rec.t == 5);
    CHECK(exactly(rec.p, point3(0, 1, 0)));
    CHECK(well_formed(rec));
    // Both roots are 5: nothing before it and nothing after it.
    CHECK_FALSE(s.hit(r, rt::interval(0, 5), rec));
    CHECK_FALSE(s.hit(r, rt::interval(5, rt::infinity), rec));
}

TEST_CASE("sphere: a ray starting inside hits the far root 1, not the root -1 behind it",
          "[ch02]") {
    auto s = make_sphere(point3(0, 0, 0), 1);
    rt::ray r(point3(0, 0, 0), vec3(0, 0, 1));

    rt::hit_record rec;
    REQUIRE(s.hit(r, rt::interval::universe(), rec));
    CHECK(rec.t == -1);  // the near root exists...
    REQUIRE(s.hit(r, forward, rec));
    CHECK(rec.t == 1);  // ...but lies behind the origin
    CHECK(exactly(rec.p, point3(0, 0, 1)));
    CHECK_FALSE(rec.front_face);
    CHECK(exactly(rec.normal, vec3(0, 0, -1)));
    CHECK(dot(rec.normal, r.direction()) < 0);
}

TEST_CASE("sphere: a sphere behind the ray is missed, and a miss leaves the record alone",
          "[ch02]") {
    auto s             = make_sphere(point3(0, 0, 0), 1);
    rt::hit_record rec = sentinel();
    CHECK_FALSE(s.hit(rt::ray(point3(0, 0, 5), vec3(0, 0, 1)), forward, rec));  // roots -6, -4
    CHECK(is_sentinel(rec));
    CHECK_FALSE(s.hit(rt::ray(point3(0, 2, -5), vec3(0, 0, 1)), forward, rec));  // clear miss
    CHECK(is_sentinel(rec));
    CHECK_FALSE(s.hit(rt::ray(point3(0, 0, -5), vec3(0, 0, 1)), rt::interval(0, 4), rec));
    CHECK(is_sentinel(rec));
}

TEST_CASE("sphere: a ray starting on the sphere along its tangent plane has both roots 0",
          "[ch02]") {
    // q = 0 in the solver: c / q would be 0 / 0 without its guard.
    auto s = make_sphere(point3(0, 0, 0), 1);
    rt::ray r(point3(1, 0, 0), vec3(0, 1, 0));
    rt::hit_record rec = sentinel();
    CHECK_FALSE(s.hit(r, forward, rec));
    CHECK(is_sentinel(rec));
    REQUIRE(s.hit(r, rt::interval::universe(), rec));
    CHECK(rec.t == 0);
    CHECK(exactly(rec.p, point3(1, 0, 0)));
    CHECK(well_formed(rec));
}

TEST_CASE("sphere: scaling the direction scales t and keeps the hit point", "[ch02]") {
    auto s = make_sphere(point3(0, 0, 0), 1);
    for (real k : {real(1e-3), real(0.25), real(3), real(1e3)}) {
        INFO("k = " << k);
        rt::hit_record rec;
        REQUIRE(s.hit(rt::ray(point3(0, 0, -5), vec3(0, 0, k)), forward, rec));
        CHECK(rec.t * k == Approx(4).epsilon(2 * eps));  // one rounding in 4 / k, one in t * k
        CHECK(exactly(rec.p, point3(0, 0, -1)));
    }

    // An oblique ray: every scaling gives the same point up to the rounding of r.at(t) and of
    // the projection onto the sphere, a few ulps of the unit sphere. 16 eps leaves room for that.
    rt::ray unit_ray(point3(0.3, -0.2, -5),
                     rt::unit_vector(vec3(0.2, 0.45, 0.1) - point3(0.3, -0.2, -5)));
    rt::hit_record reference;
    REQUIRE(s.hit(unit_ray, forward, reference));
    for (real k : {real(1e-3), real(0.25), real(3), real(1e3)}) {
        INFO("k = " << k);
        rt::hit_record rec;
        REQUIRE(s.hit(rt::ray(unit_ray.origin(), k * unit_ray.direction()), forward, rec));
        CHECK((rec.p - reference.p).length() <= 16 * eps);
        CHECK(rec.t * k == Approx(reference.t).epsilon(16 * eps));
        CHECK((rec.normal - reference.normal).length() <= 16 * eps);
    }
}

TEST_CASE("sphere: the hit point lies on the surface within the record's own error bound",
          "[ch02]") {
    // p_error is what spawn_ray trusts: it must bound the distance of p from the true sphere.
    rt::pcg32 rng(7, 11);
    const point3 center(1.5, -2, 0.5);
    const real radius = 0.75;
    auto s            = make_sphere(center, radius);
    int hits = 0, off = 0, malformed = 0, not_facing = 0;
    for (int i = 0; i < 2000; ++i) {
        real distance = uniform(rng, 1, 10) * radius;
        point3 origin = center + distance * random_unit(rng);
        point3 target = center + random_in_cube(rng, real(1.2) * radius);
        rt::ray r(origin, target - origin);
        rt::hit_record rec;
        if (!s.hit(r, forward, rec)) continue;
        ++hits;
        if (off_surface(rec.p, center, radius) > rec.p_error) ++off;
        if (!well_formed(rec)) ++malformed;
        if (!(dot(rec.normal, r.direction()) < 0)) ++not_facing;
    }
    INFO(hits << " hits: " << off << " off the surface, " << malformed << " malformed, "
              << not_facing << " with a normal not facing the ray");
    CHECK(hits > 1000);
    CHECK(off == 0);
    CHECK(malformed == 0);
    CHECK(not_facing == 0);
}

TEST_CASE("sphere: a radius that is not positive and finite throws a user_error naming it",
          "[ch02]") {
    const real nan = std::numeric_limits<real>::quiet_NaN();
    for (real radius : {real(0), real(-0.0), real(-2.5), nan, rt::infinity, -rt::infinity}) {
        std::ostringstream printed;
        printed << radius;
        INFO("radius = " << printed.str());
        std::string message;
        try {
            make_sphere(point3(0, 0, 0), radius);
        } catch (const rt::user_error& e) {
            message = e.what();
        }
        CHECK_THAT(message, Catch::Contains("radius") && Catch::Contains(printed.str()));
    }
    CHECK_THROWS_AS(rt::sphere(point3(0, 0, 0), 1, nullptr), rt::user_error);
    CHECK_NOTHROW(make_sphere(point3(0, 0, 0), std::numeric_limits<real>::min()));
}

// ---------------------------------------------------------------------------------------------
// Hard cases. The book's quadratic b^2 - a c subtracts two numbers of size (D/r)^2 r^2 to get
// one of size r^2, so at D = 1e6 radii its discriminant carries an error of about
// eps (D/r)^2 ~ 2e-4 (relative to r^2), which moves the hit point by ~1e-4 r and turns a 1e-6
// grazing margin into noise. The stable form takes the discriminant from the perpendicular
// distance f_perp, whose error is ~eps D: 2e-10 r at 1e6 radii, four orders below every
// threshold here. The thresholds (1e-4 r for the hit point, 1 -/+ 1e-6 for grazing rays) are set
// where the stable solver has that margin and the book's does not.

TEST_CASE(
    "sphere: seen from 1e4 to 1e6 radii, aimed rays hit where aimed and off-center rays "
    "miss",
    "[hardcase][ch02]") {
    if (needs_double()) return;
    rt::pcg32 rng(2024, 5);
    for (real radius : {real(1e-4), real(1), real(1e4)}) {
        for (real distance : {real(1e4), real(1e5), real(1e6)}) {
            const point3 center = random_in_cube(rng, 10 * radius);
            auto s              = make_sphere(center, radius);
            int trials = 0, aimed_missed = 0, far_from_aim = 0, off = 0, malformed = 0;
            int inside_missed = 0, outside_hit = 0;
            real worst_aim_error = 0;
            for (int i = 0; i < 1000; ++i, ++trials) {
                vec3 toward_eye = random_unit(rng);
                point3 eye      = center + distance * radius * toward_eye;

                // A point of the visible cap with dot(n, toward_eye) >= 0.45: its distance from
                // the silhouette's axis is at most sqrt(1 - 0.45^2) = 0.89 r, well inside.
                vec3 n = random_unit(rng);
                while (dot(n, toward_eye) < real(0.45)) n = random_unit(rng);
                point3 aim = center + radius * n;
                rt::hit_record rec;
                if (!s.hit(rt::ray(eye, aim - eye), forward, rec)) {
                    ++aimed_missed;
                } else {
                    real error      = (rec.p - aim).length() / radius;
                    worst_aim_error = std::fmax(worst_aim_error, error);
                    if (!(error <= real(1e-4))) ++far_from_aim;
                    if (off_surface(rec.p, center, radius) > rec.p_error) ++off;
                    if (!well_formed(rec) || !rec.front_face) ++malformed;
                }

                // Aim 0.99 and 1.01 radii off the center, across the line of sight.
                vec3 across = random_tangent(rng, toward_eye);
                point3 in   = center + real(0.99) * radius * across;
                point3 out  = center + real(1.01) * radius * across;
                if (!s.hit(rt::ray(eye, in - eye), forward, rec))
                    ++inside_missed;
                else if (!well_formed(rec))
                    ++malformed;
                if (s.hit(rt::ray(eye, out - eye), forward, rec)) ++outside_hit;
            }
            INFO("radius " << radius << ", seen from " << distance << " radii, " << trials
                           << " trials: aimed rays missed " << aimed_missed << ", hit > 1e-4 r "
                           << "from the aim " << far_from_aim << " (worst " << worst_aim_error
                           << " r), off the surface " << off << "; 0.99 r missed " << inside_missed
                           << ", 1.01 r hit " << outside_hit << "; malformed " << malformed);
            CHECK(aimed_missed == 0);
            CHECK(far_from_aim == 0);
            CHECK(off == 0);
            CHECK(inside_missed == 0);
            CHECK(outside_hit == 0);
            CHECK(malformed == 0);
        }
    }
}

TEST_CASE("sphere: grazing rays 1e-6 inside the silhouette hit and 1e-6 outside miss",
          "[hardcase][ch02]") {
    if (needs_double()) return;
    // The ray's distance from the center is k r with k = 1 -/+ 1e-6 (less a relative
    // k^2 / (2 D^2) <= 5e-9 for the line not being exactly perpendicular). Rounding the eye's
    // coordinates moves the line by ~eps D r <= 2e-10 r: far below the 1e-6 r margin.
    rt::pcg32 rng(99, 3);
    for (real radius : {real(1e-4), real(1), real(1e4)}) {
        for (real distance : {real(1e4), real(1e5), real(1e6)}) {
            const point3 center = random_in_cube(rng, 3 * radius);
            auto s              = make_sphere(center, radius);
            int grazing_missed = 0, grazing_outside_hit = 0, off = 0, malformed = 0;
            for (int i = 0; i < 1000; ++i) {
                vec3 toward_eye = random_unit(rng);
                point3 eye      = center + distance * radius * toward_eye;
                vec3 across     = random_tangent(rng, toward_eye);
                point3 in       = center + (1 - real(1e-6)) * radius * across;
                point3 out      = center + (1 + real(1e-6)) * radius * across;
                rt::hit_record rec;
                if (!s.hit(rt::ray(eye, in - eye), forward, rec)) {
                    ++grazing_missed;
                } else {
                    if (off_surface(rec.p, center, radius) > rec.p_error) ++off;
                    if (!well_formed(rec)) ++malformed;
                }
                if (s.hit(rt::ray(eye, out - eye), forward, rec)) ++grazing_outside_hit;
            }
            INFO("radius " << radius << ", seen from " << distance << " radii: grazing rays "
                           << "inside missed " << grazing_missed << ", outside hit "
                           << grazing_outside_hit << ", hit points off the surface " << off
                           << ", malformed " << malformed);
            CHECK(grazing_missed == 0);
            CHECK(grazing_outside_hit == 0);
            CHECK(off == 0);
            CHECK(malformed == 0);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Chapter 07: moving spheres. The center moves linearly, C(t) = C0 + t (C1 - C0), over the
// shutter interval [0, 1]; a ray carries the time it travels at.

namespace {

rt::sphere make_moving(const point3& c0, const point3& c1, real radius) {
    return rt::sphere(c0, c1, radius, std::make_shared<rt::normal_shading>());
}

// A texture that reads (u, v), so a sphere made of it computes them on every hit (spheres skip
// that work for materials that never look at (u, v)).
struct uv_reading_texture : rt::texture {
    rt::color value(real u, real v, const point3&) const override { return rt::color(u, v, 0); }
    bool uses_uv() const override { return true; }
};

rt::sphere make_textured_moving(const point3& c0, const point3& c1, real radius) {
    return rt::sphere(c0, c1, radius,
                      std::make_shared<rt::lambertian>(std::make_shared<uv_reading_texture>()));
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

}  // namespace

TEST_CASE("sphere: a moving center is C0 at time 0, C1 at time 1 and halfway at 0.5", "[ch07]") {
    // Dyadic centers: every step is exact.
    auto s = make_moving(point3(1, 2, 3), point3(3, -2, 4.5), 1);
    CHECK(exactly(s.center_at(0), point3(1, 2, 3)));
    CHECK(exactly(s.center_at(1), point3(3, -2, 4.5)));
    CHECK(exactly(s.center_at(0.5), point3(2, 0, 3.75)));
    CHECK(exactly(s.center_at(0.25), point3(1.5, 1, 3.375)));
    // A static sphere never moves, at any time (its velocity is exactly 0).
    const point3 somewhere(real(0.1), real(-0.7), real(0.3));
    auto still = make_sphere(somewhere, 1);
    for (real t : {real(0), real(0.3), real(0.999), real(1)})
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

TEST_CASE("sphere: a ray at time t hits the sphere where it is at t, not where it was", "[ch07]") {
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

TEST_CASE("sphere: the bounding box holds a moving sphere at every time", "[ch07]") {
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
    const rt::aabb still = make_sphere(point3(1, -2, 3), 0.5).bounding_box();
    CHECK(still.x.min == 0.5);
    CHECK(still.x.max == 1.5);
    CHECK(still.y.min == -2.5);
    CHECK(still.z.max == 3.5);
}

// ---------------------------------------------------------------------------------------------
// Chapter 08: surface coordinates. u = phi / (2 pi) is the longitude, growing eastward (around
// +y, from -x through +z, +x, -z), v = theta / pi the latitude from the south pole.

namespace {

struct uv {
    real u, v;
};

uv uv_of(const vec3& n) {
    uv r{};
    rt::sphere::uv_from_normal(n, r.u, r.v);
    return r;
}

// The inverse map: the unit normal at (u, v). theta = pi v from -y; phi = 2 pi u from -x.
vec3 normal_at(real u, real v) {
    const real theta = rt::pi * v, phi = 2 * rt::pi * u;
    return vec3(-std::cos(phi) * std::sin(theta), -std::cos(theta),
                std::sin(phi) * std::sin(theta));
}

// Distance between two u values on the circle of longitudes (u = 0 and u = 1 meet at -x).
real u_distance(real a, real b) {
    const real d = std::fabs(a - b);
    return std::min(d, 1 - d);
}

}  // namespace

TEST_CASE("sphere: uv_from_normal at the poles and at the four points of the equator", "[ch08]") {
    // v: 0 at the south pole, 1 at the north pole (acos(-1) = pi to the last bit), 1/2 on the
    // equator (acos(0) = pi/2: one rounding each, so within an ulp).
    CHECK(uv_of(vec3(0, -1, 0)).v == 0);
    CHECK(uv_of(vec3(0, 1, 0)).v == Approx(1).epsilon(eps));
    for (const vec3& n : {vec3(0, -1, 0), vec3(0, 1, 0)}) {
        // At a pole every longitude is the same point; u must still be a valid coordinate.
        const real u = uv_of(n).u;
        CHECK((u >= 0 && u <= 1));
    }
    // Eastward from -x: -x at u = 0, +z at 1/4, +x at 1/2, -z at 3/4 (as the book's
    // get_sphere_uv: <0 0 1> yields 0.25, <0 0 -1> yields 0.75).
    struct equator_point {
        vec3 n;
        real u;
    };
    for (const auto& [n, u] :
         {equator_point{vec3(-1, 0, 0), 0}, equator_point{vec3(0, 0, 1), 0.25},
          equator_point{vec3(1, 0, 0), 0.5}, equator_point{vec3(0, 0, -1), 0.75}}) {
        INFO("n = " << n);
        CHECK(uv_of(n).u == Approx(u).margin(eps));
        CHECK(uv_of(n).v == Approx(0.5).epsilon(eps));
    }
    // Latitude 45 degrees north over +x.
    const uv north_east = uv_of(rt::unit_vector(vec3(1, 1, 0)));
    CHECK(north_east.u == Approx(0.5).epsilon(eps));
    CHECK(north_east.v == Approx(0.75).epsilon(4 * eps));
}

TEST_CASE("sphere: u grows eastward, so a texture is not mirrored seen from outside", "[ch08]") {
    // Seen from outside at the point n, with +y up, "right" is east = y x n. A picture whose
    // u grows to the right reads correctly; one whose u grows to the left is mirrored.
    rt::pcg32 rng(80, 1);
    int mirrored = 0, tested = 0;
    for (int i = 0; i < 10000; ++i) {
        const vec3 n    = random_unit(rng);
        const vec3 east = cross(vec3(0, 1, 0), n);
        if (east.length() < real(0.1)) continue;  // near a pole, east is ill-defined
        const uv here = uv_of(n), right = uv_of(rt::unit_vector(n + real(1e-4) * east));
        if (std::fabs(here.u - right.u) > real(0.5)) continue;  // stepped over the seam
        ++tested;
        if (!(right.u > here.u)) ++mirrored;
    }
    CHECK(tested > 8000);
    CHECK(mirrored == 0);
}

TEST_CASE("sphere: uv_from_normal inverts the spherical coordinates", "[ch08]") {
    // n -> (u, v) -> normal_at(u, v) gives n back. The error is a few ulps of theta and phi,
    // except near the poles: a unit vector's y is rounded by eps/2 like any coordinate, and
    // theta = acos(-y) magnifies that by 1 / sin(theta). Hence 16 eps (1 + 1 / sin theta).
    rt::pcg32 rng(81, 2);
    int wrong = 0, out_of_range = 0;
    for (int i = 0; i < 20000; ++i) {
        const vec3 n = random_unit(rng);
        const uv c   = uv_of(n);
        if (!(c.u >= 0 && c.u <= 1 && c.v >= 0 && c.v <= 1)) ++out_of_range;
        const real sin_theta = std::sqrt(n.x() * n.x() + n.z() * n.z());
        if ((normal_at(c.u, c.v) - n).length() > 16 * eps * (1 + 1 / sin_theta)) {
            if (++wrong <= 5) UNSCOPED_INFO("n = " << n << " -> u " << c.u << ", v " << c.v);
        }
    }
    CHECK(wrong == 0);
    CHECK(out_of_range == 0);
}

TEST_CASE("sphere: u is continuous across the seam at -x (modulo 1), and stays within 0..1",
          "[ch08]") {
    // Just either side of the -x meridian u is near 0 or near 1; on the circle of longitudes
    // they are neighbours: points at longitudes -+a from the seam are 2a / (2 pi) apart in u,
    // up to the rounding of phi near pi and of u near 1 (a few eps; 8 eps allowed).
    for (real latitude : {real(-1.2), real(-0.5), real(0), real(0.4), real(1.5)}) {
        for (real a : {real(1e-3), real(1e-6), real(1e-9)}) {
            const real c = std::cos(latitude);
            const vec3 south_of(-c * std::cos(a), std::sin(latitude), c * std::sin(a));
            const vec3 north_of(-c * std::cos(a), std::sin(latitude), -c * std::sin(a));
            const uv p = uv_of(south_of), q = uv_of(north_of);
            CAPTURE(latitude, a, p.u, q.u);
            CHECK(p.u < real(0.5));  // the +z side starts at 0
            CHECK(q.u > real(0.5));  // the -z side ends at 1
            CHECK(u_distance(p.u, q.u) == Approx(a / rt::pi).margin(8 * eps));
            CHECK(p.v == q.v);
        }
    }
    // On the seam itself both ends are valid: z = +0 gives u = 0, z = -0 gives u = 1.
    CHECK(uv_of(vec3(-1, 0, 0)).u == 0);
    CHECK(uv_of(vec3(-1, 0, -real(0))).u == Approx(1).epsilon(eps));
}

TEST_CASE("sphere: a hit reports the (u, v) of its outward normal, also on a moving sphere",
          "[ch08]") {
    // The texture sticks to the sphere: (u, v) follow the point relative to the center where
    // it is at the ray's time, from outside and from inside.
    rt::pcg32 rng(82, 3);
    int not_own = 0, elsewhere = 0, hits = 0;
    for (int i = 0; i < 5000; ++i) {
        const point3 c0   = random_in_cube(rng, 5);
        const point3 c1   = i % 2 ? c0 : random_in_cube(rng, 5);
        const real radius = uniform(rng, real(0.1), 3);
        auto s            = make_textured_moving(c0, c1, radius);
        const real t      = rng.uniform();
        const point3 c    = s.center_at(t);
        const point3 o    = c + (i % 3 == 0 ? real(0.5) : real(4)) * radius * random_unit(rng);
        const point3 aim  = c + real(0.95) * radius * random_unit(rng);
        rt::hit_record rec;
        if (!s.hit(rt::ray(o, aim - o, t), forward, rec)) continue;
        ++hits;
        const vec3 outward = rec.front_face ? rec.normal : -rec.normal;
        const uv own       = uv_of(outward);
        if (rec.u != own.u || rec.v != own.v) ++not_own;
        // The same point, from the geometry: (p - C(t)) / r within the rounding of p (its
        // p_error) and of the normal, magnified near the poles as above.
        const vec3 from_center = (rec.p - c) / radius;
        const real sin_theta   = std::sqrt(outward.x() * outward.x() + outward.z() * outward.z());
        const real tolerance   = 16 * eps * (1 + 1 / sin_theta) + 2 * rec.p_error / radius;
        if ((normal_at(rec.u, rec.v) - from_center).length() > tolerance) ++elsewhere;
    }
    CHECK(hits > 4500);
    CHECK(not_own == 0);
    CHECK(elsewhere == 0);
}
