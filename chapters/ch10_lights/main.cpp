// Chapter 10: lights. A diffuse_light emits its color (on both faces, as in book 2) and reflects
// nothing; the path tracer adds emission at every hit, L = Le + weight * L(scattered). With
// a black background all light comes from the emitters. Quads Q + a u + b v make rectangles in
// any orientation (book 2's first xy, yz and xz rectangles are special cases).
#include <string>

#include "book_quads.h"
#include "ch05_dielectric/fresnel_option.h"
#include "ch06_defocus/layout_seed_option.h"
#include "ch08_textures/texture_decoding_option.h"
#include "rt/integrators/path_tracer.h"
#include "rt/program/command_line.h"
#include "simple_light.h"

int main(int argc, char** argv) {
    rt::command_line cli("ch10_lights");
    add_fresnel_option(cli);
    add_layout_seed_option(cli);
    add_texture_decoding_option(cli);
    std::string which = "simple-light";
    cli.add_choice("--scene", which, {"simple-light", "quads"},
                   "simple-light (book 2's two lights; default), or quads (its five quads)", false);
    return cli.run(argc, argv, [&] {
        return rt::path_trace(which == "quads" ? book_quads() : simple_light());
    });
}
