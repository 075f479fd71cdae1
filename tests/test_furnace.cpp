// Furnace tests: one object in a uniform background of radiance 1, no floor. An object that
// neither creates nor destroys energy must look exactly as bright as the background; one that
// absorbs must look its albedo. These catch lost or doubled energy, total internal reflection
// bugs and self-intersection all at once. Tolerances: 5 standard errors of the mean (by the
// central limit theorem a false failure has probability ~6e-7), see statistics.h.
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>

#include "common/dielectric.h"
#include "common/integrator.h"
#include "common/lambertian.h"
#include "common/metal.h"
#include "common/sphere.h"
#include "statistics.h"

using rt::color, rt::point3, rt::real, rt::vec3;

namespace {

struct furnace_result {
    rt_test::running_mean on_object, off_object;  // red channel (all objects here are gray)
    int non_finite = 0;
};

// Renders a 48x48 view of the unit-radius world at the origin from (0, 0, 4) with 32 samples
// per pixel, and sorts each path by whether its camera ray hits the world.
furnace_result run_furnace(rt::hittable_list world, int max_depth = 50) {
    rt::scene sc;
    sc.world            = std::move(world);
    sc.sky              = rt::background::uniform(color(1, 1, 1));
    sc.cam.aspect_ratio = 1;
    sc.cam.image_width  = 48;
    sc.cam.vfov         = 40;
    sc.cam.lookfrom     = point3(0, 0, 4);
    sc.cam.lookat       = point3(0, 0, 0);
    sc.cam.initialize();

    furnace_result result;
    rt::sampler s(1234);
    for (int j = 0; j < 48; ++j) {
        for (int i = 0; i < 48; ++i) {
            for (int k = 0; k < 32; ++k) {
                s.start_pixel_sample(i, j, k);
                rt::ray r = sc.cam.get_ray(i, j, s);
                rt::hit_record rec;
                bool on = sc.world.hit(r, rt::interval(0, rt::infinity), rec);
                color L = rt::trace_path(sc, r, s, max_depth);
                if (!std::isfinite(L.x()) || !std::isfinite(L.y()) || !std::isfinite(L.z()))
                    ++result.non_finite;
                (on ? result.on_object : result.off_object).add(double(L.x()));
            }
        }
    }
    return result;
}

void check_mean(const rt_test::running_mean& samples, double expected) {
    auto check = rt_test::mean_within_tolerance(samples.estimate(), expected, 5);
    INFO(check.summary);
    CHECK(check.passed);
}

rt::hittable_list one_sphere(std::shared_ptr<rt::material> mat) {
    return rt::hittable_list(std::make_shared<rt::sphere>(point3(0, 0, 0), 1, std::move(mat)));
}

}  // namespace

TEST_CASE("furnace: a Lambertian sphere shows its albedo, the background shows 1", "[ch03]") {
    auto result = run_furnace(one_sphere(std::make_shared<rt::lambertian>(color(0.6, 0.6, 0.6))));
    CHECK(result.non_finite == 0);
    REQUIRE(result.on_object.count() > 1000);
    check_mean(result.on_object, 0.6);
    check_mean(result.off_object, 1.0);
}

TEST_CASE("furnace: a polished metal sphere shows its albedo", "[ch04]") {
    auto result = run_furnace(one_sphere(std::make_shared<rt::metal>(color(0.7, 0.7, 0.7), 0)));
    CHECK(result.non_finite == 0);
    check_mean(result.on_object, 0.7);
    check_mean(result.off_object, 1.0);
}

TEST_CASE("furnace: a glass sphere neither loses nor gains energy", "[ch05]") {
    auto result = run_furnace(one_sphere(std::make_shared<rt::dielectric>(1.5)));
    CHECK(result.non_finite == 0);
    check_mean(result.on_object, 1.0);
    check_mean(result.off_object, 1.0);
}

TEST_CASE("furnace: a glass sphere with an air bubble (total internal reflection) gives 1",
          "[ch05][hardcase]") {
    rt::hittable_list world;
    world.add(
        std::make_shared<rt::sphere>(point3(0, 0, 0), 1, std::make_shared<rt::dielectric>(1.5)));
    world.add(std::make_shared<rt::sphere>(point3(0, 0, 0), 0.8,
                                           std::make_shared<rt::dielectric>(1 / 1.5)));
    auto result = run_furnace(std::move(world));
    CHECK(result.non_finite == 0);
    check_mean(result.on_object, 1.0);
}

TEST_CASE("furnace: a glass sphere at max depth 1 returns nothing past its surface", "[ch05]") {
    // One segment: the camera ray hits the glass and the path ends before seeing the background.
    auto result = run_furnace(one_sphere(std::make_shared<rt::dielectric>(1.5)), 1);
    auto on     = result.on_object.estimate();
    CHECK(on.mean == 0);
    check_mean(result.off_object, 1.0);
}
