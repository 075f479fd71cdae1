// Chapter 10's report scene: book 2's simple light, marble spheres lit only by two emitters in
// the dark. Later chapters' programs render it as --scene ch10.
#pragma once

#include <memory>

#include "rt/camera/thin_lens_camera.h"
#include "rt/geometry/quad.h"
#include "rt/geometry/sphere.h"
#include "rt/materials/diffuse_light.h"
#include "rt/materials/textured_lambertian.h"
#include "rt/scene/background.h"
#include "rt/scene/hittable_list.h"
#include "rt/scene/scene.h"
#include "rt/textures/noise_texture.h"

// Book 2's simple light: two marble spheres lit by a spherical and a rectangular light.
inline rt::scene simple_light() {
    using rt::point3, rt::vec3;
    auto marble = std::make_shared<rt::textured_lambertian>(std::make_shared<rt::noise_texture>(4));
    auto light  = std::make_shared<rt::diffuse_light>(rt::color(4, 4, 4));

    auto world = std::make_shared<rt::hittable_list>();
    world->add(std::make_shared<rt::sphere>(point3(0, -1000, 0), 1000, marble));
    world->add(std::make_shared<rt::sphere>(point3(0, 2, 0), 2, marble));
    world->add(std::make_shared<rt::sphere>(point3(0, 7, 0), 2, light));
    world->add(std::make_shared<rt::quad>(point3(3, 1, -2), vec3(2, 0, 0), vec3(0, 2, 0), light));

    auto cam      = std::make_shared<rt::thin_lens_camera>();
    cam->vfov     = 20;
    cam->lookfrom = point3(26, 3, 6);
    cam->lookat   = point3(0, 2, 0);

    rt::scene scene;
    scene.world    = world;
    scene.sky      = rt::background::uniform(rt::color(0, 0, 0));
    scene.cam      = cam;
    scene.settings = {.width = 400, .samples_per_pixel = 100, .max_depth = 50};
    return scene;
}
