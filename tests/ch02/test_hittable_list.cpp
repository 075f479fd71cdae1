// Tests for hittable_list.h (chapter 02): the nearest hit among several objects. (The box around
// them all is chapter 07's.)
#include <catch2/catch.hpp>
#include <memory>

#include "rt/geometry/sphere.h"
#include "rt/scene/hittable_list.h"

namespace {

using rt::point3, rt::real, rt::vec3;

}  // namespace

TEST_CASE("hittable_list: the nearest of several hits wins, whatever the order", "[ch02]") {
    auto near_sphere = std::make_shared<rt::sphere>(point3(0, 0, -3), 1);
    auto far_sphere  = std::make_shared<rt::sphere>(point3(0, 0, -10), 2);
    const rt::ray r(point3(0, 0, 0), vec3(0, 0, -1));
    for (bool near_first : {true, false}) {
        rt::hittable_list list;
        list.add(near_first ? near_sphere : far_sphere);
        list.add(near_first ? far_sphere : near_sphere);
        rt::hit_record rec;
        REQUIRE(list.hit(r, rt::interval(0, rt::infinity), rec));
        CHECK(rec.t == 2);
        // Beyond the near sphere (t in (4.5, inf)), the far one is what is left.
        REQUIRE(list.hit(r, rt::interval(4.5, rt::infinity), rec));
        CHECK(rec.t == 8);
    }
    rt::hittable_list empty;
    rt::hit_record rec;
    CHECK_FALSE(empty.hit(r, rt::interval::universe(), rec));
}

TEST_CASE("hittable_list: a list inside a list finds the same nearest hit", "[ch02]") {
    // Objects behind, overlapping and in front of one another: the inner list's nearest hit
    // competes with the outer list's objects like any other object.
    auto a     = std::make_shared<rt::sphere>(point3(0, 0, -3), 1);    // hit at t = 2
    auto b     = std::make_shared<rt::sphere>(point3(0, 0, -5), 2.5);  // hit at t = 2.5
    auto c     = std::make_shared<rt::sphere>(point3(0, 0, -9), 1);    // hit at t = 8
    auto inner = std::make_shared<rt::hittable_list>();
    inner->add(c);
    inner->add(a);
    rt::hittable_list outer;
    outer.add(b);
    outer.add(inner);
    const rt::ray r(point3(0, 0, 0), vec3(0, 0, -1));
    rt::hit_record rec;
    REQUIRE(outer.hit(r, rt::interval(0, rt::infinity), rec));
    CHECK(rec.t == 2);
    REQUIRE(outer.hit(r, rt::interval(2, rt::infinity), rec));  // past a's front: b
    CHECK(rec.t == real(2.5));
    REQUIRE(outer.hit(r, rt::interval(7.5, rt::infinity), rec));  // past b's back (t = 7.5): c
    CHECK(rec.t == 8);
    CHECK_FALSE(outer.hit(r, rt::interval(10, rt::infinity), rec));
}
