// Chapter 05: dielectrics. Glass bends a ray by Snell's law, n1 sin(theta1) = n2 sin(theta2),
// and reflects part of the light, more at grazing angles (Schlick's approximation of Fresnel).
// One ray continues per hit: reflection with probability R, refraction otherwise; past the
// critical angle there is only reflection (total internal reflection).
#include "ch05_dielectric/fresnel_option.h"
#include "glass_scene.h"
#include "rt/integrators/path_tracer.h"
#include "rt/program/command_line.h"

int main(int argc, char** argv) {
    rt::command_line cli("ch05_dielectric");
    add_fresnel_option(cli);
    return cli.run(argc, argv, [] { return rt::path_trace(glass_scene_from_origin()); });
}
