// Chapter 09: Perlin noise. Random unit gradients on the integer lattice, blended with smooth
// Hermite weights, give noise that is random but continuous; summing octaves of it (turbulence)
// and using it to shift the phase of sine stripes makes marble:
//   gray = 0.5 (1 + sin(scale z + 10 turbulence(p))).
#include <string>

#include "ch05_dielectric/fresnel_option.h"
#include "ch06_defocus/layout_seed_option.h"
#include "ch08_textures/texture_decoding_option.h"
#include "perlin_spheres.h"
#include "rt/integrators/path_tracer.h"
#include "rt/program/asset_path.h"
#include "rt/program/command_line.h"

int main(int argc, char** argv) {
    rt::command_line cli("ch09_perlin");
    add_fresnel_option(cli);
    add_layout_seed_option(cli);
    add_texture_decoding_option(cli);
    std::string which = "marble", texture_file = rt::asset_path("globe.png");
    cli.add_choice("--scene", which, {"marble", "globe"},
                   "marble (book 2), or globe: the image texture beside it");
    cli.add_text("--texture", texture_file, "Image for the globe");
    return cli.run(argc, argv,
                   [&] { return rt::path_trace(perlin_spheres(texture_file, which == "globe")); });
}
