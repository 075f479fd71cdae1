// interval (rt/core/interval.h): closed [min, max] ranges of t and of color channels. Chapter 02.
#include <catch2/catch.hpp>

#include "rt/core/interval.h"

using rt::infinity;
using rt::interval;
using rt::real;

TEST_CASE("interval: contains is closed, surrounds is open", "[interval][ch02]") {
    const interval i(1, 3);
    CHECK(i.size() == 2);
    CHECK(i.contains(1));
    CHECK(i.contains(2));
    CHECK(i.contains(3));
    CHECK_FALSE(i.contains(real(0.999)));
    CHECK_FALSE(i.contains(real(3.001)));
    // surrounds excludes the ends: a hit at exactly t_min (the surface a ray leaves) is rejected.
    CHECK_FALSE(i.surrounds(1));
    CHECK(i.surrounds(2));
    CHECK_FALSE(i.surrounds(3));

    // A single point contains itself but surrounds nothing.
    const interval point(2, 2);
    CHECK(point.size() == 0);
    CHECK(point.contains(2));
    CHECK_FALSE(point.surrounds(2));
}

TEST_CASE("interval: clamp keeps values inside", "[interval][ch02]") {
    const interval unit(0, 1);
    CHECK(unit.clamp(real(-0.5)) == 0);
    CHECK(unit.clamp(real(0.25)) == real(0.25));
    CHECK(unit.clamp(2) == 1);
    CHECK(unit.clamp(-infinity) == 0);
    CHECK(unit.clamp(infinity) == 1);
    CHECK(unit.clamp(0) == 0);
    CHECK(unit.clamp(1) == 1);
}

TEST_CASE("interval: empty holds nothing and universe holds everything", "[interval][ch02]") {
    const interval empty = interval::empty();
    const interval by_default;
    CHECK(by_default.min == empty.min);
    CHECK(by_default.max == empty.max);
    CHECK(empty.min > empty.max);
    CHECK(empty.size() < 0);
    for (real x : {-infinity, real(-1), real(0), real(1e30), infinity}) {
        CAPTURE(x);
        CHECK_FALSE(empty.contains(x));
        CHECK_FALSE(empty.surrounds(x));
    }

    const interval universe = interval::universe();
    CHECK(universe.size() == infinity);
    for (real x : {real(-1e30), real(-1), real(0), real(1), real(1e30)}) {
        CAPTURE(x);
        CHECK(universe.contains(x));
        CHECK(universe.surrounds(x));
        CHECK(universe.clamp(x) == x);
    }
    // The closed universe includes its infinite ends; the open one does not.
    CHECK(universe.contains(infinity));
    CHECK(universe.contains(-infinity));
    CHECK_FALSE(universe.surrounds(infinity));
}
