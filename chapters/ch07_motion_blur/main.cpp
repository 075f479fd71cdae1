// Chapter 07: motion blur, and a bounding volume hierarchy to make big scenes fast.
// The shutter is open for t in [0, 1); each camera ray gets a random time, and a moving sphere
// is hit where its center is at that time, C(t) = C0 + t (C1 - C0): averaging over times blurs
// it along its path. The BVH puts the ~480 spheres in a tree of boxes, so a ray tests only the
// few spheres in the boxes it crosses (about log n boxes instead of n spheres).
// --scene ch06-final renders book 1's final scene (chapter 06) through the same BVH.
#include <string>

#include "book1_in_bvh.h"
#include "bouncing_spheres.h"
#include "ch05_dielectric/fresnel_option.h"
#include "ch06_defocus/layout_seed_option.h"
#include "rt/integrators/path_tracer.h"
#include "rt/program/command_line.h"

int main(int argc, char** argv) {
    rt::command_line cli("ch07_motion_blur");
    add_fresnel_option(cli);
    add_layout_seed_option(cli);
    std::string accel = "bvh";
    std::string which = "bouncing";
    cli.add_choice("--accel", accel, {"bvh", "list"},
                   "bvh, or list to test every sphere (for comparison)");
    cli.add_choice("--scene", which, {"bouncing", "ch06-final"},
                   "bouncing (book 2's bouncing spheres), or ch06-final (book 1's final scene)");
    return cli.run(argc, argv, [&] {
        const bool use_bvh = accel == "bvh";
        return rt::path_trace(which == "bouncing" ? bouncing_spheres(use_bvh)
                                                  : book1_final_scene_in_bvh(use_bvh));
    });
}
