// Chapter 02's scene: a sphere on a huge sphere, the ground.
#pragma once

#include <memory>

#include "rt/geometry/sphere.h"
#include "rt/scene/hittable_list.h"
#include "rt/scene/scene.h"

// A small sphere resting on a huge one that serves as the ground, both in one hittable_list.
inline rt::scene sphere_on_ground() {
    auto world = std::make_shared<rt::hittable_list>();
    world->add(std::make_shared<rt::sphere>(rt::point3(0, 0, -1), 0.5));
    world->add(std::make_shared<rt::sphere>(rt::point3(0, -100.5, -1), 100));

    rt::scene scene;
    scene.world = world;
    // The default sky and camera: at the origin looking down -z, vfov 90, 16:9.
    // One segment per path: the normal is all a pixel shows.
    scene.settings = {.width = 400, .samples_per_pixel = 100, .max_depth = 1};
    return scene;
}
