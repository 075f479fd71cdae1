// Furnace tests of chapter 05's glass (ch03/furnace.h): clear glass in a uniform background of
// 1 neither loses nor gains energy, with either reflectance model, through total internal
// reflection too; and a path that ends on the glass brings nothing back.
#include <catch2/catch.hpp>
#include <memory>

#include "ch03/furnace.h"
#include "rt/geometry/sphere.h"
#include "rt/materials/dielectric.h"
#include "rt/scene/hittable_list.h"

namespace {

std::shared_ptr<rt::hittable> glass_sphere(rt::real radius, rt::real ior,
                                           rt::fresnel_model model = rt::fresnel_model::schlick) {
    return std::make_shared<rt::sphere>(rt_test::furnace_center, radius,
                                        std::make_shared<rt::dielectric>(ior, model));
}

}  // namespace

TEST_CASE("furnace: a glass sphere neither loses nor gains energy", "[ch05]") {
    auto result = rt_test::run_furnace(glass_sphere(1, 1.5));
    CHECK(result.non_finite == 0);
    rt_test::check_furnace_mean(result.on_object, 1.0);
    rt_test::check_furnace_mean(result.off_object, 1.0);
}

TEST_CASE("furnace: a glass sphere with exact Fresnel neither loses nor gains energy", "[ch05]") {
    auto result = rt_test::run_furnace(glass_sphere(1, 1.5, rt::fresnel_model::exact));
    CHECK(result.non_finite == 0);
    rt_test::check_furnace_mean(result.on_object, 1.0);
    rt_test::check_furnace_mean(result.off_object, 1.0);
}

TEST_CASE("furnace: a glass sphere with an air bubble (total internal reflection) gives 1",
          "[ch05][hardcase]") {
    for (auto model : {rt::fresnel_model::schlick, rt::fresnel_model::exact}) {
        auto world = std::make_shared<rt::hittable_list>();
        world->add(glass_sphere(1, 1.5, model));
        world->add(glass_sphere(rt::real(0.8), 1 / rt::real(1.5), model));
        auto result = rt_test::run_furnace(world);
        INFO((model == rt::fresnel_model::exact ? "exact" : "schlick"));
        CHECK(result.non_finite == 0);
        rt_test::check_furnace_mean(result.on_object, 1.0);
    }
}

TEST_CASE("furnace: a glass sphere at max depth 1 returns nothing past its surface", "[ch05]") {
    // One segment: the camera ray hits the glass and the path ends before seeing the background.
    auto result = rt_test::run_furnace(glass_sphere(1, 1.5), 1);
    auto on     = result.on_object.estimate();
    CHECK(on.mean == 0);
    rt_test::check_furnace_mean(result.off_object, 1.0);
}
