// Tests for sine_checker_texture (texture.h, chapter 08): the checker of book 1's older edition
// (v3), colored by the sign of sin(pi x / s) sin(pi y / s) sin(pi z / s). Inside a cell it
// agrees with the floor rule of checker_texture; across every cell face it changes color; on a
// face where a sine is exactly 0 (the planes x, y or z = 0) the product is 0 and the color is
// the even one everywhere, where the floor rule still alternates. Chapter 08's --scene checker
// shows that last case on a floor at y = 0.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>

#include "rt/core/error.h"
#include "rt/textures/texture.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::point3, rt::real, rt::vec3;
using rt_test::exactly, rt_test::uniform;

const color white(1, 1, 1), black(0, 0, 0);

// Whether the texture shows its even color (white) at p; it must show one of its two colors.
bool shows_even(const rt::texture& t, const point3& p) {
    const color c = t.value(0, 0, p);
    REQUIRE((exactly(c, white) || exactly(c, black)));
    return exactly(c, white);
}

// The distance from x / scale to the nearest integer (a cell face), in cells.
real distance_to_face(real x, real scale) {
    const real cells = x / scale;
    return std::fabs(cells - std::round(cells));
}

// A texture that shows what it was asked: (u, v, p.x + p.y + p.z).
class echo_texture : public rt::texture {
  public:
    color value(real u, real v, const point3& p) const override {
        return color(u, v, p.x() + p.y() + p.z());
    }
    bool uses_uv() const override { return true; }
};

}  // namespace

TEST_CASE("sine checker: colors at known points, including negative coordinates", "[ch08]") {
    const rt::sine_checker_texture unit(1, white, black);
    // sin(pi x) is positive for x in (0, 1), negative in (1, 2) and in (-1, 0).
    CHECK(shows_even(unit, point3(0.5, 0.5, 0.5)));        // + + +
    CHECK_FALSE(shows_even(unit, point3(1.5, 0.5, 0.5)));  // - + +
    CHECK_FALSE(shows_even(unit, point3(-0.5, 0.5, 0.5)));
    CHECK(shows_even(unit, point3(-0.5, -0.5, 0.5)));      // - - +
    CHECK_FALSE(shows_even(unit, point3(1.5, 1.5, 1.5)));  // - - -
    CHECK(shows_even(unit, point3(2.25, -1.75, 0.1)));     // sin(-1.75 pi) = sin(0.25 pi) > 0
    CHECK_FALSE(shows_even(unit, point3(2.25, -0.75, 0.1)));
    // The seed's cells, side pi / 10: the sines are sin(10 x) sin(10 y) sin(10 z).
    const rt::sine_checker_texture seed(rt::pi / 10, white, black);
    CHECK(shows_even(seed, point3(0.1, 0.1, 0.1)));        // sin(1)^3 > 0
    CHECK_FALSE(shows_even(seed, point3(0.4, 0.1, 0.1)));  // sin(4) < 0
    CHECK(shows_even(seed, point3(0.4, 0.4, 0.1)));
    CHECK(shows_even(seed, point3(-0.1, -0.1, 0.1)));
}

TEST_CASE("sine checker: inside the cells it is the floor rule's checkerboard", "[ch08]") {
    // sin(pi x / s) has the sign (-1)^k in the cell [k s, (k + 1) s), so the sign of the product
    // is (-1)^n with n the floor rule's sum of cell indices. Points closer than 1e-4 cells to a
    // face are skipped: there the rounding of pi x / s may decide (in the float build too).
    rt::pcg32 rng(81, 3);
    int compared = 0;
    for (real scale : {real(1), rt::pi / 10, real(0.32), real(1e-3), real(1e3)}) {
        const rt::sine_checker_texture sines(scale, white, black);
        const rt::checker_texture floors(scale, white, black);
        for (int i = 0; i < 20000; ++i) {
            const real x = uniform(rng, -50 * scale, 50 * scale);
            const real y = uniform(rng, -50 * scale, 50 * scale);
            const point3 p(x, y, uniform(rng, -50 * scale, 50 * scale));
            if (distance_to_face(p.x(), scale) < real(1e-4) ||
                distance_to_face(p.y(), scale) < real(1e-4) ||
                distance_to_face(p.z(), scale) < real(1e-4))
                continue;
            INFO("scale " << scale << ", p = " << p);
            REQUIRE(shows_even(sines, p) == shows_even(floors, p));
            ++compared;
        }
    }
    CHECK(compared > 99000);
}

TEST_CASE("sine checker: the color changes across every cell face, and repeats every 2 cells",
          "[ch08]") {
    const real scale = rt::pi / 10;
    const rt::sine_checker_texture sines(scale, white, black);
    const rt::checker_texture floors(scale, white, black);
    const real y = real(0.35) * scale, z = real(1.6) * scale;  // inside cells
    for (int k = -4; k <= 4; ++k) {
        for (int axis = 0; axis < 3; ++axis) {
            INFO("face " << k << " on axis " << axis);
            point3 below(real(0.5) * scale, y, z), above = below;
            below[axis] = (real(k) - real(1e-3)) * scale;
            above[axis] = (real(k) + real(1e-3)) * scale;
            CHECK(shows_even(sines, below) != shows_even(sines, above));
            CHECK(shows_even(sines, below) == shows_even(floors, below));
            CHECK(shows_even(sines, above) == shows_even(floors, above));
            point3 two_cells_on = above;
            two_cells_on[axis] += 2 * scale;
            CHECK(shows_even(sines, two_cells_on) == shows_even(sines, above));
        }
    }
}

TEST_CASE("sine checker: on the planes x, y or z = 0 the product is 0 and the checker vanishes",
          "[ch08]") {
    // The floor of chapter 08's --scene checker lies in y = 0 (a quad puts its hit points exactly
    // on its plane). The sine rule shows the even color there everywhere, also at -0; the floor
    // rule puts y = 0 in the cell [0, s) and keeps alternating in x and z.
    const real scale = rt::pi / 10;
    const rt::sine_checker_texture sines(scale, white, black);
    const rt::checker_texture floors(scale, white, black);
    rt::pcg32 rng(82, 5);
    int floor_even = 0, floor_odd = 0;
    for (int i = 0; i < 2000; ++i) {
        const real a = uniform(rng, -10, 10), b = uniform(rng, -10, 10);
        for (real zero : {real(0), -real(0)}) {
            CHECK(shows_even(sines, point3(a, zero, b)));
            CHECK(shows_even(sines, point3(zero, a, b)));
            CHECK(shows_even(sines, point3(a, b, zero)));
        }
        (shows_even(floors, point3(a, 0, b)) ? floor_even : floor_odd)++;
    }
    CHECK(floor_even > 800);
    CHECK(floor_odd > 800);
}

TEST_CASE("sine checker: hands u, v and p unchanged to its two textures", "[ch08]") {
    auto echo = std::make_shared<echo_texture>();
    const rt::sine_checker_texture t(1, echo, echo);
    CHECK(exactly(t.value(real(0.25), real(0.75), point3(0.5, 0.5, 0.5)), color(0.25, 0.75, 1.5)));
    CHECK(t.uses_uv());
    CHECK_FALSE(rt::sine_checker_texture(1, white, black).uses_uv());
}

TEST_CASE("sine checker: a scale that is not positive, finite and normal throws a user_error",
          "[ch08]") {
    const real nan       = std::numeric_limits<real>::quiet_NaN();
    const real subnormal = std::numeric_limits<real>::denorm_min();
    for (real scale : {real(0), real(-1), nan, rt::infinity, -rt::infinity, subnormal}) {
        std::ostringstream printed;
        printed << scale;
        INFO("scale = " << printed.str());
        std::string message;
        try {
            rt::sine_checker_texture t(scale, white, black);
        } catch (const rt::user_error& e) {
            message = e.what();
        }
        const bool tiny = scale > 0 && scale < std::numeric_limits<real>::min();
        CHECK_THAT(message, Catch::Contains(std::string("checker scale must ") +
                                            (tiny ? "not be subnormal" : "be positive and finite") +
                                            ", got " + printed.str()));
    }
    CHECK_NOTHROW(rt::sine_checker_texture(std::numeric_limits<real>::min(), white, black));
    CHECK_THROWS_AS(rt::sine_checker_texture(1, nullptr, std::make_shared<rt::solid_color>(black)),
                    rt::user_error);
    CHECK_THROWS_AS(rt::sine_checker_texture(1, std::make_shared<rt::solid_color>(white), nullptr),
                    rt::user_error);
}
