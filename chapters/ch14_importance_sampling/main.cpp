// Chapter 14: importance sampling. A Monte Carlo estimate of an integral,
//   integral of g  ~=  (1/N) sum g(x_i) / p(x_i),
// is right for any density p that is nonzero wherever g is, and the less noisy the more p looks
// like g. In chapters 03-13 a path's next direction follows the material alone (cos / pi for a
// diffuse surface), so a small lamp was found only by luck. Book 3 aims half of the directions at
// the lights: a quad light by a uniform point of its area, a sphere light by the cone of directions
// it fills (both as densities per solid angle), and weights by the mixture
//   p(wi) = 1/2 p_material(wi) + 1/2 p_lights(wi),   weight = f(wi) |cos| / p(wi).
// --integrator path renders with chapter 03's path tracer instead; --scene chNN renders chapter
// NN's scene (as book 3 re-renders book 2's Cornell box), --scene chNN-NAME another of its scenes.
#include <string>
#include <vector>

#include "book3_cornell_box.h"
#include "ch05_dielectric/fresnel_option.h"
#include "ch06_defocus/layout_seed_option.h"
#include "ch08_textures/texture_decoding_option.h"
#include "rt/integrators/mixture_tracer.h"
#include "rt/integrators/path_tracer.h"
#include "rt/program/asset_path.h"
#include "rt/program/command_line.h"
#include "scene_catalog.h"

int main(int argc, char** argv) {
    rt::command_line cli("ch14_importance_sampling");
    add_fresnel_option(cli);
    add_layout_seed_option(cli);
    add_texture_decoding_option(cli);
    std::string which = "ch14", integrator = "light", texture_file = rt::asset_path("globe.png");
    std::vector<std::string> names = scene_names();
    names.insert(names.begin(), "ch14");
    cli.add_choice("--scene", which, names,
                   "ch14 (book 3's Cornell box), or chNN / chNN-NAME: an earlier chapter's scene");
    cli.add_choice("--integrator", integrator, {"light", "path"},
                   "light (book 3's mixture), or path (chapter 03's path tracer)");
    cli.add_text("--texture", texture_file, "Image for globes");
    return cli.run(argc, argv, [&] {
        rt::scene scene =
            which == "ch14" ? book3_cornell_box() : scene_by_name(which, texture_file);
        return integrator == "light" ? rt::mixture_trace(scene) : rt::path_trace(scene);
    });
}
