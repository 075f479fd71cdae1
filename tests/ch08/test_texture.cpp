// Tests for texture.h (chapter 08): a solid color is the same everywhere, and the checkerboard
// is the 3D lattice of cubes of side `scale` coloured by the parity of
// floor(x / s) + floor(y / s) + floor(z / s). Cells are half-open, [k s, (k + 1) s): a point
// exactly on a boundary belongs to the cell on its positive side (and -0 counts as 0).
// value_at() asks the hit for its (u, v) only when the texture reads them: a texture that does
// not gets value(0, 0, p), and the shape's uv_at() is never called.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>

#include "ch03/material_helpers.h"
#include "rt/core/error.h"
#include "rt/geometry/sphere.h"
#include "rt/textures/texture.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::point3, rt::real, rt::vec3;

using rt_test::any_material, rt_test::exactly;

const color white(1, 1, 1), black(0, 0, 0);

// Whether the checker shows its even color at p (even and odd are white and black).
bool even_at(const rt::texture& t, const point3& p) {
    const color c = t.value(0, 0, p);
    REQUIRE((exactly(c, white) || exactly(c, black)));
    return exactly(c, white);
}

// A texture that shows what it was asked: (u, v, p.x + p.y + p.z).
class echo_texture : public rt::texture {
  public:
    color value(real u, real v, const point3& p) const override {
        return color(u, v, p.x() + p.y() + p.z());
    }
    bool uses_uv() const override { return true; }
};

// A texture that records every call, and says it reads (u, v) or not, as told.
class recording_texture : public rt::texture {
  public:
    explicit recording_texture(bool reads_uv) : reads(reads_uv) {}
    color value(real u, real v, const point3& p) const override {
        ++calls;
        last_u = u;
        last_v = v;
        last_p = p;
        return color(0.25, 0.5, 0.75);
    }
    bool uses_uv() const override { return reads; }

    bool reads;
    mutable int calls   = 0;
    mutable real last_u = -1, last_v = -1;
    mutable point3 last_p;
};

// A sphere that counts how often its surface coordinates are computed.
class counting_sphere : public rt::sphere {
  public:
    using rt::sphere::sphere;
    rt::surface_uv uv_at(const vec3& local) const override {
        ++uv_calls;
        return rt::sphere::uv_at(local);
    }
    mutable int uv_calls = 0;
};

}  // namespace

TEST_CASE("texture: a solid color is the same at every u, v and p", "[ch08]") {
    const color albedo(real(0.2), real(0.4), real(0.8));
    const rt::solid_color t(albedo);
    const real nan = std::numeric_limits<real>::quiet_NaN();
    for (const point3& p : {point3(0, 0, 0), point3(-1e6, 3, 0.5), point3(nan, 0, 0)}) {
        for (real u : {real(0), real(0.5), real(-3), nan}) {
            CHECK(exactly(t.value(u, 1 - u, p), albedo));
        }
    }
}

TEST_CASE("texture: checker cells at known points, including negative coordinates", "[ch08]") {
    const rt::checker_texture unit(1, white, black);
    // Cell (0,0,0) is even; one step along any axis flips the parity, two steps restore it.
    CHECK(even_at(unit, point3(0.5, 0.5, 0.5)));
    CHECK_FALSE(even_at(unit, point3(1.5, 0.5, 0.5)));
    CHECK_FALSE(even_at(unit, point3(0.5, 1.5, 0.5)));
    CHECK_FALSE(even_at(unit, point3(0.5, 0.5, 1.5)));
    CHECK(even_at(unit, point3(1.5, 1.5, 0.5)));
    CHECK(even_at(unit, point3(2.5, 0.5, 0.5)));
    CHECK_FALSE(even_at(unit, point3(1.5, 1.5, 1.5)));
    // Negative coordinates: floor(-0.5) = -1 (odd), not a truncation to 0; -1 % 2 is -1 in C++,
    // which must still count as odd.
    CHECK_FALSE(even_at(unit, point3(-0.5, 0.5, 0.5)));
    CHECK(even_at(unit, point3(-0.5, -0.5, 0.5)));
    CHECK_FALSE(even_at(unit, point3(-0.5, -0.5, -0.5)));
    CHECK(even_at(unit, point3(-1.5, 0.5, 0.5)));  // floor = -2
    CHECK_FALSE(even_at(unit, point3(-2.5, 0.5, 0.5)));
    CHECK(even_at(unit, point3(real(-1e-9), real(-1e-9), 0.5)));  // cells -1, -1, 0
    // Far from the origin, the same rule: floor(1e6 + 0.5) = 1e6 (even).
    CHECK(even_at(unit, point3(1e6 + 0.5, 0.5, 0.5)));
    CHECK_FALSE(even_at(unit, point3(-1e6 - 0.5, 0.5, 0.5)));  // floor = -1e6 - 1

    // Scale 0.25: cell index floor(4 x).
    const rt::checker_texture small(0.25, white, black);
    CHECK(even_at(small, point3(0.125, 0.125, 0.125)));
    CHECK_FALSE(even_at(small, point3(0.375, 0.125, 0.125)));
    CHECK_FALSE(even_at(small, point3(-0.125, 0.125, 0.125)));
    CHECK(even_at(small, point3(-0.375, 0.125, 0.125)));
}

TEST_CASE("texture: a point on a checker boundary belongs to the cell on its positive side",
          "[ch08]") {
    // Exactly representable boundaries x = k s (s a power of two, or 3 or 5 with integer x), and
    // the largest float below each. x / s is then k exactly, and the float below divides to
    // below k. (Multiplying by a rounded 1 / s instead puts a third of those below-points for
    // s = 3 or 5 into the cell above.)
    for (real scale : {real(1), real(0.5), real(2), real(3), real(5)}) {
        const rt::checker_texture t(scale, white, black);
        int wrong = 0;
        for (int k = -1000; k <= 1000; ++k) {
            const real x = real(k) * scale;  // exact
            const real h = scale / 2;        // a coordinate inside cell 0
            // Cell k on the boundary x = k s, and cell k - 1 just below it.
            const bool k_even = k % 2 == 0;
            if (even_at(t, point3(x, h, h)) != k_even) ++wrong;
            // (Below 0, the smallest normal number: a subnormal one divided by s > 1 would
            // round to -0, which is on the boundary.)
            const real below =
                k == 0 ? -std::numeric_limits<real>::min() : std::nextafter(x, -rt::infinity);
            if (even_at(t, point3(below, h, h)) == k_even) ++wrong;
            // The same on the y and z axes.
            if (even_at(t, point3(h, x, h)) != k_even) ++wrong;
            if (even_at(t, point3(h, h, x)) != k_even) ++wrong;
        }
        INFO("scale " << scale << ": " << wrong << " points in the wrong cell");
        CHECK(wrong == 0);
    }
    // -0 is on the boundary 0 and belongs to cell 0, like +0.
    const rt::checker_texture unit(1, white, black);
    CHECK(even_at(unit, point3(-real(0), 0.5, 0.5)));
    CHECK(even_at(unit, point3(0, 0, 0)));
    CHECK_FALSE(even_at(unit, point3(1, 0, 0)));  // cells 1, 0, 0
    CHECK(even_at(unit, point3(1, 1, 0)));
}

TEST_CASE("texture: the checker hands u, v and p unchanged to its two textures", "[ch08]") {
    auto echo = std::make_shared<echo_texture>();
    const rt::checker_texture t(1, echo, std::make_shared<rt::solid_color>(black));
    const point3 p(0.25, 0.5, 0.125);  // cell (0, 0, 0): even
    CHECK(exactly(t.value(0.375, 0.75, p), color(0.375, 0.75, 0.875)));
    const rt::checker_texture flipped(1, std::make_shared<rt::solid_color>(black), echo);
    const point3 q(1.25, 0.5, 0.125);  // cell (1, 0, 0): odd
    CHECK(exactly(flipped.value(0.125, 0.875, q), color(0.125, 0.875, 1.875)));
}

TEST_CASE("texture: a checker scale that is not positive, finite and normal throws a user_error",
          "[ch08]") {
    // A subnormal scale is positive and finite, but every x / scale overflows to infinity.
    const real nan       = std::numeric_limits<real>::quiet_NaN();
    const real subnormal = std::numeric_limits<real>::denorm_min();
    for (real scale : {real(0), -real(0), real(-1), real(-0.25), nan, rt::infinity, -rt::infinity,
                       subnormal, std::numeric_limits<real>::min() / 2}) {
        std::ostringstream printed;
        printed << scale;
        INFO("scale = " << printed.str());
        std::string message;
        try {
            rt::checker_texture t(scale, white, black);
        } catch (const rt::user_error& e) {
            message = e.what();
        }
        const bool tiny = scale > 0 && scale < std::numeric_limits<real>::min();
        CHECK_THAT(message, Catch::Contains(std::string("checker scale must ") +
                                            (tiny ? "not be subnormal" : "be positive and finite") +
                                            ", got " + printed.str()));
    }
    CHECK_NOTHROW(rt::checker_texture(std::numeric_limits<real>::min(), white, black));
    CHECK_NOTHROW(rt::checker_texture(real(1e-3), white, black));
    CHECK_NOTHROW(rt::checker_texture(real(1e6), white, black));
    CHECK_THROWS_AS(rt::checker_texture(1, nullptr, std::make_shared<rt::solid_color>(black)),
                    rt::user_error);
    CHECK_THROWS_AS(rt::checker_texture(1, std::make_shared<rt::solid_color>(white), nullptr),
                    rt::user_error);
}

TEST_CASE(
    "texture: solid colors and checkers of them read no (u, v), but a checker with one that "
    "does reads them",
    "[ch08]") {
    auto solid = std::make_shared<rt::solid_color>(white);
    auto echo  = std::make_shared<echo_texture>();
    CHECK_FALSE(solid->uses_uv());
    CHECK_FALSE(rt::checker_texture(1, white, black).uses_uv());
    CHECK(rt::checker_texture(1, echo, solid).uses_uv());
    CHECK(rt::checker_texture(1, solid, echo).uses_uv());
}

TEST_CASE("texture: value_at computes the hit's (u, v) only for a texture that reads them",
          "[ch08]") {
    // A ray down onto the top of a sphere, off its axis so that (u, v) are not (0, 0).
    const counting_sphere ball(point3(1, 2, 3), 2, any_material());
    rt::hit_record rec;
    REQUIRE(ball.hit(rt::ray(point3(1.5, 10, 3.25), vec3(0, -1, 0)), rt::interval(0, rt::infinity),
                     rec));
    REQUIRE(rec.object == &ball);
    const rt::surface_uv expected = rt::sphere::uv_from_normal(rec.local);
    REQUIRE(expected.u > 0);
    REQUIRE(expected.v > 0);
    REQUIRE(ball.uv_calls == 0);  // the hit itself computes no coordinates

    // A texture that does not read (u, v): value(0, 0, p), and the sphere is never asked.
    const recording_texture solid_like(false);
    CHECK(exactly(solid_like.value_at(rec), color(0.25, 0.5, 0.75)));
    CHECK(solid_like.calls == 1);
    CHECK(solid_like.last_u == 0);
    CHECK(solid_like.last_v == 0);
    CHECK(exactly(solid_like.last_p, rec.p));
    CHECK(ball.uv_calls == 0);
    // Nor through a checker of such textures.
    const rt::checker_texture checker(1, std::make_shared<recording_texture>(false),
                                      std::make_shared<recording_texture>(false));
    checker.value_at(rec);
    CHECK(ball.uv_calls == 0);

    // A texture that reads them: the sphere computes them once, from its local normal.
    const recording_texture mapped(true);
    mapped.value_at(rec);
    CHECK(ball.uv_calls == 1);
    CHECK(mapped.last_u == expected.u);
    CHECK(mapped.last_v == expected.v);
    CHECK(exactly(mapped.last_p, rec.p));
    // A checker with such a texture on either side asks for them as well.
    const rt::checker_texture mixed(1, std::make_shared<recording_texture>(false),
                                    std::make_shared<echo_texture>());
    // The hit, near (1.5, 3.92, 3.25), lies in cell 1 + 3 + 3: odd, the echo.
    const color seen = mixed.value_at(rec);
    CHECK(ball.uv_calls == 2);
    CHECK(exactly(seen, color(expected.u, expected.v, rec.p.x() + rec.p.y() + rec.p.z())));
}
