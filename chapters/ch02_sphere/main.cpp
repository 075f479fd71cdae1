// Chapter 02: a sphere. A ray A + t b hits the sphere |P - C| = r where the quadratic
//   (b.b) t^2 + 2 b.(A - C) t + (A - C).(A - C) - r^2 = 0
// has a root; the nearest positive root is the hit. Each hit shows its unit outward normal n
// as the color 0.5 (n + 1). Several samples per pixel smooth the sphere's edge (anti-aliasing).
#include <memory>

#include "common/normal_shading.h"
#include "common/options.h"
#include "common/sphere.h"

// A small sphere resting on a huge one that serves as the ground, both in one hittable_list.
rt::scene sphere_on_ground() {
    auto normals = std::make_shared<rt::normal_shading>();

    rt::scene scene;
    scene.world.add(std::make_shared<rt::sphere>(rt::point3(0, 0, -1), 0.5, normals));
    scene.world.add(std::make_shared<rt::sphere>(rt::point3(0, -100.5, -1), 100, normals));
    // The default sky and camera: at the origin looking down -z, vfov 90, 16:9.
    return scene;
}

int main(int argc, char** argv) {
    // The normal shading absorbs every ray it colors, so one segment per path is enough.
    rt::command_line cli("ch02_sphere",
                         {.width = 400, .render = {.samples_per_pixel = 100, .max_depth = 1}});
    return cli.run(argc, argv, sphere_on_ground);
}
