// Chapter 08's report scene: book 2's earth, an image-textured sphere under a light blue sky.
// Later chapters' programs render it as --scene ch08 (with their own --texture file).
#pragma once

#include <memory>
#include <string>

#include "rt/camera/thin_lens_camera.h"
#include "rt/geometry/sphere.h"
#include "rt/materials/textured_lambertian.h"
#include "rt/scene/background.h"
#include "rt/scene/scene.h"
#include "rt/textures/image_texture.h"

// Book 2's earth scene: a globe of radius 2 at the origin, seen from (0, 0, 12).
inline rt::scene globe(const std::string& texture_file) {
    auto surface = std::make_shared<rt::textured_lambertian>(
        std::make_shared<rt::image_texture>(texture_file));
    auto cam      = std::make_shared<rt::thin_lens_camera>();
    cam->vfov     = 20;
    cam->lookfrom = rt::point3(0, 0, 12);
    cam->lookat   = rt::point3(0, 0, 0);

    rt::scene scene;
    scene.world    = std::make_shared<rt::sphere>(rt::point3(0, 0, 0), 2, surface);
    scene.sky      = rt::background::uniform(rt::color(0.70, 0.80, 1.00));
    scene.cam      = cam;
    scene.settings = {.width = 400, .samples_per_pixel = 100, .max_depth = 50};
    return scene;
}
