// The book's two checker scenes of its texture section: its bouncing spheres on a checkered
// ground (book 2, image 2; --scene bouncing, later chapters' --scene ch08-bouncing) and two
// checkered spheres (image 3; --scene two-spheres, later chapters' --scene ch08-two-spheres),
// with the book's checker_texture (the parity of floor(x / s) + floor(y / s) + floor(z / s)).
#pragma once

#include <memory>

#include "ch07_motion_blur/bouncing_spheres.h"
#include "rt/camera/thin_lens_camera.h"
#include "rt/geometry/sphere.h"
#include "rt/materials/textured_lambertian.h"
#include "rt/scene/background.h"
#include "rt/scene/hittable_list.h"
#include "rt/scene/scene.h"
#include "rt/textures/texture.h"

// A checker of the book's two colors, a green and an off-white, with cells of side `scale`.
inline std::shared_ptr<rt::material> book_checker(double scale) {
    return std::make_shared<rt::textured_lambertian>(std::make_shared<rt::checker_texture>(
        static_cast<rt::real>(scale), rt::color(0.2, 0.3, 0.1), rt::color(0.9, 0.9, 0.9)));
}

inline rt::scene bouncing_spheres_on_checker() {
    return bouncing_spheres(/*use_bvh=*/true, book_checker(0.32));
}

inline rt::scene two_checkered_spheres() {
    using rt::point3;
    auto checker = book_checker(0.8);
    auto world   = std::make_shared<rt::hittable_list>();
    world->add(std::make_shared<rt::sphere>(point3(0, -10, 0), 10, checker));
    world->add(std::make_shared<rt::sphere>(point3(0, 10, 0), 10, checker));

    auto cam      = std::make_shared<rt::thin_lens_camera>();
    cam->vfov     = 20;
    cam->lookfrom = point3(13, 2, 3);
    cam->lookat   = point3(0, 0, 0);

    rt::scene scene;
    scene.world    = world;
    scene.sky      = rt::background::uniform(rt::color(0.70, 0.80, 1.00));
    scene.cam      = cam;
    scene.settings = {.width = 400, .samples_per_pixel = 100, .max_depth = 50};
    return scene;
}
