// Chapter 15: next-event estimation and multiple importance sampling. At every surface the path
// can evaluate, it does two things: it aims a shadow ray at a point of a light (next-event
// estimation: the light arrives unless something blocks it, or a medium dims it by
// exp(-density * distance)), and it scatters as its material chooses. A light reached either
// way counts with Veach's power heuristic weight,
//   w_light(wi) = p_light(wi)^2 / (p_light(wi)^2 + p_material(wi)^2),
// and w_material = 1 - w_light for the same path, so the two estimates add up to one unbiased
// answer that is good wherever either strategy is. Russian roulette ends paths that carry
// little light, and divides the survivors by their chance to survive.
// --integrator light (chapter 14) or path (chapter 03) for comparison; --scene as in chapter 14.
#include <string>
#include <vector>

#include "ch05_dielectric/fresnel_option.h"
#include "ch06_defocus/layout_seed_option.h"
#include "ch08_textures/texture_decoding_option.h"
#include "ch14_importance_sampling/book3_cornell_box.h"
#include "ch14_importance_sampling/scene_catalog.h"
#include "rt/integrators/mis_tracer.h"
#include "rt/integrators/mixture_tracer.h"
#include "rt/integrators/path_tracer.h"
#include "rt/program/asset_path.h"
#include "rt/program/command_line.h"

int main(int argc, char** argv) {
    rt::command_line cli("ch15_mis");
    add_fresnel_option(cli);
    add_layout_seed_option(cli);
    add_texture_decoding_option(cli);
    std::string which = "ch14", integrator = "mis", texture_file = rt::asset_path("globe.png");
    std::vector<std::string> names = scene_names();
    names.insert(names.begin(), "ch14");
    cli.add_choice("--scene", which, names,
                   "ch14 (book 3's Cornell box), or chNN / chNN-NAME: an earlier chapter's scene");
    cli.add_choice("--integrator", integrator, {"mis", "light", "path"},
                   "mis (next-event estimation with MIS), light (book 3), or path (chapter 03)");
    cli.add_text("--texture", texture_file, "Image for globes");
    return cli.run(argc, argv, [&] {
        rt::scene scene =
            which == "ch14" ? book3_cornell_box() : scene_by_name(which, texture_file);
        if (integrator == "mis") return rt::mis_trace(scene);
        return integrator == "light" ? rt::mixture_trace(scene) : rt::path_trace(scene);
    });
}
