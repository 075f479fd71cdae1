// Chapter 03's scenes under the default sky, seen by the default camera: the report scene, three
// matte spheres and a small one on a finite floor (later chapters' --scene ch03), and the book's
// own (--scene book; later chapters' --scene ch03-book).
#pragma once

#include <memory>

#include "rt/geometry/quad.h"
#include "rt/geometry/sphere.h"
#include "rt/materials/lambertian.h"
#include "rt/scene/hittable_list.h"
#include "rt/scene/scene.h"

// Three matte spheres and a small one on a finite xz-rectangle floor, under the sky.
inline rt::scene matte_spheres_on_floor() {
    using rt::color, rt::point3, rt::vec3;
    auto floor = std::make_shared<rt::lambertian>(color(0.8, 0.8, 0.0));
    auto blue  = std::make_shared<rt::lambertian>(color(0.1, 0.2, 0.5));
    auto gray  = std::make_shared<rt::lambertian>(color(0.5, 0.5, 0.5));
    auto red   = std::make_shared<rt::lambertian>(color(0.7, 0.2, 0.1));
    auto white = std::make_shared<rt::lambertian>(color(0.9, 0.9, 0.9));

    auto world = std::make_shared<rt::hittable_list>();
    // The floor: y = -0.5, x in [-3, 3], z in [-4, 1]; its far edge shows the sky behind it.
    world->add(
        std::make_shared<rt::quad>(point3(-3, -0.5, -4), vec3(6, 0, 0), vec3(0, 0, 5), floor));
    world->add(std::make_shared<rt::sphere>(point3(0, 0, -1.2), 0.5, blue));
    world->add(std::make_shared<rt::sphere>(point3(-1.1, 0, -1.5), 0.5, gray));
    world->add(std::make_shared<rt::sphere>(point3(1.1, 0, -1.5), 0.5, red));
    world->add(std::make_shared<rt::sphere>(point3(0.45, -0.35, -0.55), 0.15, white));

    rt::scene scene;
    scene.world = world;
    // The default sky and camera: at the origin looking down -z, vfov 90, 16:9.
    scene.settings = {.width = 400, .samples_per_pixel = 100, .max_depth = 50};
    return scene;
}

// Book 1's diffuse chapter, its last image (image 12, "the gamma-corrected render of two diffuse
// spheres"): chapter 02's sphere and ground sphere, both reflecting half the light, at the book's
// 400 pixels, 100 samples and 50 bounces.
inline rt::scene book_diffuse_spheres() {
    using rt::color, rt::point3;
    auto half  = std::make_shared<rt::lambertian>(color(0.5, 0.5, 0.5));
    auto world = std::make_shared<rt::hittable_list>();
    world->add(std::make_shared<rt::sphere>(point3(0, 0, -1), 0.5, half));
    world->add(std::make_shared<rt::sphere>(point3(0, -100.5, -1), 100, half));

    rt::scene scene;
    scene.world    = world;
    scene.settings = {.width = 400, .samples_per_pixel = 100, .max_depth = 50};
    return scene;
}
