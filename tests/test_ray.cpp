// ray (common/ray.h): P(t) = A + t b, and the instant the ray travels at. Chapter 01.
#include <catch2/catch.hpp>

#include "common/ray.h"
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

TEST_CASE("ray: the time is carried and defaults to zero", "[ray][ch01]") {
    const rt::ray still(point3(0, 0, 0), vec3(0, 0, -1));
    CHECK(still.time() == 0);
    const rt::ray moving(point3(0, 0, 0), vec3(0, 0, -1), real(0.25));
    CHECK(moving.time() == real(0.25));
    // at() does not depend on the time: motion belongs to the objects, not the ray.
    CHECK(equal(moving.at(2), still.at(2)));

    const rt::ray none;
    CHECK(equal(none.origin(), point3(0, 0, 0)));
    CHECK(equal(none.direction(), vec3(0, 0, 0)));
    CHECK(none.time() == 0);
}
