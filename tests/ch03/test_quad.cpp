// Tests for quad.h (chapter 03): hits inside, on the closed edges and corners, misses just
// outside and parallel, the face normal, the material, and the zero-area checks. The quads have
// power-of-two edges and the rays dyadic coordinates, so every plane coordinate (a, b) is computed
// exactly and a point on an edge really is on it.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>

#include "ch03/material_helpers.h"
#include "rt/core/error.h"
#include "rt/geometry/quad.h"
#include "test_helpers.h"

namespace {

using rt::point3, rt::real, rt::vec3;

constexpr real eps = std::numeric_limits<real>::epsilon();
const rt::interval forward(0, rt::infinity);

rt::quad make_quad(const point3& Q, const vec3& u, const vec3& v) {
    return rt::quad(Q, u, v, rt_test::any_material());
}

using rt_test::exactly;

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

TEST_CASE("quad: a ray through its inside hits with the front normal unit(u x v)", "[ch03]") {
    auto mat = rt_test::any_material();
    rt::quad q(corner, edge_u, edge_v, mat);
    rt::hit_record rec;
    REQUIRE(q.hit(down_onto(0.25, 0.5), forward, rec));
    CHECK(rec.t == 5);
    CHECK(exactly(rec.p, at(0.25, 0.5)));
    CHECK(rec.front_face);
    CHECK(exactly(rec.normal, vec3(0, 0, 1)));
    CHECK(rec.mat == mat.get());  // the quad's own material
    // interval::surrounds is open: t = 5 itself is outside (0, 5).
    CHECK_FALSE(q.hit(down_onto(0.25, 0.5), rt::interval(0, 5), rec));
}

TEST_CASE("quad: points exactly on its edges and corners hit (a, b = 0 or 1 count as inside)",
          "[ch03]") {
    auto q                = make_quad(corner, edge_u, edge_v);
    const real edges[][2] = {{0, 0},   {1, 0},   {0, 1},   {1, 1},  // the four corners
                             {0, 0.5}, {1, 0.5}, {0.5, 0}, {0.5, 1}};
    for (const auto& ab : edges) {
        INFO("a = " << ab[0] << ", b = " << ab[1]);
        rt::hit_record rec;
        REQUIRE(q.hit(down_onto(ab[0], ab[1]), forward, rec));
        CHECK(exactly(rec.p, at(ab[0], ab[1])));
    }
}

TEST_CASE("quad: points 1e-9 (relative) outside an edge or corner miss", "[ch03]") {
    auto q = make_quad(corner, edge_u, edge_v);
    // 1e-9 of an edge is far above the rounding of a and b (an ulp of 1, 2e-16): these points are
    // really outside, and the closed test must not round them in. (A float build cannot place a
    // point 1e-9 past 1; it uses 4 of its ulps, 5e-7, instead.)
    const real margin = std::fmax(real(1e-9), 4 * eps);
    const real below = -margin, above = 1 + margin;
    const real outside[][2] = {{below, 0.5},   {above, 0.5},   {0.5, below},   {0.5, above},
                               {below, below}, {above, above}, {below, above}, {above, below}};
    for (const auto& ab : outside) {
        INFO("a = " << ab[0] << ", b = " << ab[1]);
        rt::hit_record rec;
        CHECK_FALSE(q.hit(down_onto(ab[0], ab[1]), forward, rec));
    }
}

TEST_CASE("quad: rays parallel to its plane miss without NaN", "[ch03]") {
    auto q = make_quad(corner, edge_u, edge_v);
    rt::hit_record rec;
    rec.t = -7;
    // In the plane itself, crossing the quad; above the plane; and so nearly parallel that
    // t = 5 / (the smallest normal number) overflows to infinity.
    CHECK_FALSE(q.hit(rt::ray(point3(0, 0, 3), vec3(1, 0, 0)), forward, rec));
    CHECK_FALSE(q.hit(rt::ray(point3(0, 0, 8), vec3(1, 1, 0)), forward, rec));
    CHECK_FALSE(q.hit(rt::ray(point3(0, 0, 8), vec3(1, 0, -std::numeric_limits<real>::min())),
                      forward, rec));
    CHECK(rec.t == -7);  // untouched: nothing was written, so no NaN either
}

TEST_CASE("quad: a hit from behind has front_face false and the normal facing the ray", "[ch03]") {
    auto q = make_quad(corner, edge_u, edge_v);
    rt::hit_record rec;
    REQUIRE(q.hit(rt::ray(at(0.5, 0.5) - vec3(0, 0, 2), vec3(0, 0, 1)), forward, rec));
    CHECK(rec.t == 2);
    CHECK_FALSE(rec.front_face);
    CHECK(exactly(rec.normal, vec3(0, 0, -1)));
    CHECK(rec.mat != nullptr);  // the material, from the back as well
}

TEST_CASE("quad: a tilted quad reports the normal unit(u x v) and a hit point on its plane",
          "[ch03]") {
    const point3 Q(-3, 1.5, 2);
    const vec3 u(1, 2, -0.5), v(-0.5, 0.25, 1.5);
    auto q        = make_quad(Q, u, v);
    vec3 n        = rt::unit_vector(cross(u, v));
    point3 target = Q + real(0.3) * u + real(0.6) * v;
    point3 origin = target + 4 * n + vec3(0.5, -0.25, 0.1);
    rt::hit_record rec;
    REQUIRE(q.hit(rt::ray(origin, target - origin), forward, rec));
    CHECK(rec.front_face);
    // n and the quad's normal are both unit(u x v), computed in the same operations up to the
    // order of one division: a few ulps apart.
    CHECK((rec.normal - n).length() <= 4 * eps);
    // target and the hit are both rounded at the scale of the coordinates (~4); 64 ulps of that
    // is generous, and still 1e-13 of the quad.
    CHECK((rec.p - target).length() <= 64 * eps * 4);
    CHECK(std::fabs(dot(rec.p - Q, n)) <= rec.p_error);

    // The same ray from the back side.
    point3 behind = target - 4 * n;
    REQUIRE(q.hit(rt::ray(behind, target - behind), forward, rec));
    CHECK_FALSE(rec.front_face);
    CHECK((rec.normal + n).length() <= 4 * eps);
}

TEST_CASE("quad: zero area (u = 0, v = 0, or u parallel to v) throws a user_error", "[ch03]") {
    auto mat = rt_test::any_material();
    CHECK_THROWS_AS(rt::quad(corner, vec3(0, 0, 0), edge_v, mat), rt::user_error);
    CHECK_THROWS_AS(rt::quad(corner, edge_u, vec3(0, 0, 0), mat), rt::user_error);
    CHECK_THROWS_AS(rt::quad(corner, vec3(1, 2, 3), vec3(2, 4, 6), mat), rt::user_error);
    CHECK_THROWS_AS(rt::quad(corner, vec3(1, 2, 3), vec3(-0.5, -1, -1.5), mat), rt::user_error);
    // The message says what is wrong and names both edges (validate.h's form).
    CHECK_THROWS_WITH(rt::quad(corner, vec3(1, 2, 3), vec3(2, 4, 6), mat),
                      Catch::Contains("quad edges must span an area") &&
                          Catch::Contains("got u = (1, 2, 3), v = (2, 4, 6)"));
    CHECK_THROWS_WITH(rt::quad(corner, edge_u, edge_v, nullptr),
                      Catch::Contains("quad material is missing"));
    CHECK_NOTHROW(rt::quad(corner, edge_u, edge_v, mat));
}

TEST_CASE("quad: corner() and the edges are the ones it was made with", "[ch03]") {
    const rt::quad q = make_quad(corner, edge_u, edge_v);
    CHECK(exactly(q.corner(), corner));
    CHECK(exactly(q.edge_u(), edge_u));
    CHECK(exactly(q.edge_v(), edge_v));
}
