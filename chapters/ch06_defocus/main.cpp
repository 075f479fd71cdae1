// Chapter 06: a positionable camera with a thin lens. The camera stands at lookfrom, looks at
// lookat, and vup says which way is up: w = unit(lookfrom - lookat), u = unit(vup x w),
// v = w x u. Rays start at a random point of a lens disk of diameter --aperture and pass
// through the point of the focus plane (at --focus-dist) that the pinhole ray would hit, so only
// that plane is sharp: the circle of confusion grows with the aperture and the distance from it.
#include <optional>
#include <string>

#include "ch05_dielectric/fresnel_option.h"
#include "ch06_defocus/layout_seed_option.h"
#include "lens_scenes.h"
#include "rt/integrators/path_tracer.h"
#include "rt/program/command_line.h"

int main(int argc, char** argv) {
    rt::command_line cli("ch06_defocus");
    add_fresnel_option(cli);
    add_layout_seed_option(cli);
    std::optional<rt::real> aperture, focus;
    std::string which = "glass";
    cli.add_number("--aperture", aperture, "Lens diameter (default 2.0; final: 0.105)", 0, true);
    cli.add_number("--focus-dist", focus, "Distance to the sharp plane (default: lookat)", 0,
                   false);
    cli.add_choice("--scene", which, {"glass", "book", "final"},
                   "glass, book (book 1's depth of field, its image 22), or final (book 1's "
                   "random spheres)",
                   false);
    return cli.run(argc, argv, [&] {
        if (which == "book") return rt::path_trace(book_depth_of_field(aperture, focus));
        return rt::path_trace(which == "glass" ? glass_scene_through_lens(aperture, focus)
                                               : book1_final_scene(aperture, focus));
    });
}
