// Chapter 01: the background. With nothing in the scene every ray sees the sky, a blend from
// white (looking down) to light blue (looking up) by the y of the ray's unit direction:
//   color = (1 - a) * white + a * blue,   a = (y + 1) / 2.
#include "common/options.h"

// Nothing to hit: the camera at the origin looks down -z with a 90 degree vertical view.
// (These are also the defaults of rt::scene and rt::camera, which later chapters rely on.)
rt::scene empty_sky() {
    rt::scene scene;
    scene.sky              = rt::background::sky();
    scene.cam.aspect_ratio = 16.0 / 9.0;
    scene.cam.vfov         = 90;
    scene.cam.lookfrom     = rt::point3(0, 0, 0);
    scene.cam.lookat       = rt::point3(0, 0, -1);
    return scene;
}

int main(int argc, char** argv) {
    // A gradient needs few samples; one segment per path, since nothing can be hit.
    rt::command_line cli("ch01_background",
                         {.width = 400, .render = {.samples_per_pixel = 4, .max_depth = 1}});
    return cli.run(argc, argv, empty_sky);
}
