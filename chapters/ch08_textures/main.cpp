// Chapter 08: image textures. A sphere point with unit outward normal n gets surface coordinates
//   u = phi / (2 pi),  phi = atan2(-n.z, n.x) + pi;    v = theta / pi,  theta = acos(-n.y),
// and an equirectangular image (longitude across, latitude down) is looked up at (u, v): the
// texel in column u W and row (1 - v) H. The Lambertian albedo is that texel, decoded to linear.
// --scene checker shows solid textures instead: a solid color and two 3D checkerboards.
#include <string>

#include "book_checker_scenes.h"
#include "ch05_dielectric/fresnel_option.h"
#include "ch06_defocus/layout_seed_option.h"
#include "ch08_textures/texture_decoding_option.h"
#include "checker_scene.h"
#include "globe_scene.h"
#include "rt/integrators/path_tracer.h"
#include "rt/program/asset_path.h"
#include "rt/program/command_line.h"

int main(int argc, char** argv) {
    rt::command_line cli("ch08_textures");
    add_fresnel_option(cli);
    add_layout_seed_option(cli);
    add_texture_decoding_option(cli);
    // The project's own equirectangular map, made by tools/make-globe-texture.
    std::string texture_file = rt::asset_path("globe.png");
    std::string which        = "globe";
    cli.add_text("--texture", texture_file, "Equirectangular image for the globe");
    cli.add_choice("--scene", which, {"globe", "checker", "bouncing", "two-spheres"},
                   "globe (book 2's earth), checker (solid and checkered), bouncing (book 2's "
                   "bouncing spheres on a checker), or two-spheres (book 2's checkered spheres)");
    return cli.run(argc, argv, [&] {
        if (which == "bouncing") return rt::path_trace(bouncing_spheres_on_checker());
        if (which == "two-spheres") return rt::path_trace(two_checkered_spheres());
        return rt::path_trace(which == "globe" ? globe(texture_file) : checkered_spheres());
    });
}
