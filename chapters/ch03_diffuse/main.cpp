// Chapter 03: diffuse materials. A Lambertian surface scatters a ray into a direction drawn
// with density cos(theta) / pi about the normal and attenuates it by its albedo, so after many
// bounces each pixel estimates L = Le + albedo * L(scattered). Scattered rays start just off the
// surface they leave (spawn_reflected_ray), so there is no shadow acne; the PNG is sRGB-encoded.
#include <string>

#include "matte_scene.h"
#include "rt/integrators/path_tracer.h"
#include "rt/program/command_line.h"

int main(int argc, char** argv) {
    rt::command_line cli("ch03_diffuse");
    std::string which = "floor";
    cli.add_choice("--scene", which, {"floor", "book"},
                   "floor (spheres on a rectangle), or book (book 1's image 12)", false);
    return cli.run(argc, argv, [&] {
        return rt::path_trace(which == "floor" ? matte_spheres_on_floor() : book_diffuse_spheres());
    });
}
