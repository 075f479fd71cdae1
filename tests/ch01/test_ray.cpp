// ray (rt/core/ray.h): P(t) = A + t b, and continued(), the next segment of the same path.
// Chapter 01. (The instant a ray carries, and that continued() keeps it, is chapter 07's.)
#include <catch2/catch.hpp>

#include "rt/core/ray.h"
#include "test_helpers.h"

using rt::point3;
using rt::real;
using rt::vec3;

namespace {

// Bit-for-bit equality of vectors (rt_test::exactly), under the name the checks read best with.
bool (&equal)(const vec3&, const vec3&) = rt_test::exactly;

}  // namespace

TEST_CASE("ray: at(t) walks along the direction from the origin", "[ray][ch01]") {
    const rt::ray r(point3(1, 2, 3), vec3(4, 5, 6));
    // Small integers and halves: every product and sum is exact.
    CHECK(equal(r.at(0), point3(1, 2, 3)));
    CHECK(equal(r.at(1), point3(5, 7, 9)));
    CHECK(equal(r.at(2), point3(9, 12, 15)));
    CHECK(equal(r.at(real(-0.5)), point3(-1, real(-0.5), 0)));
    // The direction is kept as given, not normalized: t is measured in units of |b|.
    CHECK(equal(r.direction(), vec3(4, 5, 6)));
    CHECK(equal(r.origin(), point3(1, 2, 3)));
}

TEST_CASE("ray: a default ray starts at the origin with a zero direction", "[ray][ch01]") {
    const rt::ray none;
    CHECK(equal(none.origin(), point3(0, 0, 0)));
    CHECK(equal(none.direction(), vec3(0, 0, 0)));
}

TEST_CASE("ray: continued() gives a new origin and direction and leaves the ray alone",
          "[ray][ch01]") {
    const rt::ray first(point3(1, 2, 3), vec3(4, 5, 6));
    const rt::ray next = first.continued(point3(-1, real(0.5), 7), vec3(0, -2, real(0.25)));
    // Both are taken as given, bit for bit: not normalized, not offset.
    CHECK(equal(next.origin(), point3(-1, real(0.5), 7)));
    CHECK(equal(next.direction(), vec3(0, -2, real(0.25))));
    CHECK(equal(next.at(2), point3(-1, real(-3.5), real(7.5))));
    // The ray it continues is a value, unchanged.
    CHECK(equal(first.origin(), point3(1, 2, 3)));
    CHECK(equal(first.direction(), vec3(4, 5, 6)));
}
