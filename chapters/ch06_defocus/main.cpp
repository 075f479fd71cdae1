// Chapter 06: a positionable camera with a thin lens. The camera stands at lookfrom, looks at
// lookat, and vup says which way is up: w = unit(lookfrom - lookat), u = unit(vup x w),
// v = w x u. Rays start at a random point of a lens disk of diameter --aperture and pass
// through the point of the focus plane (at --focus-dist) that the pinhole ray would hit, so only
// that plane is sharp: the circle of confusion grows with the aperture and the distance from it.
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "ch05_dielectric/glass_scene.h"
#include "common/command_line.h"
#include "common/path_tracer.h"
#include "common/thin_lens_camera.h"
#include "random_spheres.h"

// The glass scene from above and to the side: from (3, 3, 2), looking at the middle sphere.
rt::scene glass_scene_through_lens(std::optional<rt::real> aperture,
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

// Book 1's final scene; the book's defocus angle 0.6 degrees at focus distance 10 is a lens of
// diameter 2 * 10 * tan(0.3 degrees).
rt::scene final_scene(std::optional<rt::real> aperture, std::optional<rt::real> focus) {
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

int main(int argc, char** argv) {
    rt::command_line cli("ch06_defocus");
    std::optional<rt::real> aperture, focus;
    std::string which = "glass";
    cli.app()
        .add_option("--aperture", aperture, "Lens diameter (default 2.0; final: 0.105)")
        ->check(CLI::NonNegativeNumber);
    cli.app()
        .add_option("--focus-dist", focus, "Distance to the sharp plane (default: lookat)")
        ->check(CLI::PositiveNumber);
    cli.app()
        .add_option("--scene", which, "glass, or final (book 1's random spheres)")
        ->check(CLI::IsMember({"glass", "final"}));
    return cli.run(argc, argv, [&] {
        return rt::path_trace(which == "glass" ? glass_scene_through_lens(aperture, focus)
                                               : final_scene(aperture, focus));
    });
}
