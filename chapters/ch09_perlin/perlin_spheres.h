// Chapter 09's scenes under a light blue sky: book 2's two marble spheres (the report scene,
// --scene marble; later chapters' --scene ch09), or a marble sphere beside an image-textured
// globe on the marble ground (--scene globe; later chapters' --scene ch09-globe).
#pragma once

#include <memory>
#include <string>

#include "rt/camera/thin_lens_camera.h"
#include "rt/geometry/sphere.h"
#include "rt/materials/textured_lambertian.h"
#include "rt/scene/background.h"
#include "rt/scene/hittable_list.h"
#include "rt/scene/scene.h"
#include "rt/textures/image_texture.h"
#include "rt/textures/noise_texture.h"

// Book 2's two Perlin spheres: a marble ground and a marble sphere sharing one texture.
inline rt::scene perlin_spheres(const std::string& texture_file, bool with_globe) {
    using rt::point3;
    auto marble = std::make_shared<rt::textured_lambertian>(std::make_shared<rt::noise_texture>(4));
    auto world  = std::make_shared<rt::hittable_list>();
    world->add(std::make_shared<rt::sphere>(point3(0, -1000, 0), 1000, marble));
    if (!with_globe) {
        world->add(std::make_shared<rt::sphere>(point3(0, 2, 0), 2, marble));
    } else {  // the image texture beside the noise, for comparison
        auto earth = std::make_shared<rt::image_texture>(texture_file);
        world->add(std::make_shared<rt::sphere>(point3(0, 2, 2.2), 2, marble));
        world->add(std::make_shared<rt::sphere>(point3(0, 2, -2.2), 2,
                                                std::make_shared<rt::textured_lambertian>(earth)));
    }
    auto cam      = std::make_shared<rt::thin_lens_camera>();
    cam->vfov     = with_globe ? 30 : 20;
    cam->lookfrom = point3(13, 2, 3);
    cam->lookat   = point3(0, with_globe ? 1.5 : 0, 0);

    rt::scene scene;
    scene.world    = world;
    scene.sky      = rt::background::uniform(rt::color(0.70, 0.80, 1.00));
    scene.cam      = cam;
    scene.settings = {.width = 400, .samples_per_pixel = 100, .max_depth = 50};
    return scene;
}
