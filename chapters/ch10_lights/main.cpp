// Chapter 10: lights. A diffuse_light emits its color (on both faces, as in book 2) and reflects
// nothing; the path tracer adds emission at every hit, L = Le + attenuation * L(scattered). With
// a black background all light comes from the emitters. Quads Q + a u + b v make rectangles in
// any orientation (the seed report's xy, yz and xz rectangles are special cases).
#include <memory>

#include "common/diffuse_light.h"
#include "common/lambertian.h"
#include "common/noise_texture.h"
#include "common/options.h"
#include "common/quad.h"
#include "common/sphere.h"

// Book 2's simple light: two marble spheres lit by a spherical and a rectangular light.
rt::scene simple_light() {
    using rt::point3, rt::vec3;
    auto marble = std::make_shared<rt::lambertian>(std::make_shared<rt::noise_texture>(4));
    auto light  = std::make_shared<rt::diffuse_light>(rt::color(4, 4, 4));

    rt::scene scene;
    scene.world.add(std::make_shared<rt::sphere>(point3(0, -1000, 0), 1000, marble));
    scene.world.add(std::make_shared<rt::sphere>(point3(0, 2, 0), 2, marble));
    scene.world.add(std::make_shared<rt::sphere>(point3(0, 7, 0), 2, light));
    scene.world.add(
        std::make_shared<rt::quad>(point3(3, 1, -2), vec3(2, 0, 0), vec3(0, 2, 0), light));
    scene.sky          = rt::background::uniform(rt::color(0, 0, 0));
    scene.cam.vfov     = 20;
    scene.cam.lookfrom = point3(26, 3, 6);
    scene.cam.lookat   = point3(0, 2, 0);
    return scene;
}

int main(int argc, char** argv) {
    rt::command_line cli("ch10_lights",
                         {.width = 400, .render = {.samples_per_pixel = 100, .max_depth = 50}});
    return cli.run(argc, argv, simple_light);
}
