// Tests for mixture_tracer.h (chapter 14): book 3's mixture of the material's density and the
// lights' is unbiased. On small scenes (ch14/estimator_scenes.h) its mean radiance agrees with
// the closed form where there is one (a floor under a quad light, a sphere light, the gradient
// sky) and with the plain path tracer's everywhere (smoke between a floor and a light; glass and
// metal, which are only sampled; a closed box with long paths), within 5 standard errors. And it
// never returns NaN, infinity or a negative radiance.
#include <catch2/catch.hpp>

#include "ch14/estimator_scenes.h"
#include "rt/integrators/mixture_tracer.h"
#include "rt/integrators/path_tracer.h"
#include "rt/samplers/independent_sampler.h"

namespace {

using namespace rt_test::estimator_scenes;

}  // namespace

TEST_CASE("mixture_tracer: the same mean as the path tracer, and as the closed form", "[ch14]") {
    std::uint64_t seed = 100;
    for (const test_scene& sc : all_scenes()) {
        INFO(sc.name);
        const rt::path_tracer path(sc.world, sc.sky);
        const rt::mixture_tracer mixture(sc.world, sc.sky);
        const run by_path    = estimate(path, sc, 40000, seed++);
        const run by_mixture = estimate(mixture, sc, 40000, seed++);
        {
            INFO("path tracer");
            check_run(by_path, sc);
        }
        {
            INFO("mixture");
            check_run(by_mixture, sc);
        }
        check_same_mean(by_path, by_mixture);
    }
}

TEST_CASE("mixture_tracer: is named \"light\", and a scene without lights is path traced",
          "[ch14]") {
    // Under a black sky with nothing that emits, there is no light to aim at: the mixture must
    // reduce to sampling the material alone (and see nothing but black).
    auto world = std::make_shared<rt::hittable_list>();
    world->add(floor_quad());
    const rt::mixture_tracer dark(world, rt::background::uniform(rt::color(0, 0, 0)));
    CHECK(dark.name() == "light");
    rt::independent_sampler s(5);
    int lit = 0;
    for (int k = 0; k < 100; ++k) {
        s.start_pixel_sample(0, 0, k);
        const rt::color L = dark.radiance(rt::ray(point3(0, 1, 0), vec3(0.2, -1, 0.1)), s, 5);
        lit += !rt_test::exactly(L, rt::color(0, 0, 0));
    }
    CHECK(lit == 0);
}
