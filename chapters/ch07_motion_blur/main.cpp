// Chapter 07: motion blur, and a bounding volume hierarchy to make big scenes fast.
// The shutter is open for t in [0, 1); each camera ray gets a random time, and a moving sphere
// is hit where its center is at that time, C(t) = C0 + t (C1 - C0): averaging over times blurs
// it along its path. The BVH puts the ~480 spheres in a tree of boxes, so a ray tests only the
// few spheres in the boxes it crosses (about log n boxes instead of n spheres).
#include <cmath>
#include <string>

#include "ch06_defocus/random_spheres.h"
#include "common/bvh.h"
#include "common/options.h"

// Book 2's bouncing spheres: book 1's final scene with the diffuse spheres moving up during the
// shutter, on a checkered ground, under a light blue sky of constant color.
rt::scene bouncing_spheres(bool use_bvh) {
    rt::hittable_list spheres = random_spheres(/*bouncing=*/true);
    rt::scene scene;
    if (use_bvh)
        scene.world.add(std::make_shared<rt::bvh>(spheres.objects));
    else
        scene.world = spheres;
    scene.sky            = rt::background::uniform(rt::color(0.70, 0.80, 1.00));
    scene.cam.vfov       = 20;
    scene.cam.lookfrom   = rt::point3(13, 2, 3);
    scene.cam.lookat     = rt::point3(0, 0, 0);
    scene.cam.focus_dist = 10;
    // Book 2's defocus angle of 0.02 degrees at the focus distance, as a lens diameter.
    scene.cam.aperture = 2 * scene.cam.focus_dist * std::tan(rt::degrees_to_radians(0.01));
    return scene;
}

int main(int argc, char** argv) {
    rt::command_line cli("ch07_motion_blur",
                         {.width = 400, .render = {.samples_per_pixel = 100, .max_depth = 50}});
    std::string accel = "bvh";
    cli.app()
        .add_option("--accel", accel, "bvh, or list to test every sphere (for comparison)")
        ->check(CLI::IsMember({"bvh", "list"}))
        ->capture_default_str();
    return cli.run(argc, argv, [&] { return bouncing_spheres(accel == "bvh"); });
}
