// Small scenes for testing that an estimator of chapters 14 and 15 (book 3's mixture, next-event
// estimation with MIS) is unbiased: each one's mean radiance along a bundle of camera rays must
// agree with the plain path tracer's (chapter 03), and with a closed form where there is one.
// Included as "ch14/estimator_scenes.h".
//
// Closed forms, for a diffuse floor (albedo rho) seen at the point o below a light of radiance
// Le and nothing else in the scene (the floor cannot see itself, so one bounce is all there is):
//   L = rho / pi * Le * integral of cos theta over the directions that see the light.
// - A square of half-side a, parallel to the floor at height h, centered above o: four times
//   the form factor to a rectangle a x a with a corner above o (the differential-area-to-parallel-
//   rectangle factor of radiative transfer tables),
//     F(a, a, h) = 1/(2 pi) [A/sqrt(1 + A^2) atan(A/sqrt(1 + A^2)) * 2],  A = a / h,
//   and the integral of cos is pi * 4 F.
// - A sphere of radius R whose center is at height h above o (R < h): its cone, of
//   sin theta_max = R / h, is centered on the normal, and the integral of cos over it is
//   pi sin^2 theta_max. So L = rho Le R^2 / h^2.
// - The sky of background.h, L(y) = bottom + (y + 1)/2 (top - bottom), over the upper
//   hemisphere (y = cos theta): the integrals of cos and cos^2 are pi and 2 pi / 3, so
//   L = rho [(bottom + top) / 2 + (top - bottom) / 3].
// Tolerances: 5 standard errors (statistics.h), of one mean against a closed form, or of the
// difference of two independent means against 0.
#pragma once

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "rt/geometry/box.h"
#include "rt/geometry/quad.h"
#include "rt/geometry/sphere.h"
#include "rt/integrators/estimator.h"
#include "rt/materials/dielectric.h"
#include "rt/materials/diffuse_light.h"
#include "rt/materials/lambertian.h"
#include "rt/materials/metal.h"
#include "rt/media/constant_medium.h"
#include "rt/samplers/independent_sampler.h"
#include "rt/scene/background.h"
#include "rt/scene/hittable_list.h"
#include "statistics.h"
#include "test_helpers.h"

namespace rt_test::estimator_scenes {

using rt::color, rt::point3, rt::real, rt::vec3;

inline constexpr double pi = 3.14159265358979323846;

struct test_scene {
    std::string name;
    std::shared_ptr<rt::hittable> world;
    rt::background sky;
    point3 eye;     // camera rays start here ...
    point3 target;  // ... and aim at a point within `spread` of this one
    real spread;    // 0: the same ray every time
    int max_depth;
    double expected;  // the closed form of the mean over the channels, or NaN if none
};

inline const double no_closed_form   = std::numeric_limits<double>::quiet_NaN();
inline constexpr double floor_albedo = 0.5, light_radiance = 5;

inline std::shared_ptr<rt::quad> floor_quad() {
    return std::make_shared<rt::quad>(
        point3(-50, 0, -50), vec3(100, 0, 0), vec3(0, 0, 100),
        std::make_shared<rt::lambertian>(color(floor_albedo, floor_albedo, floor_albedo)));
}

inline std::shared_ptr<rt::material> lamp(double radiance = light_radiance) {
    return std::make_shared<rt::diffuse_light>(color(radiance, radiance, radiance));
}

// A square light of half-side a at height h above the origin, facing up (away from the floor:
// two-sided emission is what lights it).
inline test_scene quad_light_over_floor() {
    const double a = 1, h = 1, A = a / h;
    const double corner =
        1 / (2 * pi) * 2 * A / std::sqrt(1 + A * A) * std::atan(A / std::sqrt(1 + A * A));
    auto world = std::make_shared<rt::hittable_list>();
    world->add(floor_quad());
    world->add(std::make_shared<rt::quad>(point3(-a, h, -a), vec3(0, 0, 2 * a), vec3(2 * a, 0, 0),
                                          lamp()));
    return {"quad light over a floor",
            world,
            rt::background::uniform(color(0, 0, 0)),
            point3(3, 0.4, 0),
            point3(0, 0, 0),
            0,
            5,
            floor_albedo * light_radiance * 4 * corner};
}

// A sphere light of radius 1 whose center is 2 above the origin.
inline test_scene sphere_light_over_floor() {
    const double R = 1, h = 2;
    auto world = std::make_shared<rt::hittable_list>();
    world->add(floor_quad());
    world->add(std::make_shared<rt::sphere>(point3(0, h, 0), R, lamp()));
    return {"sphere light over a floor",
            world,
            rt::background::uniform(color(0, 0, 0)),
            point3(3, 0.4, 0),
            point3(0, 0, 0),
            0,
            5,
            floor_albedo * light_radiance * R * R / (h * h)};
}

// Chapter 01's gradient sky over the floor alone.
inline test_scene sky_over_floor() {
    auto world = std::make_shared<rt::hittable_list>();
    world->add(floor_quad());
    const rt::background sky = rt::background::sky();
    double expected          = 0;
    for (int i = 0; i < 3; ++i) {
        const double b = sky.bottom[i], t = sky.top[i];
        expected += floor_albedo * ((b + t) / 2 + (t - b) / 3) / 3;
    }
    return {"gradient sky over a floor",
            world,
            sky,
            point3(3, 0.4, 0),
            point3(0, 0, 0),
            0,
            5,
            expected};
}

// A box of smoke between the floor and a light above it, seen through the smoke.
inline test_scene medium_between_floor_and_light() {
    auto world = std::make_shared<rt::hittable_list>();
    world->add(floor_quad());
    world->add(
        std::make_shared<rt::quad>(point3(-1, 3, -1), vec3(2, 0, 0), vec3(0, 0, 2), lamp(8)));
    world->add(std::make_shared<rt::constant_medium>(
        rt::box(point3(-1.5, 0.5, -1.5), point3(1.5, 2, 1.5),
                std::make_shared<rt::lambertian>(color(0.5, 0.5, 0.5))),
        real(0.6), color(0.8, 0.8, 0.8)));
    return {"a medium between a floor and a light",
            world,
            rt::background::uniform(color(0, 0, 0)),
            point3(4, 1.5, 0.3),
            point3(0, 0.8, 0),
            real(0.5),
            8,
            no_closed_form};
}

// A glass sphere and a fuzzy metal sphere on a floor under a light: materials that are only
// sampled, between the floor and the light.
inline test_scene glass_over_floor() {
    auto world = std::make_shared<rt::hittable_list>();
    world->add(floor_quad());
    world->add(std::make_shared<rt::quad>(point3(-0.75, 2.5, -0.75), vec3(1.5, 0, 0),
                                          vec3(0, 0, 1.5), lamp(6)));
    world->add(std::make_shared<rt::sphere>(point3(0, 0.6, 0), real(0.5),
                                            std::make_shared<rt::dielectric>(real(1.5))));
    world->add(
        std::make_shared<rt::sphere>(point3(1.2, 0.5, 0.2), real(0.4),
                                     std::make_shared<rt::metal>(color(0.8, 0.7, 0.6), real(0.3))));
    return {"glass and metal over a floor, under a light",
            world,
            rt::background::uniform(color(0, 0, 0)),
            point3(0.5, 2, 3),
            point3(0.3, 0.1, 0.3),
            real(0.6),
            8,
            no_closed_form};
}

// Inside a closed diffuse box with a light below its ceiling: long paths, where Russian
// roulette ends most of them, and a sky that cannot be seen (but is bright: a light that never
// contributes).
inline test_scene closed_box() {
    auto world = std::make_shared<rt::hittable_list>();
    auto wall  = std::make_shared<rt::lambertian>(color(0.75, 0.75, 0.75));
    world->add(rt::box(point3(-1, -1, -1), point3(1, 1, 1), wall));
    world->add(std::make_shared<rt::quad>(point3(-0.4, 0.95, -0.4), vec3(0.8, 0, 0),
                                          vec3(0, 0, 0.8), lamp(4)));
    return {"inside a closed box",
            world,
            rt::background::uniform(color(1, 1, 1)),
            point3(0, 0, 0.9),
            point3(0.3, -0.6, -1),
            real(0.8),
            40,
            no_closed_form};
}

inline std::vector<test_scene> all_scenes() {
    return {quad_light_over_floor(),          sphere_light_over_floor(), sky_over_floor(),
            medium_between_floor_and_light(), glass_over_floor(),        closed_box()};
}

struct run {
    running_mean radiance;  // the mean over the channels, per sample
    int non_finite = 0, negative = 0;
};

// n samples of est along the scene's camera rays: sample k starts the sampler at pixel sample
// (0, 0, k) of `seed`, and its camera ray aims at a point drawn from its own stream of `seed`.
inline run estimate(const rt::radiance_estimator& est, const test_scene& sc, int n,
                    std::uint64_t seed) {
    run result;
    rt::independent_sampler s(seed);
    rt::pcg32 aim(seed, 99);
    for (int k = 0; k < n; ++k) {
        s.start_pixel_sample(0, 0, k);
        point3 at = sc.target;
        if (sc.spread > 0) at = at + sc.spread * rt_test::random_unit(aim);
        const color L = est.radiance(rt::ray(sc.eye, at - sc.eye), s, sc.max_depth);
        for (int i = 0; i < 3; ++i) {
            result.non_finite += !std::isfinite(L[i]);
            result.negative += L[i] < 0;
        }
        result.radiance.add((double(L.x()) + double(L.y()) + double(L.z())) / 3);
    }
    return result;
}

// The run's radiance is finite and not negative, and its mean is the closed form (if any).
inline void check_run(const run& r, const test_scene& sc) {
    CHECK(r.non_finite == 0);
    CHECK(r.negative == 0);
    if (!std::isnan(sc.expected)) {
        auto check = mean_within_tolerance(r.radiance.estimate(), sc.expected, 5);
        INFO("against the closed form: " << check.summary);
        CHECK(check.passed);
    }
}

// Two independent runs have the same mean: their difference is within 5 standard errors of 0.
inline void check_same_mean(const run& a, const run& b) {
    const mean_estimate ea = a.radiance.estimate(), eb = b.radiance.estimate();
    const double se =
        std::sqrt(ea.standard_error * ea.standard_error + eb.standard_error * eb.standard_error);
    const double difference = ea.mean - eb.mean;
    INFO("means " << ea.mean << " +- " << ea.standard_error << " and " << eb.mean << " +- "
                  << eb.standard_error << ": differ by " << difference << " = " << difference / se
                  << " standard errors of the difference");
    CHECK(std::fabs(difference) <= 5 * se);
}

}  // namespace rt_test::estimator_scenes
