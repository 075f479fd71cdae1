// Chapter 07's scene: book 2's bouncing spheres, in a BVH (the report scene; later chapters'
// --scene ch07) or in a flat list that tests every sphere (--accel list; --scene ch07-list).
// Both give the same image: the BVH only finds the closest hit faster.
#pragma once

#include <cmath>
#include <memory>
#include <vector>

#include "ch06_defocus/random_spheres.h"
#include "rt/accel/bounded.h"
#include "rt/accel/bvh.h"
#include "rt/camera/thin_lens_camera.h"
#include "rt/geometry/moving_sphere.h"
#include "rt/scene/background.h"
#include "rt/scene/hittable_list.h"
#include "rt/scene/scene.h"

// Book 2's bouncing spheres: book 1's grid of spheres, laid out by book 2's draws, in which
// every small matte sphere moves up by its rise while the shutter is open, under a light blue
// sky of constant color. `ground`, when given, replaces the ground sphere's gray (chapter 08's
// checkered ground, as the book's texture section has it).
inline rt::scene bouncing_spheres(bool use_bvh, std::shared_ptr<rt::material> ground = nullptr) {
    std::vector<rt::bounded_object> spheres;
    for (auto& [s, rise] : random_sphere_layout(/*bouncing=*/true)) {
        if (ground && s->radius() == 1000) {
            spheres.emplace_back(std::make_shared<rt::sphere>(s->center(), s->radius(), ground));
            continue;
        }
        if (rise == 0) {
            spheres.emplace_back(s);
            continue;
        }
        rt::point3 top = s->center() + rt::vec3(0, rise, 0);
        spheres.emplace_back(
            std::make_shared<rt::moving_sphere>(s->center(), top, s->radius(), s->surface()));
    }

    auto cam           = std::make_shared<rt::thin_lens_camera>();
    cam->vfov          = 20;
    cam->lookfrom      = rt::point3(13, 2, 3);
    cam->lookat        = rt::point3(0, 0, 0);
    cam->focus_dist    = 10;
    cam->shutter_close = 1;  // open for the whole motion, t in [0, 1)
    // Book 2's defocus angle of 0.02 degrees at the focus distance, as a lens diameter.
    cam->aperture = 2 * cam->focus_dist * std::tan(rt::degrees_to_radians(0.01));

    rt::scene scene;
    if (use_bvh) {
        scene.world = std::make_shared<rt::bvh>(spheres);
    } else {
        auto list = std::make_shared<rt::hittable_list>();
        for (auto& s : spheres) list->add(s.object);
        scene.world = list;
    }
    scene.sky      = rt::background::uniform(rt::color(0.70, 0.80, 1.00));
    scene.cam      = cam;
    scene.settings = {.width = 400, .samples_per_pixel = 100, .max_depth = 50};
    return scene;
}
