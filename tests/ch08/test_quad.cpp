// Tests for the surface coordinates of quad.h (chapter 08): a hit's (u, v) are its plane
// coordinates (a, b), kept in rec.local as (a, b, 0) and returned by rec.uv(). The quads have
// power-of-two edges and the rays dyadic coordinates, so (a, b) are computed exactly.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>

#include "ch03/material_helpers.h"
#include "rt/geometry/quad.h"
#include "test_helpers.h"

namespace {

using rt::point3, rt::real, rt::vec3;

constexpr real eps = std::numeric_limits<real>::epsilon();
const rt::interval forward(0, rt::infinity);

using rt_test::any_material, rt_test::exactly;

rt::quad make_quad(const point3& Q, const vec3& u, const vec3& v) {
    return rt::quad(Q, u, v, any_material());
}

// The quad Q + a u + b v in the plane z = 3: Q = (1, -2, 3), u = (2, 0, 0), v = (0, 4, 0), so
// x = 1 + 2a, y = -2 + 4b, and its normal unit(u x v) is +z.
const point3 corner(1, -2, 3);
const vec3 edge_u(2, 0, 0), edge_v(0, 4, 0);

point3 at(real a, real b) {
    return corner + a * edge_u + b * edge_v;
}

// A ray straight down onto the plane through the point of plane coordinates (a, b).
rt::ray down_onto(real a, real b) {
    return rt::ray(at(a, b) + vec3(0, 0, 5), vec3(0, 0, -1));
}

}  // namespace

TEST_CASE("quad: a hit's (u, v) are its plane coordinates (a, b): 0 and 1 at the corners",
          "[ch08]") {
    auto q = make_quad(corner, edge_u, edge_v);
    // Dyadic points: a and b are computed exactly.
    const real points[][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0.25, 0.5}, {0.75, 0.125}};
    for (const auto& ab : points) {
        INFO("a = " << ab[0] << ", b = " << ab[1]);
        rt::hit_record rec;
        REQUIRE(q.hit(down_onto(ab[0], ab[1]), forward, rec));
        CHECK(rec.uv().u == ab[0]);
        CHECK(rec.uv().v == ab[1]);
        // From behind, the same point has the same coordinates: (u, v) belong to the surface.
        REQUIRE(q.hit(rt::ray(at(ab[0], ab[1]) - vec3(0, 0, 5), vec3(0, 0, 1)), forward, rec));
        CHECK(rec.uv().u == ab[0]);
        CHECK(rec.uv().v == ab[1]);
    }

    // A tilted quad: Q + a u + b v is hit at (a, b) up to rounding. The error of a is that of
    // the hit point (a few ulps of the coordinates, ~4) divided by the edge length (~1), 64 ulps
    // allowed.
    const point3 Q(-3, 1.5, 2);
    const vec3 u(1, 2, -0.5), v(-0.5, 0.25, 1.5);
    auto tilted  = make_quad(Q, u, v);
    const vec3 n = rt::unit_vector(cross(u, v));
    for (const auto& ab : {std::pair<real, real>(0.3, 0.6), {0.01, 0.99}, {0.5, 0.5}}) {
        const point3 target = Q + ab.first * u + ab.second * v;
        const point3 origin = target + 3 * n + vec3(0.125, -0.25, 0.375);
        rt::hit_record rec;
        REQUIRE(tilted.hit(rt::ray(origin, target - origin), forward, rec));
        CHECK(rec.uv().u == Approx(ab.first).margin(64 * eps * 4));
        CHECK(rec.uv().v == Approx(ab.second).margin(64 * eps * 4));
    }
}

TEST_CASE("quad: a hit records the quad and (alpha, beta, 0), and rec.uv() is (alpha, beta)",
          "[ch08]") {
    auto q = make_quad(corner, edge_u, edge_v);
    rt::hit_record rec;
    REQUIRE(q.hit(down_onto(0.375, 0.625), forward, rec));
    CHECK(rec.object == &q);
    CHECK(exactly(rec.local, vec3(0.375, 0.625, 0)));
    CHECK(rec.uv().u == 0.375);
    CHECK(rec.uv().v == 0.625);
    // uv_at reads the first two coordinates of any local point it is given.
    CHECK(q.uv_at(vec3(0.125, 0.75, 0)).u == 0.125);
    CHECK(q.uv_at(vec3(0.125, 0.75, 0)).v == 0.75);
    rec.local = vec3(0.5, 0.25, 0);
    CHECK(rec.uv().u == 0.5);
    CHECK(rec.uv().v == 0.25);
}
