// Book 2's quads (its image 16; --scene quads, later chapters' --scene ch10-quads): five
// coloured quads, the sides of an open box seen from its front, lit by the sky. It shows the
// quad before any light: each is Q + a u + b v, in a plane of any orientation.
#pragma once

#include <memory>

#include "rt/camera/thin_lens_camera.h"
#include "rt/geometry/quad.h"
#include "rt/materials/lambertian.h"
#include "rt/scene/background.h"
#include "rt/scene/hittable_list.h"
#include "rt/scene/scene.h"

inline rt::scene book_quads() {
    using rt::color, rt::point3, rt::vec3;
    auto matte = [](color albedo) { return std::make_shared<rt::lambertian>(albedo); };
    auto world = std::make_shared<rt::hittable_list>();
    world->add(std::make_shared<rt::quad>(point3(-3, -2, 5), vec3(0, 0, -4), vec3(0, 4, 0),
                                          matte(color(1.0, 0.2, 0.2))));  // left, red
    world->add(std::make_shared<rt::quad>(point3(-2, -2, 0), vec3(4, 0, 0), vec3(0, 4, 0),
                                          matte(color(0.2, 1.0, 0.2))));  // back, green
    world->add(std::make_shared<rt::quad>(point3(3, -2, 1), vec3(0, 0, 4), vec3(0, 4, 0),
                                          matte(color(0.2, 0.2, 1.0))));  // right, blue
    world->add(std::make_shared<rt::quad>(point3(-2, 3, 1), vec3(4, 0, 0), vec3(0, 0, 4),
                                          matte(color(1.0, 0.5, 0.0))));  // upper, orange
    world->add(std::make_shared<rt::quad>(point3(-2, -3, 5), vec3(4, 0, 0), vec3(0, 0, -4),
                                          matte(color(0.2, 0.8, 0.8))));  // lower, teal

    auto cam          = std::make_shared<rt::thin_lens_camera>();
    cam->aspect_ratio = 1;
    cam->vfov         = 80;
    cam->lookfrom     = point3(0, 0, 9);
    cam->lookat       = point3(0, 0, 0);

    rt::scene scene;
    scene.world    = world;
    scene.sky      = rt::background::uniform(color(0.70, 0.80, 1.00));
    scene.cam      = cam;
    scene.settings = {.width = 400, .samples_per_pixel = 100, .max_depth = 50};
    return scene;
}
