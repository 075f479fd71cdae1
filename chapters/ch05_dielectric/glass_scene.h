// Book 1's glass scene, shared by chapter 05 (seen from the origin) and chapter 06 (seen through
// a positionable thin-lens camera): a hollow glass sphere (an air bubble of index ratio 1/1.5
// inside glass of index 1.5), a matte sphere and a mirror-polished metal sphere on the ground.
// Chapter 05's report scene, glass_scene_from_origin(), is here too: --scene ch05 of later
// chapters' programs.
#pragma once

#include <memory>

#include "rt/geometry/sphere.h"
#include "rt/materials/dielectric.h"
#include "rt/materials/lambertian.h"
#include "rt/materials/metal.h"
#include "rt/scene/hittable_list.h"
#include "rt/scene/scene.h"

inline std::shared_ptr<rt::hittable_list> glass_with_bubble() {
    using rt::color, rt::point3;
    auto ground = std::make_shared<rt::lambertian>(color(0.8, 0.8, 0.0));
    auto center = std::make_shared<rt::lambertian>(color(0.1, 0.2, 0.5));
    auto glass  = std::make_shared<rt::dielectric>(1.5);
    auto bubble = std::make_shared<rt::dielectric>(1.0 / 1.5);
    auto mirror = std::make_shared<rt::metal>(color(0.8, 0.6, 0.2), 0.0);

    auto world = std::make_shared<rt::hittable_list>();
    world->add(std::make_shared<rt::sphere>(point3(0, -100.5, -1), 100, ground));
    world->add(std::make_shared<rt::sphere>(point3(0, 0, -1), 0.5, center));
    world->add(std::make_shared<rt::sphere>(point3(-1, 0, -1), 0.5, glass));
    world->add(std::make_shared<rt::sphere>(point3(-1, 0, -1), 0.4, bubble));
    world->add(std::make_shared<rt::sphere>(point3(1, 0, -1), 0.5, mirror));
    return world;
}

// The glass sphere with its air bubble, seen from the origin down -z.
inline rt::scene glass_scene_from_origin() {
    rt::scene scene;
    scene.world = glass_with_bubble();
    // The default sky and camera: at the origin looking down -z, vfov 90, 16:9.
    scene.settings = {.width = 400, .samples_per_pixel = 100, .max_depth = 50};
    return scene;
}
