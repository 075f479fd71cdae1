// Chapter 03: diffuse materials. A Lambertian surface scatters a ray into a direction drawn
// with density cos(theta) / pi about the normal and attenuates it by its albedo, so after many
// bounces each pixel estimates L = Le + albedo * L(scattered). Scattered rays start just off the
// surface they leave (spawn_reflected_ray), so there is no shadow acne; the PNG is sRGB-encoded.
#include "matte_scene.h"
#include "rt/integrators/path_tracer.h"
#include "rt/program/command_line.h"

int main(int argc, char** argv) {
    return rt::command_line("ch03_diffuse").run(argc, argv, [] {
        return rt::path_trace(matte_spheres_on_floor());
    });
}
