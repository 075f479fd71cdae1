// Tests for mis_tracer.h (chapter 15): next-event estimation with the power heuristic and
// Russian roulette is unbiased. On the small scenes of ch14/estimator_scenes.h its mean radiance
// agrees with the closed form where there is one (a floor under a two-sided quad light, a sphere
// light, the gradient sky) and with the plain path tracer's and book 3's mixture's everywhere
// (smoke between a floor and a light, whose shadow rays take the exact transmittance; glass and
// metal, which are only sampled; a closed box, where roulette ends most paths), within 5
// standard errors. It never returns NaN, infinity or a negative radiance. And it is less noisy
// than the path tracer where a light is small, which is what it is for.
#include <catch2/catch.hpp>
#include <memory>

#include "ch14/estimator_scenes.h"
#include "rt/integrators/mis_tracer.h"
#include "rt/integrators/mixture_tracer.h"
#include "rt/integrators/path_tracer.h"
#include "rt/samplers/independent_sampler.h"

namespace {

using namespace rt_test::estimator_scenes;

}  // namespace

TEST_CASE("mis_tracer: the same mean as the path tracer, the mixture and the closed form",
          "[ch15]") {
    std::uint64_t seed = 200;
    for (const test_scene& sc : all_scenes()) {
        INFO(sc.name);
        const rt::path_tracer path(sc.world, sc.sky);
        const rt::mixture_tracer mixture(sc.world, sc.sky);
        const rt::mis_tracer mis(sc.world, sc.sky);
        const run by_path    = estimate(path, sc, 40000, seed++);
        const run by_mixture = estimate(mixture, sc, 20000, seed++);
        const run by_mis     = estimate(mis, sc, 40000, seed++);
        {
            INFO("mis");
            check_run(by_mis, sc);
        }
        {
            INFO("mis against the path tracer");
            check_same_mean(by_mis, by_path);
        }
        {
            INFO("mis against the mixture");
            check_same_mean(by_mis, by_mixture);
        }
    }
}

TEST_CASE("mis_tracer: less noise than the path tracer under a small light", "[ch15]") {
    // A sphere light of radius 0.1 at height 2: a cosine-sampled direction finds it once in
    // 400 tries, a light sample every time. The standard error must drop by more than 10
    // times (measured: 45), the means must agree, and the closed form (rho Le R^2 / h^2) hold.
    auto world = std::make_shared<rt::hittable_list>();
    world->add(floor_quad());
    world->add(std::make_shared<rt::sphere>(point3(0, 2, 0), rt::real(0.1), lamp(100)));
    const test_scene sc{"small sphere light",
                        world,
                        rt::background::uniform(rt::color(0, 0, 0)),
                        point3(3, 0.4, 0),
                        point3(0, 0, 0),
                        0,
                        5,
                        floor_albedo * 100 * 0.1 * 0.1 / (2 * 2)};
    const run by_path = estimate(rt::path_tracer(sc.world, sc.sky), sc, 20000, 301);
    const run by_mis  = estimate(rt::mis_tracer(sc.world, sc.sky), sc, 20000, 302);
    check_run(by_mis, sc);
    check_same_mean(by_path, by_mis);
    const double path_se = by_path.radiance.estimate().standard_error;
    const double mis_se  = by_mis.radiance.estimate().standard_error;
    INFO("standard errors: path " << path_se << ", mis " << mis_se);
    CHECK(mis_se * 10 < path_se);
}

TEST_CASE("mis_tracer: is named \"mis\", and a scene without lights is path traced", "[ch15]") {
    auto world = std::make_shared<rt::hittable_list>();
    world->add(floor_quad());
    const rt::mis_tracer dark(world, rt::background::uniform(rt::color(0, 0, 0)));
    CHECK(dark.name() == "mis");
    rt::independent_sampler s(5);
    int lit = 0;
    for (int k = 0; k < 100; ++k) {
        s.start_pixel_sample(0, 0, k);
        const rt::color L = dark.radiance(rt::ray(point3(0, 1, 0), vec3(0.2, -1, 0.1)), s, 5);
        lit += !rt_test::exactly(L, rt::color(0, 0, 0));
    }
    CHECK(lit == 0);
}
