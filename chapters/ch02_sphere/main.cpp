// Chapter 02: a sphere. A ray A + t b hits the sphere |P - C| = r where the quadratic
//   (b.b) t^2 + 2 b.(A - C) t + (A - C).(A - C) - r^2 = 0
// has a root; the nearest positive root is the hit. Each hit shows its unit outward normal n
// as the color 0.5 (n + 1). Several samples per pixel smooth the sphere's edge (anti-aliasing).
#include <memory>

#include "rt/geometry/sphere.h"
#include "rt/integrators/show_normals.h"
#include "rt/program/command_line.h"
#include "rt/scene/hittable_list.h"

// A small sphere resting on a huge one that serves as the ground, both in one hittable_list.
rt::scene sphere_on_ground() {
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

int main(int argc, char** argv) {
    return rt::command_line("ch02_sphere").run(argc, argv, [] {
        return rt::show_normals(sphere_on_ground());
    });
}
