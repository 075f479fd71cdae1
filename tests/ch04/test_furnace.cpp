// Furnace test of chapter 04's material (ch03/furnace.h): a polished metal sphere in a uniform
// background of 1 must look exactly its albedo.
#include <catch2/catch.hpp>
#include <memory>

#include "ch03/furnace.h"
#include "rt/geometry/sphere.h"
#include "rt/materials/metal.h"

using rt::color;

TEST_CASE("furnace: a polished metal sphere shows its albedo", "[ch04]") {
    auto result = rt_test::run_furnace(std::make_shared<rt::sphere>(
        rt_test::furnace_center, 1, std::make_shared<rt::metal>(color(0.7, 0.7, 0.7), 0)));
    CHECK(result.non_finite == 0);
    rt_test::check_furnace_mean(result.on_object, 0.7);
    rt_test::check_furnace_mean(result.off_object, 1.0);
}
