// Tests for sphere.h (chapter 02). First the exact cases of The Ray Tracer Challenge, where every
// number is representable and the solver must return it bit for bit; then hard-case tests of the
// stable solver (Ray Tracing Gems ch. 7) on distant, tiny, huge and grazing spheres. Chapter 02's
// spheres have no material (shapes are shown by their normals); a sphere's material is tested
// with chapter 03.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "rt/core/error.h"
#include "rt/core/rng.h"
#include "rt/geometry/sphere.h"
#include "test_helpers.h"

namespace {

using rt::point3, rt::real, rt::vec3;

constexpr real eps = std::numeric_limits<real>::epsilon();
const rt::interval forward(0, rt::infinity);

rt::sphere make_sphere(const point3& center, real radius) {
    return rt::sphere(center, radius);
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
           std::isfinite(rec.p_error) && rec.p_error >= 0 &&
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
           rec.p_error == 42 && !rec.front_face;
}

// Distance of p from the surface of the sphere (center, radius).
real off_surface(const point3& p, const point3& center, real radius) {
    return std::fabs((p - center).length() - radius);
}

// The hard cases look from 1e6 radii and graze by 1e-6 radii in double, beyond float's 24 bits
// (its ulp at 1e6 is 0.06): a float build takes its own distances and margins, chosen there.
constexpr bool is_double = std::numeric_limits<real>::digits >= 53;

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
    CHECK_NOTHROW(make_sphere(point3(0, 0, 0), std::numeric_limits<real>::min()));
}

TEST_CASE("sphere: hit_sphere, shared by every sphere, is what sphere::hit reports", "[ch02]") {
    // sphere::hit adds only what the free function leaves to its caller (the material), so the
    // geometry of both must agree bit for bit, hit or miss.
    rt::pcg32 rng(41, 2);
    int hits = 0, differ = 0;
    for (int i = 0; i < 2000; ++i) {
        const point3 center = random_in_cube(rng, 5);
        const real radius   = uniform(rng, real(0.1), 3);
        const auto s        = make_sphere(center, radius);
        REQUIRE(exactly(s.center(), center));
        REQUIRE(s.radius() == radius);
        const point3 origin = random_in_cube(rng, 10);
        const point3 target = center + random_in_cube(rng, radius);
        const rt::ray r(origin, target - origin);
        rt::hit_record by_sphere = sentinel(), by_function = sentinel();
        const bool hit_a = s.hit(r, forward, by_sphere);
        const bool hit_b = rt::hit_sphere(center, radius, r, forward, by_function);
        hits += hit_a;
        if (hit_a != hit_b || !exactly(by_sphere.p, by_function.p) ||
            !exactly(by_sphere.normal, by_function.normal) || by_sphere.t != by_function.t ||
            by_sphere.p_error != by_function.p_error ||
            by_sphere.front_face != by_function.front_face) {
            UNSCOPED_INFO("center " << center << ", radius " << radius << ", ray from " << origin
                                    << " towards " << target);
            ++differ;
        }
        if (!hit_b && !is_sentinel(by_function)) ++differ;  // a miss writes nothing
    }
    CHECK(hits > 1000);
    CHECK(differ == 0);
}

// ---------------------------------------------------------------------------------------------
// Hard cases. The book's quadratic b^2 - a c subtracts two numbers of size (D/r)^2 r^2 to get
// one of size r^2, so at D = 1e6 radii its discriminant carries an error of about
// eps (D/r)^2 ~ 2e-4 (relative to r^2), which moves the hit point by ~1e-4 r and turns a 1e-6
// grazing margin into noise. The stable form takes the discriminant from the perpendicular
// distance f_perp, whose error is ~eps D: 2e-10 r at 1e6 radii, four orders below every
// threshold here. The thresholds (1e-4 r for the hit point, 1 -/+ 1e-6 for grazing rays) are set
// where the stable solver has that margin and the book's does not.
// Float (eps = 1.2e-7) meets the same split a thousand times nearer: at D = 1e3 radii the book's
// error is eps D^2 = 0.12 r^2, the stable form's eps D = 1.2e-4 r (measured on the hit point: at
// most 2.7 eps D). So float looks from 1e1 to 1e3 radii, with 1e-3 r for the hit point (8 eps D
// at 1e3) and 1 -/+ 1e-3 for grazing rays (likewise; from 1e2 radii, see there): the stable
// solver holds both, the book's misses them by two orders. The 0.99 r and 1.01 r rays keep their
// 1e-2 r margin, 80 eps D at 1e3. Radii 1e-4..1e4 in both: scale costs no bits, and float's
// largest product, a^2 r^2 = (D r)^4 r^2 = 1e36 (r = 1e4, D = 1e3), stays below its 3.4e38.

TEST_CASE(
    "sphere: seen from 1e4 to 1e6 radii (float: 1e1 to 1e3), aimed rays hit where aimed and "
    "off-center rays miss",
    "[hardcase][ch02]") {
    const real aim_bound = is_double ? real(1e-4) : real(1e-3);  // of the radius
    const std::vector<real> distances =
        is_double ? std::vector<real>{1e4, 1e5, 1e6} : std::vector<real>{1e1, 1e2, 1e3};
    rt::pcg32 rng(2024, 5);
    for (real radius : {real(1e-4), real(1), real(1e4)}) {
        for (real distance : distances) {
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
                    if (!(error <= aim_bound)) ++far_from_aim;
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
                           << " trials: aimed rays missed " << aimed_missed << ", hit > "
                           << aim_bound << " r from the aim " << far_from_aim << " (worst "
                           << worst_aim_error << " r), off the surface " << off
                           << "; 0.99 r missed " << inside_missed << ", 1.01 r hit " << outside_hit
                           << "; malformed " << malformed);
            CHECK(aimed_missed == 0);
            CHECK(far_from_aim == 0);
            CHECK(off == 0);
            CHECK(inside_missed == 0);
            CHECK(outside_hit == 0);
            CHECK(malformed == 0);
        }
    }
}

TEST_CASE(
    "sphere: grazing rays 1e-6 (float: 1e-3) inside the silhouette hit and as far outside miss",
    "[hardcase][ch02]") {
    // The ray's distance from the center is k r with k = 1 -/+ 1e-6 (less a relative
    // k^2 / (2 D^2) <= 5e-9 for the line not being exactly perpendicular). Rounding the eye's
    // coordinates moves the line by ~eps D r <= 2e-10 r: far below the 1e-6 r margin.
    // Float: k = 1 -/+ 1e-3 from 1e2 and 1e3 radii. eps D r <= 1.2e-4 r is 8 times below the
    // margin (measured: it still holds at 2e-4, fails at 1e-4), and k^2 / (2 D^2) <= 5e-5 is 20
    // times below; at 1e1 radii that term, 5e-3, would bring the outside rays onto the sphere.
    const real margin = is_double ? real(1e-6) : real(1e-3);
    const std::vector<real> distances =
        is_double ? std::vector<real>{1e4, 1e5, 1e6} : std::vector<real>{1e2, 1e3};
    rt::pcg32 rng(99, 3);
    for (real radius : {real(1e-4), real(1), real(1e4)}) {
        for (real distance : distances) {
            const point3 center = random_in_cube(rng, 3 * radius);
            auto s              = make_sphere(center, radius);
            int grazing_missed = 0, grazing_outside_hit = 0, off = 0, malformed = 0;
            for (int i = 0; i < 1000; ++i) {
                vec3 toward_eye = random_unit(rng);
                point3 eye      = center + distance * radius * toward_eye;
                vec3 across     = random_tangent(rng, toward_eye);
                point3 in       = center + (1 - margin) * radius * across;
                point3 out      = center + (1 + margin) * radius * across;
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

TEST_CASE("sphere: a sphere below the rounding of its own position gives no NaN",
          "[hardcase][ch02]") {
    // Radius 1e-12 at x = 1e8, where an ulp is 1.5e-8 (double): a ray straight through the center
    // lands exactly on it, and the normal would be 0/0. Float holds the same case: 1e8 is exact
    // there (2^8 * 390625), its ulp is 8, and r^2 = 1e-24 is far above its least normal 1.2e-38.
    // The normal's length: 1e-12 (double), and float's unit length to 4 eps, as well_formed says.
    const rt::sphere speck(point3(1e8, 0, 0), real(1e-12));
    const rt::ray r(point3(0, 0, 0), vec3(1, 0, 0));
    rt::hit_record rec;
    REQUIRE(speck.hit(r, rt::interval(0, rt::infinity), rec));
    CHECK(std::isfinite(rec.normal.x()));
    CHECK(std::isfinite(rec.normal.y()));
    CHECK(std::isfinite(rec.normal.z()));
    CHECK(std::fabs(rec.normal.length() - 1) < (is_double ? real(1e-12) : 4 * eps));
    CHECK(std::isfinite(rec.p.x()));
}
