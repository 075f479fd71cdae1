// A sphere made of a material (rt/geometry/sphere.h, chapter 03's constructor): every hit reports
// the material, and a missing one is refused. The geometry is chapter 02's and tested there.
#include <catch2/catch.hpp>
#include <memory>

#include "ch03/material_helpers.h"
#include "rt/core/error.h"
#include "rt/geometry/sphere.h"

using rt::point3, rt::vec3;

TEST_CASE("sphere: a sphere made of a material reports it on every hit", "[ch03]") {
    auto mat = rt_test::any_material();
    const rt::sphere s(point3(0, 0, 0), 1, mat);
    CHECK(s.surface() == mat);
    rt::hit_record rec;
    // From outside, and from inside (the far root).
    REQUIRE(s.hit(rt::ray(point3(0, 0, -5), vec3(0, 0, 1)), rt::interval(0, rt::infinity), rec));
    CHECK(rec.mat == mat.get());
    rec.mat = nullptr;
    REQUIRE(s.hit(rt::ray(point3(0, 0, 0), vec3(1, 0, 0)), rt::interval(0, rt::infinity), rec));
    CHECK_FALSE(rec.front_face);
    CHECK(rec.mat == mat.get());
    // The material changes nothing of the geometry: the same hit as a sphere without one.
    const rt::sphere bare(point3(0, 0, 0), 1);
    rt::hit_record bare_rec;
    REQUIRE(
        bare.hit(rt::ray(point3(0, 0, 0), vec3(1, 0, 0)), rt::interval(0, rt::infinity), bare_rec));
    CHECK(bare_rec.t == rec.t);
    CHECK(bare.surface() == nullptr);
}

TEST_CASE("sphere: a missing material throws a user_error naming it", "[ch03]") {
    CHECK_THROWS_WITH(rt::sphere(point3(0, 0, 0), 1, nullptr),
                      Catch::Contains("sphere material is missing"));
    // The radius is still checked first, with or without a material.
    CHECK_THROWS_WITH(rt::sphere(point3(0, 0, 0), 0, rt_test::any_material()),
                      Catch::Contains("sphere radius"));
}
