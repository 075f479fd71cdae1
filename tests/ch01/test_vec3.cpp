// vec3 (rt/core/vec3.h): the algebra every later chapter builds on. Chapter 01.
// Small integers and halves are exact in binary floating point, so most cases compare with ==.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "rt/core/rng.h"
#include "rt/core/vec3.h"
#include "test_helpers.h"

using rt::real;
using rt::vec3;

namespace {

constexpr real eps = std::numeric_limits<real>::epsilon();

// Bit-for-bit equality of vectors (rt_test::exactly), under the name the checks read best with.
bool (&equal)(const vec3&, const vec3&) = rt_test::exactly;

vec3 random_vec3(rt::pcg32& rng, real scale) {
    // One draw per statement: the order of arguments' evaluation is unspecified in C++.
    real x = 2 * rng.uniform() - 1;
    real y = 2 * rng.uniform() - 1;
    return scale * vec3(x, y, 2 * rng.uniform() - 1);
}

}  // namespace

TEST_CASE("vec3: arithmetic is exact on small integers", "[vec3][ch01]") {
    const vec3 u(1, 2, 3), v(4, -5, 6);
    CAPTURE(u, v);
    CHECK(equal(u + v, vec3(5, -3, 9)));
    CHECK(equal(u - v, vec3(-3, 7, -3)));
    CHECK(equal(-u, vec3(-1, -2, -3)));
    CHECK(equal(u * v, vec3(4, -10, 18)));  // component-wise: a reflectance filtering a color
    CHECK(equal(2 * u, vec3(2, 4, 6)));
    CHECK(equal(u * 2, vec3(2, 4, 6)));
    CHECK(equal(u / 2, vec3(real(0.5), 1, real(1.5))));
    CHECK(u[0] == 1);
    CHECK(u[1] == 2);
    CHECK(u[2] == 3);

    vec3 w = u;
    w += v;
    CHECK(equal(w, vec3(5, -3, 9)));
    w *= 2;
    CHECK(equal(w, vec3(10, -6, 18)));
    w /= 4;
    CHECK(equal(w, vec3(real(2.5), real(-1.5), real(4.5))));
    w[1] = 7;
    CHECK(w.y() == 7);
}

TEST_CASE("vec3: dot, cross and length on exact cases", "[vec3][ch01]") {
    const vec3 u(1, 2, 3), v(4, -5, 6);
    CHECK(dot(u, v) == 12);
    CHECK(equal(cross(u, v), vec3(27, 6, -13)));
    // The right-hand rule on the axes: x cross y = z, y cross z = x, z cross x = y.
    CHECK(equal(cross(vec3(1, 0, 0), vec3(0, 1, 0)), vec3(0, 0, 1)));
    CHECK(equal(cross(vec3(0, 1, 0), vec3(0, 0, 1)), vec3(1, 0, 0)));
    CHECK(equal(cross(vec3(0, 0, 1), vec3(1, 0, 0)), vec3(0, 1, 0)));
    CHECK(equal(cross(u, u), vec3(0, 0, 0)));
    // Pythagorean quadruples have exact lengths.
    CHECK(vec3(2, 3, 6).length_squared() == 49);
    CHECK(vec3(2, 3, 6).length() == 7);
    CHECK(vec3(-1, 2, -2).length() == 3);
    CHECK(vec3().length() == 0);
}

TEST_CASE("vec3: unit_vector has length one and keeps the direction", "[vec3][ch01]") {
    // v / |v| is computed as (1/|v|) * v: two roundings per component, so each component is within
    // 2 eps (relative) of the exact quotient, and |unit| within about 3 eps of 1 (sqrt adds one
    // more rounding, the sum of squares three more, halved by the square root).
    const vec3 u = rt::unit_vector(vec3(2, 3, 6));
    CHECK(std::fabs(u.x() - real(2) / 7) <= 2 * eps * real(2) / 7);
    CHECK(std::fabs(u.y() - real(3) / 7) <= 2 * eps * real(3) / 7);
    CHECK(std::fabs(u.z() - real(6) / 7) <= 2 * eps * real(6) / 7);

    rt::pcg32 rng(1, 2);
    for (int i = 0; i < 1000; ++i) {
        const vec3 v    = random_vec3(rng, real(1000));
        const vec3 unit = rt::unit_vector(v);
        CAPTURE(v, unit);
        CHECK(std::fabs(unit.length() - 1) <= 4 * eps);
        // Parallel and pointing the same way: the cross product vanishes up to rounding.
        CHECK(dot(unit, v) > 0);
        CHECK(cross(unit, v).length() <= 8 * eps * v.length());
    }
}

TEST_CASE("vec3: cross anti-commutes and is orthogonal to both factors", "[vec3][ch01]") {
    // On small integers every product and difference is exact, so anti-commutation is exact.
    const vec3 a(1, 2, 3), b(4, -5, 6);
    CHECK(equal(cross(a, b), -cross(b, a)));

    // For random vectors, each component x1*y2 - x2*y1 has at most three roundings of terms no
    // larger than |a||b|, so the error per component is below 2 eps |a||b| (with or without fused
    // multiply-add), and the error of the dot product with a adds 3 eps |cross||a|: together
    // below 10 eps |a|^2 |b| for the orthogonality residual.
    rt::pcg32 rng(3, 4);
    for (int i = 0; i < 1000; ++i) {
        const vec3 x = random_vec3(rng, real(10)), y = random_vec3(rng, real(0.1));
        const vec3 c     = cross(x, y);
        const real scale = x.length() * y.length();
        CAPTURE(x, y, c);
        CHECK((c + cross(y, x)).length() <= 4 * eps * scale);
        CHECK(std::fabs(dot(c, x)) <= 10 * eps * scale * x.length());
        CHECK(std::fabs(dot(c, y)) <= 10 * eps * scale * y.length());
        // |a x b|^2 + (a.b)^2 = |a|^2 |b|^2 (Lagrange): the length is |a||b| sin(theta).
        const real lagrange = c.length_squared() + dot(x, y) * dot(x, y);
        CHECK(std::fabs(lagrange - scale * scale) <= 16 * eps * scale * scale);
    }
}

TEST_CASE("vec3: near_zero and max_abs_component", "[vec3][ch01]") {
    // near_zero is strict (< s) on every component, negative ones by magnitude.
    CHECK(vec3(0, 0, 0).near_zero());
    CHECK(vec3(real(1e-9), real(-1e-9), 0).near_zero());
    CHECK_FALSE(vec3(real(1e-7), 0, 0).near_zero());
    CHECK_FALSE(vec3(0, real(-1e-7), 0).near_zero());
    CHECK_FALSE(vec3(0, 0, real(1e-8)).near_zero());  // the default s itself is not below s
    CHECK(vec3(real(0.5), real(-0.5), real(0.25)).near_zero(real(0.6)));
    CHECK_FALSE(vec3(real(0.5), real(-0.5), real(0.25)).near_zero(real(0.5)));

    CHECK(rt::max_abs_component(vec3(1, -7, 3)) == 7);
    CHECK(rt::max_abs_component(vec3(-2, 1, real(0.5))) == 2);
    CHECK(rt::max_abs_component(vec3(0, 0, -4)) == 4);
    CHECK(rt::max_abs_component(vec3()) == 0);
}

TEST_CASE("vec3: max_abs_component is fmax's value for every input, NaN and infinity included",
          "[vec3][hardcase][ch01]") {
    // The definition it replaces, bit for bit: fmax ignores a NaN argument.
    auto by_fmax = [](const vec3& v) {
        return std::fmax(std::fabs(v.x()), std::fmax(std::fabs(v.y()), std::fabs(v.z())));
    };
    auto same = [](real a, real b) {
        return (std::isnan(a) && std::isnan(b)) || (a == b && std::signbit(a) == std::signbit(b));
    };
    const real nan      = std::numeric_limits<real>::quiet_NaN();
    const real inf      = std::numeric_limits<real>::infinity();
    const real tiny     = std::numeric_limits<real>::denorm_min();
    const real values[] = {0,    real(-0.0), 1,   -1,   real(2.5), real(-1e30),
                           tiny, -tiny,      inf, -inf, nan};
    int cases           = 0;
    for (real x : values) {
        for (real y : values) {
            for (real z : values) {
                const vec3 v(x, y, z);
                INFO("v = (" << x << ", " << y << ", " << z << ")");
                CHECK(same(rt::max_abs_component(v), by_fmax(v)));
                ++cases;
            }
        }
    }
    CHECK(cases == 11 * 11 * 11);
    rt::pcg32 rng(1101, 3);
    for (int i = 0; i < 10000; ++i) {
        const vec3 v(rt_test::uniform(rng, -1e3, 1e3), rt_test::uniform(rng, -1e3, 1e3),
                     rt_test::uniform(rng, -1e3, 1e3));
        CHECK(same(rt::max_abs_component(v), by_fmax(v)));
    }
}
