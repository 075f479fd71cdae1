// Furnace test of chapter 03's material (ch03/furnace.h): a Lambertian sphere in a uniform
// background of 1 must look exactly its albedo, and the background around it 1.
#include <catch2/catch.hpp>
#include <memory>

#include "ch03/furnace.h"
#include "rt/geometry/sphere.h"
#include "rt/materials/lambertian.h"

using rt::color;

TEST_CASE("furnace: a Lambertian sphere shows its albedo, the background shows 1", "[ch03]") {
    auto result = rt_test::run_furnace(std::make_shared<rt::sphere>(
        rt_test::furnace_center, 1, std::make_shared<rt::lambertian>(color(0.6, 0.6, 0.6))));
    CHECK(result.non_finite == 0);
    REQUIRE(result.on_object.count() > 1000);
    rt_test::check_furnace_mean(result.on_object, 0.6);
    rt_test::check_furnace_mean(result.off_object, 1.0);
}
