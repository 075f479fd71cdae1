// Chapter 12: volumes. In a medium of density rho a ray scatters in a step dL with probability
// rho dL, so the distance to the next scattering is exponential, d = -ln(xi) / rho. If d falls
// inside the medium's boundary the ray scatters there in a uniformly random direction (an
// isotropic phase function, weight = the medium's albedo); otherwise it passes through.
#include "ch05_dielectric/fresnel_option.h"
#include "ch06_defocus/layout_seed_option.h"
#include "ch08_textures/texture_decoding_option.h"
#include "cornell_smoke.h"
#include "rt/integrators/path_tracer.h"
#include "rt/program/command_line.h"

int main(int argc, char** argv) {
    rt::command_line cli("ch12_volumes");
    add_fresnel_option(cli);
    add_layout_seed_option(cli);
    add_texture_decoding_option(cli);
    return cli.run(argc, argv, [] { return rt::path_trace(cornell_smoke()); });
}
