// The furnace test (after Nori and pbrt-v4): one object in a uniform background of radiance 1, no
// floor. An object that neither creates nor destroys energy must look exactly as bright as the
// background; one that absorbs must look its albedo. Chapter 03 on; included as "ch03/furnace.h".
// Tolerances: 5 standard errors of the mean, see statistics.h.
#pragma once

#include <catch2/catch.hpp>
#include <cmath>
#include <memory>

#include "rt/camera/camera.h"
#include "rt/geometry/hittable.h"
#include "rt/integrators/path_tracer.h"
#include "rt/render/film.h"
#include "rt/samplers/independent_sampler.h"
#include "rt/scene/background.h"
#include "statistics.h"

namespace rt_test {

// Where the furnace's object stands: 4 in front of chapter 01's camera (at the origin, looking
// down -z), so that a sphere of radius 1 there fills about half of a 40-degree view.
inline const rt::point3 furnace_center(0, 0, -4);

struct furnace_result {
    running_mean on_object, off_object;  // red channel (every object here is gray)
    int non_finite = 0;
};

// Path traces a 48 x 48 view of `world` (objects about furnace_center, in a uniform background
// of 1) with 32 samples per pixel, and sorts each path by whether its camera ray hits the world.
inline furnace_result run_furnace(const std::shared_ptr<rt::hittable>& world, int max_depth = 50) {
    const rt::film f = rt::film::for_aspect(48, 1);
    rt::camera cam;
    cam.aspect_ratio = 1;
    cam.vfov         = 40;
    cam.initialize(f);
    const rt::path_tracer tracer(world, rt::background::uniform(rt::color(1, 1, 1)));

    furnace_result result;
    rt::independent_sampler s(1234);
    for (int j = 0; j < f.height; ++j) {
        for (int i = 0; i < f.width; ++i) {
            for (int k = 0; k < 32; ++k) {
                s.start_pixel_sample(i, j, k);
                const rt::ray r = cam.get_ray(i, j, s);
                rt::hit_record rec;
                const bool on     = world->hit(r, rt::interval(0, rt::infinity), rec);
                const rt::color L = tracer.radiance(r, s, max_depth);
                if (!std::isfinite(L.x()) || !std::isfinite(L.y()) || !std::isfinite(L.z()))
                    ++result.non_finite;
                (on ? result.on_object : result.off_object).add(double(L.x()));
            }
        }
    }
    return result;
}

// The mean of the samples is `expected` within 5 standard errors.
inline void check_furnace_mean(const running_mean& samples, double expected) {
    auto check = mean_within_tolerance(samples.estimate(), expected, 5);
    INFO(check.summary);
    CHECK(check.passed);
}

}  // namespace rt_test
