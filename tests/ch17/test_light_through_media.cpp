// Tests for light_through_media::expected (mis_tracer.h): the light met behind a medium counted
// by its exact transmittance instead of by the medium's random hit. It must keep the mean of
// chapter 15's mis (and of the plain path tracer) on every scene of ch14/estimator_scenes.h and
// on two of its own: a lamp seen through thin mist, and a lamp whose shape an instance places a
// second time (the copy is not the light: the path must count its emission as it meets it);
// within 5 standard errors. And it must be far less noisy where a lamp is seen through mist,
// which is what it is for.
#include <catch2/catch.hpp>
#include <memory>

#include "ch14/estimator_scenes.h"
#include "rt/geometry/instance.h"
#include "rt/integrators/mis_tracer.h"
#include "rt/integrators/path_tracer.h"

namespace {

using namespace rt_test::estimator_scenes;

// A lamp straight ahead, 6 units away, across a floor, everything inside thin mist (optical
// depth about 0.1 along the view, as book 2's final scene's mist): most samples see the lamp,
// a tenth scatter first.
test_scene lamp_through_mist() {
    auto world = std::make_shared<rt::hittable_list>();
    world->add(floor_quad());
    world->add(
        std::make_shared<rt::quad>(point3(-1, 0.5, -6), vec3(2, 0, 0), vec3(0, 2, 0), lamp(8)));
    world->add(std::make_shared<rt::constant_medium>(
        std::make_shared<rt::sphere>(point3(0, 0, 0), real(20),
                                     std::make_shared<rt::lambertian>(color(0.5, 0.5, 0.5))),
        real(0.016), color(1, 1, 1)));
    return {"a lamp seen through thin mist",
            world,
            rt::background::uniform(color(0, 0, 0)),
            point3(0, 1.5, 0),
            point3(0, 1.5, -6),
            real(0.5),
            8,
            no_closed_form};
}

// The lamp of quad_light_over_floor() placed a second time by an instance, beside the first:
// the copy shines (it is the same shape) but is no light of the light set.
test_scene lamp_and_its_copy() {
    auto world = std::make_shared<rt::hittable_list>();
    world->add(floor_quad());
    auto shape =
        std::make_shared<rt::quad>(point3(-0.5, 1, -0.5), vec3(1, 0, 0), vec3(0, 0, 1), lamp(5));
    world->add(shape);
    world->add(std::make_shared<rt::translate>(shape, vec3(1.5, 0.5, 0)));
    world->add(std::make_shared<rt::constant_medium>(
        rt::box(point3(-3, 0.01, -3), point3(3, 2.5, 3),
                std::make_shared<rt::lambertian>(color(0.5, 0.5, 0.5))),
        real(0.2), color(0.7, 0.7, 0.7)));
    return {"a lamp and its copy placed by an instance, in smoke",
            world,
            rt::background::uniform(color(0, 0, 0)),
            point3(3, 0.4, 2.5),
            point3(0.7, 1, 0),
            real(0.9),
            8,
            no_closed_form};
}

}  // namespace

TEST_CASE("light_through_media::expected: the mean of mis and of the path tracer", "[ch17]") {
    std::uint64_t seed             = 700;
    std::vector<test_scene> scenes = all_scenes();
    scenes.push_back(lamp_through_mist());
    scenes.push_back(lamp_and_its_copy());
    for (const test_scene& sc : scenes) {
        INFO(sc.name);
        const rt::path_tracer path(sc.world, sc.sky);
        const rt::mis_tracer sampled(sc.world, sc.sky);
        const rt::mis_tracer expected(sc.world, sc.sky, {rt::light_through_media::expected});
        const run by_path     = estimate(path, sc, 40000, seed++);
        const run by_sampled  = estimate(sampled, sc, 40000, seed++);
        const run by_expected = estimate(expected, sc, 40000, seed++);
        check_run(by_expected, sc);
        {
            INFO("against mis");
            check_same_mean(by_expected, by_sampled);
        }
        {
            INFO("against the path tracer");
            check_same_mean(by_expected, by_path);
        }
    }
}

TEST_CASE("light_through_media::expected: a lamp seen through mist stops speckling", "[ch17]") {
    // With the lamp counted by a random hit, a tenth of the samples lose it: the standard error
    // must drop by more than 3 times.
    const test_scene sc   = lamp_through_mist();
    const run by_sampled  = estimate(rt::mis_tracer(sc.world, sc.sky), sc, 20000, 801);
    const run by_expected = estimate(
        rt::mis_tracer(sc.world, sc.sky, {rt::light_through_media::expected}), sc, 20000, 802);
    check_same_mean(by_sampled, by_expected);
    const double sampled_se  = by_sampled.radiance.estimate().standard_error;
    const double expected_se = by_expected.radiance.estimate().standard_error;
    INFO("standard errors: sampled " << sampled_se << ", expected " << expected_se);
    CHECK(expected_se * 3 < sampled_se);
}

TEST_CASE("light_through_media::expected: is named \"mis-expected\"", "[ch17]") {
    const test_scene sc = lamp_through_mist();
    CHECK(rt::mis_tracer(sc.world, sc.sky, {rt::light_through_media::expected}).name() ==
          "mis-expected");
    CHECK(rt::mis_tracer(sc.world, sc.sky).name() == "mis");
}
