// Chapter 05: dielectrics. Glass bends a ray by Snell's law, n1 sin(theta1) = n2 sin(theta2),
// and reflects part of the light, more at grazing angles (Schlick's approximation of Fresnel).
// One ray continues per hit: reflection with probability R, refraction otherwise; past the
// critical angle there is only reflection (total internal reflection).
#include "common/command_line.h"
#include "common/path_tracer.h"
#include "glass_scene.h"

// The glass sphere with its air bubble, seen from the origin down -z.
rt::scene glass_scene_from_origin() {
    rt::scene scene;
    scene.world = glass_with_bubble();
    // The default sky and camera: at the origin looking down -z, vfov 90, 16:9.
    scene.settings = {.width = 400, .samples_per_pixel = 100, .max_depth = 50};
    return scene;
}

int main(int argc, char** argv) {
    return rt::command_line("ch05_dielectric").run(argc, argv, [] {
        return rt::path_trace(glass_scene_from_origin());
    });
}
