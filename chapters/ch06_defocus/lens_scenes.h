// Chapter 06's scenes, all seen through the thin lens: book 1's glass scene from above and to
// the side (the report scene, --scene glass; later chapters' --scene ch06), the same glass scene
// as the book frames it for its depth of field (--scene book; ch06-book), and book 1's final
// scene (--scene final; ch06-final). An unset aperture or focus distance takes the scene's own
// default.
#pragma once

#include <cmath>
#include <memory>
#include <optional>

#include "ch05_dielectric/glass_scene.h"
#include "random_spheres.h"
#include "rt/camera/thin_lens_camera.h"
#include "rt/scene/hittable_list.h"
#include "rt/scene/scene.h"

// The glass scene from above and to the side: from (3, 3, 2), looking at the middle sphere.
inline rt::scene glass_scene_through_lens(std::optional<rt::real> aperture,
                                          std::optional<rt::real> focus) {
    auto cam        = std::make_shared<rt::thin_lens_camera>();
    cam->vfov       = 20;
    cam->lookfrom   = rt::point3(3, 3, 2);
    cam->lookat     = rt::point3(0, 0, -1);
    cam->aperture   = aperture.value_or(2.0);
    cam->focus_dist = focus.value_or(0);  // 0: focus on lookat

    rt::scene scene;
    scene.world    = glass_with_bubble();
    scene.cam      = cam;
    scene.settings = {.width = 400, .samples_per_pixel = 100, .max_depth = 50};
    return scene;
}

// Book 1's image 22, "spheres with depth-of-field": the glass scene from (-2, 2, 1), vfov 20,
// in focus at 3.4 with the book's defocus angle of 10 degrees, a lens of diameter
// 2 * 3.4 * tan(5 degrees).
inline rt::scene book_depth_of_field(std::optional<rt::real> aperture,
                                     std::optional<rt::real> focus) {
    auto cam        = std::make_shared<rt::thin_lens_camera>();
    cam->vfov       = 20;
    cam->lookfrom   = rt::point3(-2, 2, 1);
    cam->lookat     = rt::point3(0, 0, -1);
    cam->focus_dist = focus.value_or(rt::real(3.4));
    cam->aperture   = aperture.value_or(2 * cam->focus_dist * std::tan(rt::degrees_to_radians(5)));

    rt::scene scene;
    scene.world    = glass_with_bubble();
    scene.cam      = cam;
    scene.settings = {.width = 400, .samples_per_pixel = 100, .max_depth = 50};
    return scene;
}

// Book 1's final scene; the book's defocus angle 0.6 degrees at focus distance 10 is a lens of
// diameter 2 * 10 * tan(0.3 degrees).
inline rt::scene book1_final_scene(std::optional<rt::real> aperture,
                                   std::optional<rt::real> focus) {
    auto cam        = std::make_shared<rt::thin_lens_camera>();
    cam->vfov       = 20;
    cam->lookfrom   = rt::point3(13, 2, 3);
    cam->lookat     = rt::point3(0, 0, 0);
    cam->focus_dist = focus.value_or(10.0);
    cam->aperture = aperture.value_or(2 * cam->focus_dist * std::tan(rt::degrees_to_radians(0.3)));

    auto world = std::make_shared<rt::hittable_list>();
    for (auto& sphere : random_spheres()) world->add(sphere);

    rt::scene scene;
    scene.world = world;
    scene.cam   = cam;
    // The book's own settings for this scene: 1200 wide, 10 samples, depth 20.
    scene.settings = {.width = 1200, .samples_per_pixel = 10, .max_depth = 20};
    return scene;
}
