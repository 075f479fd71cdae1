// Tests for the surface coordinates of sphere.h and moving_sphere.h (chapter 08). u = phi / (2 pi)
// is the longitude, growing eastward (around +y, from -x through +z, +x, -z), v = theta / pi the
// latitude from the south pole. A hit keeps its object-space outward normal in rec.local, and
// rec.uv() turns it into (u, v) only when asked.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>

#include "ch03/material_helpers.h"
#include "rt/core/rng.h"
#include "rt/geometry/moving_sphere.h"
#include "rt/geometry/sphere.h"
#include "test_helpers.h"

namespace {

using rt::point3, rt::real, rt::surface_uv, rt::vec3;

constexpr real eps = std::numeric_limits<real>::epsilon();
const rt::interval forward(0, rt::infinity);

using rt_test::any_material, rt_test::exactly, rt_test::random_in_cube, rt_test::random_unit,
    rt_test::uniform;

surface_uv uv_of(const vec3& n) {
    return rt::sphere::uv_from_normal(n);
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

bool same_uv(const surface_uv& a, const surface_uv& b) {
    return a.u == b.u && a.v == b.v;
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
    const surface_uv north_east = uv_of(rt::unit_vector(vec3(1, 1, 0)));
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
        const surface_uv here = uv_of(n), right = uv_of(rt::unit_vector(n + real(1e-4) * east));
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
        const vec3 n       = random_unit(rng);
        const surface_uv c = uv_of(n);
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
            const surface_uv p = uv_of(south_of), q = uv_of(north_of);
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
    // it is at the ray's time, from outside and from inside. The hit keeps the outward normal
    // as rec.local and names its sphere as rec.object; rec.uv() is uv_from_normal(rec.local).
    rt::pcg32 rng(82, 3);
    int not_own = 0, not_local = 0, elsewhere = 0, hits = 0;
    for (int i = 0; i < 5000; ++i) {
        const point3 c0   = random_in_cube(rng, 5);
        const point3 c1   = i % 2 ? c0 : random_in_cube(rng, 5);
        const real radius = uniform(rng, real(0.1), 3);
        const rt::moving_sphere s(c0, c1, radius, any_material());
        const rt::sphere still(c0, radius, any_material());
        const bool moving = i % 4 != 3;
        const real t      = rng.uniform();
        const point3 c    = moving ? s.center_at(t) : c0;
        const point3 o    = c + (i % 3 == 0 ? real(0.5) : real(4)) * radius * random_unit(rng);
        const point3 aim  = c + real(0.95) * radius * random_unit(rng);
        const rt::hittable& shape = moving ? static_cast<const rt::hittable&>(s) : still;
        rt::hit_record rec;
        if (!shape.hit(rt::ray(o, aim - o, t), forward, rec)) continue;
        ++hits;
        const vec3 outward = rec.front_face ? rec.normal : -rec.normal;
        if (rec.object != &shape || !exactly(rec.local, outward)) ++not_local;
        const surface_uv own = uv_of(outward), got = rec.uv();
        if (!same_uv(got, own) || !same_uv(got, uv_of(rec.local))) ++not_own;
        // The same point, from the geometry: (p - C(t)) / r within the rounding of p (its
        // p_error) and of the normal, magnified near the poles as above.
        const vec3 from_center = (rec.p - c) / radius;
        const real sin_theta   = std::sqrt(outward.x() * outward.x() + outward.z() * outward.z());
        const real tolerance   = 16 * eps * (1 + 1 / sin_theta) + 2 * rec.p_error / radius;
        if ((normal_at(got.u, got.v) - from_center).length() > tolerance) ++elsewhere;
    }
    CHECK(hits > 4500);
    CHECK(not_local == 0);
    CHECK(not_own == 0);
    CHECK(elsewhere == 0);
}

TEST_CASE(
    "sphere: uv_at and rec.uv() are uv_from_normal of the local normal, and (0, 0) without an "
    "object",
    "[ch08]") {
    const rt::sphere ball(point3(3, -1, 2), 2, any_material());
    rt::pcg32 rng(83, 4);
    int differ = 0;
    for (int i = 0; i < 1000; ++i) {
        const vec3 n = random_unit(rng);
        rt::hit_record rec;
        rec.object = &ball;
        rec.local  = n;
        if (!same_uv(ball.uv_at(n), uv_of(n)) || !same_uv(rec.uv(), uv_of(n))) ++differ;
    }
    CHECK(differ == 0);
    // A record that names no object (nothing recorded it) has the coordinates (0, 0).
    rt::hit_record none;
    none.local = vec3(1, 0, 0);
    CHECK(none.uv().u == 0);
    CHECK(none.uv().v == 0);
}
