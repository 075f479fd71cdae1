// Chapter 17: fast traversal. Chapter 07's BVH is a binary tree: a ray tests two boxes at each
// level, one after the other, and every object through a virtual call. The same tree is packed
// for the machine: up to four of a node's descendants are folded into one wide node, whose four
// boxes the vector unit tests at once (and the widest descendant is unfolded first, as the one a
// ray likeliest enters), visited in the binary tree's own nearer-child-first order; and the leaves
// keep spheres and quads by type, tested by inlined code. The hits are the binary tree's, in the
// same order, so every image is unchanged, byte for byte; only the time changes.
// --scene chNN renders any earlier chapter's scene this way, with every integrator and sampler of
// chapters 14-16.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ch05_dielectric/fresnel_option.h"
#include "ch06_defocus/layout_seed_option.h"
#include "ch08_textures/texture_decoding_option.h"
#include "ch14_importance_sampling/book3_cornell_box.h"
#include "ch14_importance_sampling/scene_catalog.h"
#include "rt/accel/fast_traversal.h"
#include "rt/integrators/in_scattering.h"
#include "rt/integrators/mis_tracer.h"
#include "rt/integrators/mixture_tracer.h"
#include "rt/integrators/path_tracer.h"
#include "rt/lights/rectangle_light.h"
#include "rt/program/asset_path.h"
#include "rt/program/command_line.h"
#include "rt/render/adaptive_sampling.h"
#include "rt/samplers/sobol_sampler.h"

int main(int argc, char** argv) {
    rt::command_line cli("ch17_fast_traversal");
    add_fresnel_option(cli);
    add_layout_seed_option(cli);
    add_texture_decoding_option(cli);
    std::string which = "ch13", integrator = "mis", samples = "sobol";
    std::string texture_file       = rt::asset_path("globe.png");
    std::vector<std::string> names = scene_names();
    names.insert(names.begin(), "ch14");
    cli.add_choice("--scene", which, names,
                   "ch13 (book 2's final scene), ch14 (book 3's Cornell box), or chNN / "
                   "chNN-NAME: an earlier chapter's scene");
    cli.add_choice("--integrator", integrator, {"mis", "mis-expected", "light", "path"},
                   "mis (chapter 15), mis-expected (mis, with the light seen through media "
                   "counted by its exact transmittance), light (chapter 14), or path (chapter 03)");
    cli.add_choice("--sampler", samples, {"sobol", "independent"},
                   "sobol (chapter 16), or independent (chapter 01)");
    std::string quad_lights = "area";
    cli.add_choice("--quad-lights", quad_lights, {"area", "solid-angle"},
                   "how mis and mis-expected aim at rectangular lamps: area (chapter 14: a point "
                   "uniform on the lamp), or solid-angle (a direction uniform in the solid angle "
                   "the lamp covers)");
    std::string fuzzy_metal = "followed";
    cli.add_choice("--fuzzy-metal", fuzzy_metal, {"followed", "weighed"},
                   "what mis and mis-expected do at fuzzy metal: followed (chapter 15: only its "
                   "fuzzed direction), or weighed (the lights aimed at from it too, and both ways "
                   "weighed by their densities)");
    std::string medium_light = "scattered";
    cli.add_choice("--medium-light", medium_light, {"scattered", "along-rays"},
                   "how mis and mis-expected aim at the lights from fog and smoke: scattered "
                   "(chapter 15: from where a ray happens to scatter), or along-rays (every "
                   "segment through a medium aims once, from a point chosen along it, nearer the "
                   "lights more often: equiangular sampling)");
    std::optional<rt::real> noise_threshold;
    cli.add_number("--noise-threshold", noise_threshold,
                   "adaptive sampling: a pixel stops once the noise of its mean, as a screen shows "
                   "it, is at most this (units of white, e.g. 0.01; rt/render/adaptive_sampling.h)",
                   0, false);
    std::uint32_t min_spp = 16;
    bool min_spp_given    = false;
    cli.add_uint32_action("--min-spp",
                          "with --noise-threshold: samples every pixel takes before its first "
                          "check (default 16; then checks at each doubling)",
                          [&](std::uint32_t n) {
                              min_spp       = n;
                              min_spp_given = true;
                          });
    cli.add_text("--texture", texture_file, "Image for globes");
    return cli.run(argc, argv, [&] {
        rt::scene scene = rt::with_fast_traversal(
            which == "ch14" ? book3_cornell_box() : scene_by_name(which, texture_file));
        if (samples == "sobol") scene.settings.make_sampler = rt::sobol_sampler::make;
        if (min_spp_given && !noise_threshold)
            throw rt::user_error("--min-spp must come with --noise-threshold");
        if (noise_threshold)
            scene.settings.stop_early = std::make_shared<rt::display_noise_rule>(
                *noise_threshold, int(std::min<std::uint32_t>(min_spp, 1u << 30)));
        const bool mis = integrator == "mis" || integrator == "mis-expected";
        // The options of mis and mis-expected, given to another integrator, are refused.
        auto only_with_mis = [&](const std::string& flag, const std::string& value,
                                 const std::string& plain) {
            if (value == plain || mis) return;
            std::string message = flag;
            message += " " + value + " must come with --integrator mis or mis-expected, got ";
            message += integrator;
            throw rt::user_error(message);
        };
        only_with_mis("--quad-lights", quad_lights, "area");
        only_with_mis("--fuzzy-metal", fuzzy_metal, "followed");
        only_with_mis("--medium-light", medium_light, "scattered");
        if (mis) {
            rt::mis_choices choices;
            if (integrator == "mis-expected")
                choices.through_media = rt::light_through_media::expected;
            if (quad_lights == "solid-angle") choices.make_quad = rt::rectangle_light::make;
            choices.weigh_fuzzy_metal = fuzzy_metal == "weighed";
            if (medium_light == "along-rays") choices.aim_along_rays = rt::in_scattering::make;
            return rt::mis_trace(scene, choices);
        }
        return integrator == "light" ? rt::mixture_trace(scene) : rt::path_trace(scene);
    });
}
