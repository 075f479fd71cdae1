// Chapter 13: the finale. Book 2's final scene uses every feature: boxes, an area light, motion
// blur, glass, brushed metal, a glass ball filled with a scattering medium, a global mist, an
// image texture, Perlin marble, and a cluster of 1000 spheres in a BVH turned as one instance.
// Everything sits in one BVH. The default settings are the book's default run
// (final_scene(400, 250, 4)); its "real" run is --width 800 --spp 10000 --max-depth 40.
#include <string>

#include "ch05_dielectric/fresnel_option.h"
#include "ch06_defocus/layout_seed_option.h"
#include "ch08_textures/texture_decoding_option.h"
#include "final_scene.h"
#include "rt/integrators/path_tracer.h"
#include "rt/program/asset_path.h"
#include "rt/program/command_line.h"

int main(int argc, char** argv) {
    rt::command_line cli("ch13_final");
    add_fresnel_option(cli);
    add_layout_seed_option(cli);
    add_texture_decoding_option(cli);
    std::string texture_file = rt::asset_path("globe.png");
    cli.add_text("--texture", texture_file, "Image for the globe");
    return cli.run(argc, argv, [&] { return rt::path_trace(book2_final_scene(texture_file)); });
}
