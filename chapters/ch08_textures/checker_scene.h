// Chapter 08's second scene (--scene checker): a solid-colored sphere and two checkered ones on
// a floor at y = 0, to compare the two checker rules of rt/textures/texture.h. The middle sphere
// and the left part of the floor use the floor rule (checker_texture); the right sphere and the
// right part of the floor use the sign of a product of sines (sine_checker_texture), with the same
// cells of side pi / 10 (the sines are then sin(10 x) sin(10 y) sin(10 z)).
#pragma once

#include <memory>

#include "rt/camera/thin_lens_camera.h"
#include "rt/geometry/quad.h"
#include "rt/geometry/sphere.h"
#include "rt/materials/textured_lambertian.h"
#include "rt/scene/hittable_list.h"
#include "rt/scene/scene.h"
#include "rt/textures/texture.h"

inline rt::scene checkered_spheres() {
    using rt::color, rt::point3, rt::vec3;
    auto textured = [](std::shared_ptr<rt::texture> t) {
        return std::make_shared<rt::textured_lambertian>(std::move(t));
    };
    const double cell = rt::pi / 10;
    const color even(0.2, 0.3, 0.1), odd(0.9, 0.9, 0.9);  // book 2's checker colors
    auto solid  = textured(std::make_shared<rt::solid_color>(color(0.7, 0.25, 0.1)));
    auto floors = textured(std::make_shared<rt::checker_texture>(cell, even, odd));
    auto sines  = textured(std::make_shared<rt::sine_checker_texture>(cell, even, odd));

    auto world = std::make_shared<rt::hittable_list>();
    world->add(std::make_shared<rt::sphere>(point3(-2.4, 1, 0), 1, solid));
    world->add(std::make_shared<rt::sphere>(point3(0, 1, 0), 1, floors));
    world->add(std::make_shared<rt::sphere>(point3(2.4, 1, 0), 1, sines));
    // The floor lies in y = 0, a cell face of both rules; it is split at x = 1.2, between the
    // middle and the right sphere.
    world->add(
        std::make_shared<rt::quad>(point3(-20, 0, 6), vec3(21.2, 0, 0), vec3(0, 0, -26), floors));
    world->add(
        std::make_shared<rt::quad>(point3(1.2, 0, 6), vec3(18.8, 0, 0), vec3(0, 0, -26), sines));

    auto cam      = std::make_shared<rt::thin_lens_camera>();
    cam->vfov     = 30;
    cam->lookfrom = point3(0, 3, 9);
    cam->lookat   = point3(0, 0.8, 0);

    rt::scene scene;
    scene.world    = world;
    scene.sky      = rt::background::uniform(color(0.70, 0.80, 1.00));
    scene.cam      = cam;
    scene.settings = {.width = 400, .samples_per_pixel = 100, .max_depth = 50};
    return scene;
}
