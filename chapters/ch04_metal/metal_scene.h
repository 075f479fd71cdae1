// Chapter 04's report scene: book 1's metal spheres under the default sky, seen by the default
// camera. Later chapters' programs render it as --scene ch04.
#pragma once

#include <memory>

#include "rt/geometry/sphere.h"
#include "rt/materials/lambertian.h"
#include "rt/materials/metal.h"
#include "rt/scene/hittable_list.h"
#include "rt/scene/scene.h"

// Book 1's metal scene: a matte sphere between a metal of fuzz 0.3 (a mirror whose reflections
// are blurred) and one of fuzz 1.0 (so fuzzy it looks almost matte).
inline rt::scene metal_spheres() {
    using rt::color, rt::point3;
    auto ground   = std::make_shared<rt::lambertian>(color(0.8, 0.8, 0.0));
    auto center   = std::make_shared<rt::lambertian>(color(0.1, 0.2, 0.5));
    auto polished = std::make_shared<rt::metal>(color(0.8, 0.8, 0.8), 0.3);
    auto brushed  = std::make_shared<rt::metal>(color(0.8, 0.6, 0.2), 1.0);

    auto world = std::make_shared<rt::hittable_list>();
    world->add(std::make_shared<rt::sphere>(point3(0, -100.5, -1), 100, ground));
    world->add(std::make_shared<rt::sphere>(point3(0, 0, -1), 0.5, center));
    world->add(std::make_shared<rt::sphere>(point3(-1, 0, -1), 0.5, polished));
    world->add(std::make_shared<rt::sphere>(point3(1, 0, -1), 0.5, brushed));

    rt::scene scene;
    scene.world = world;
    // The default sky and camera: at the origin looking down -z, vfov 90, 16:9.
    scene.settings = {.width = 400, .samples_per_pixel = 100, .max_depth = 50};
    return scene;
}
