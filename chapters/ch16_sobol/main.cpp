// Chapter 16: better samples. Independent random numbers clump and leave holes, and the error
// of N of them falls only as 1/sqrt(N). Sobol's sequence fills the unit square evenly: any
// 2^m consecutive points put exactly one point in each of 2^m equal cells. Scrambling it
// (Owen: every binary digit flipped by a random function of the digits before it) keeps that and
// makes each point uniformly random, so estimates stay unbiased; shuffling the order per pixel
// (Burley 2020) keeps neighbouring pixels from sharing a pattern. Each draw of a path has its
// place (sampler.h: the camera's draws, then 8 per segment), so draw j of segment k is always
// the same kind of number and its points stay evenly spread.
// --sampler independent for comparison; --integrator and --scene as in chapter 15.
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
#include "rt/samplers/sobol_sampler.h"

int main(int argc, char** argv) {
    rt::command_line cli("ch16_sobol");
    add_fresnel_option(cli);
    add_layout_seed_option(cli);
    add_texture_decoding_option(cli);
    std::string which = "ch14", integrator = "mis", samples = "sobol";
    std::string texture_file       = rt::asset_path("globe.png");
    std::vector<std::string> names = scene_names();
    names.insert(names.begin(), "ch14");
    cli.add_choice("--scene", which, names,
                   "ch14 (book 3's Cornell box), or chNN / chNN-NAME: an earlier chapter's scene");
    cli.add_choice("--integrator", integrator, {"mis", "light", "path"},
                   "mis (chapter 15), light (chapter 14), or path (chapter 03)");
    cli.add_choice("--sampler", samples, {"sobol", "independent"},
                   "sobol, or independent (chapter 01's PCG32 streams)");
    cli.add_text("--texture", texture_file, "Image for globes");
    return cli.run(argc, argv, [&] {
        rt::scene scene =
            which == "ch14" ? book3_cornell_box() : scene_by_name(which, texture_file);
        if (samples == "sobol") scene.settings.make_sampler = rt::sobol_sampler::make;
        if (integrator == "mis") return rt::mis_trace(scene);
        return integrator == "light" ? rt::mixture_trace(scene) : rt::path_trace(scene);
    });
}
