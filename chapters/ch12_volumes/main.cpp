// Chapter 12: volumes. In a medium of density rho a ray scatters in a step dL with probability
// rho dL, so the distance to the next scattering is exponential, d = -ln(xi) / rho. If d falls
// inside the medium's boundary the ray scatters there in a uniformly random direction (an
// isotropic phase function, weight = the medium's albedo); otherwise it passes through.
#include "cornell_smoke.h"
#include "rt/integrators/path_tracer.h"
#include "rt/program/command_line.h"

int main(int argc, char** argv) {
    return rt::command_line("ch12_volumes").run(argc, argv, [] {
        return rt::path_trace(cornell_smoke());
    });
}
