// Chapter 08: image textures. A sphere point with unit outward normal n gets surface coordinates
//   u = phi / (2 pi),  phi = atan2(-n.z, n.x) + pi;    v = theta / pi,  theta = acos(-n.y),
// and an equirectangular image (longitude across, latitude down) is looked up at (u, v): the
// texel in column u W and row (1 - v) H. The Lambertian albedo is that texel, decoded to linear.
// --scene checker shows solid textures instead: a solid color and two 3D checkerboards.
#include <memory>
#include <string>

#include "checker_scene.h"
#include "common/command_line.h"
#include "common/image_texture.h"
#include "common/path_tracer.h"
#include "common/sphere.h"
#include "common/textured_lambertian.h"
#include "common/thin_lens_camera.h"

// Book 2's earth scene: a globe of radius 2 at the origin, seen from (0, 0, 12).
rt::scene globe(const std::string& texture_file) {
    auto surface = std::make_shared<rt::textured_lambertian>(
        std::make_shared<rt::image_texture>(texture_file));
    auto cam      = std::make_shared<rt::thin_lens_camera>();
    cam->vfov     = 20;
    cam->lookfrom = rt::point3(0, 0, 12);
    cam->lookat   = rt::point3(0, 0, 0);

    rt::scene scene;
    scene.world    = std::make_shared<rt::sphere>(rt::point3(0, 0, 0), 2, surface);
    scene.sky      = rt::background::uniform(rt::color(0.70, 0.80, 1.00));
    scene.cam      = cam;
    scene.settings = {.width = 400, .samples_per_pixel = 100, .max_depth = 50};
    return scene;
}

int main(int argc, char** argv) {
    rt::command_line cli("ch08_textures");
    // The project's own equirectangular map, made by tools/make-globe-texture.
    std::string texture_file = RT_ASSET_DIR "/globe.png";
    std::string which        = "globe";
    cli.app()
        .add_option("--texture", texture_file, "Equirectangular image for the globe")
        ->capture_default_str();
    cli.app()
        .add_option("--scene", which, "globe (book 2's earth), or checker (solid and checkered)")
        ->check(CLI::IsMember({"globe", "checker"}))
        ->capture_default_str();
    return cli.run(argc, argv, [&] {
        return rt::path_trace(which == "globe" ? globe(texture_file) : checkered_spheres());
    });
}
