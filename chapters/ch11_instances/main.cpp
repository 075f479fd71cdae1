// Chapter 11: instances. A box is six quads; to turn and place it we do not move its quads but
// move each ray the opposite way into the box's own space, hit the box there, and carry the hit
// point and normal back out. About the y axis by theta:
//   x' = cos(theta) x + sin(theta) z,   z' = -sin(theta) x + cos(theta) z.
// --scene rotations turns three boxes in the same room, about x, y and z.
#include <string>

#include "ch05_dielectric/fresnel_option.h"
#include "ch06_defocus/layout_seed_option.h"
#include "ch08_textures/texture_decoding_option.h"
#include "cornell_box.h"
#include "rotations_scene.h"
#include "rt/integrators/path_tracer.h"
#include "rt/program/command_line.h"

int main(int argc, char** argv) {
    rt::command_line cli("ch11_instances");
    add_fresnel_option(cli);
    add_layout_seed_option(cli);
    add_texture_decoding_option(cli);
    std::string which = "cornell";
    cli.add_choice("--scene", which, {"cornell", "rotations"},
                   "cornell (book 2's box), or rotations (about x, y and z)");
    return cli.run(argc, argv, [&] {
        return rt::path_trace(which == "cornell" ? cornell_box() : turned_boxes());
    });
}
