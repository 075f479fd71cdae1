// Chapter 07: motion blur, and a bounding volume hierarchy to make big scenes fast.
// The shutter is open for t in [0, 1); each camera ray gets a random time, and a moving sphere
// is hit where its center is at that time, C(t) = C0 + t (C1 - C0): averaging over times blurs
// it along its path. The BVH puts the ~480 spheres in a tree of boxes, so a ray tests only the
// few spheres in the boxes it crosses (about log n boxes instead of n spheres).
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "ch06_defocus/random_spheres.h"
#include "common/bvh.h"
#include "common/command_line.h"
#include "common/hittable_list.h"
#include "common/moving_sphere.h"
#include "common/path_tracer.h"
#include "common/thin_lens_camera.h"

// Book 2's bouncing spheres: book 1's final scene in which every small matte sphere moves up
// by a random height while the shutter is open, under a light blue sky of constant color.
rt::scene bouncing_spheres(bool use_bvh) {
    rt::pcg32 bounce(/*sequence=*/7, /*seed=*/2024);
    std::vector<rt::bounded_object> spheres;
    for (auto& s : random_spheres()) {
        bool small_and_matte =
            s->radius() < 1 && std::dynamic_pointer_cast<rt::lambertian>(s->surface());
        if (!small_and_matte) {
            spheres.emplace_back(s);
            continue;
        }
        rt::point3 top = s->center() + rt::vec3(0, 0.5 * bounce.uniform(), 0);
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

int main(int argc, char** argv) {
    rt::command_line cli("ch07_motion_blur");
    std::string accel = "bvh";
    cli.app()
        .add_option("--accel", accel, "bvh, or list to test every sphere (for comparison)")
        ->check(CLI::IsMember({"bvh", "list"}))
        ->capture_default_str();
    return cli.run(argc, argv, [&] { return rt::path_trace(bouncing_spheres(accel == "bvh")); });
}
