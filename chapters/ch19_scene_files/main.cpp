// Chapter 19: scene files. Until now every scene was C++, compiled into its chapter: a new scene
// meant a new program. A scene file says the same in text a person writes by hand (TOML, with
// comments): the render settings, the camera, the sky, named textures and materials, and the
// objects of the world, each with a type and its numbers, a named object placed wherever it is
// used, a box turned and moved by a list of transform steps. The reader checks every value where
// it stands and refuses a bad one with its file, line and column; the writer turns any scene of
// the earlier chapters into such a file, with every number exact, so that the file renders the
// very same image, byte for byte.
// --scene-file FILE renders a file (the chapter's own by default); --scene chNN an earlier
// chapter's scene as its chapter renders it; --dump-scene FILE writes the chosen scene as a file
// instead of rendering it. --integrator and --sampler override the scene's own.
#include <cstdio>
#include <string>
#include <vector>

#include "built_in_scenes.h"
#include "ch05_dielectric/fresnel_option.h"
#include "ch06_defocus/layout_seed_option.h"
#include "ch08_textures/texture_decoding_option.h"
#include "rt/accel/fast_traversal.h"
#include "rt/accel/mesh_bvh.h"
#include "rt/integrators/mis_tracer.h"
#include "rt/integrators/mixture_tracer.h"
#include "rt/integrators/path_tracer.h"
#include "rt/integrators/show_normals.h"
#include "rt/integrators/sky_only.h"
#include "rt/program/asset_path.h"
#include "rt/program/command_line.h"
#include "rt/samplers/independent_sampler.h"
#include "rt/samplers/sobol_sampler.h"
#include "rt/scene_files/scene_reader.h"
#include "rt/scene_files/scene_writer.h"

// The render of a described scene with its integrator, through chapter 17's fast traversal
// (which finds the same hits as the scene's own BVHs: the image is the same).
rt::render_job render_job_of(const rt::described_scene& described) {
    rt::scene scene = rt::with_fast_traversal(described.scene, {}, {rt::mesh_bvh::packer()});
    switch (described.integrator) {
        case rt::integrator_kind::sky: {
            rt::render_job job;
            job.cam       = scene.cam;
            job.estimator = std::make_shared<rt::sky_only>(scene.sky);
            job.settings  = scene.settings;
            return job;
        }
        case rt::integrator_kind::normals:
            return rt::show_normals(scene);
        case rt::integrator_kind::path:
            return rt::path_trace(scene);
        case rt::integrator_kind::light:
            return rt::mixture_trace(scene);
        case rt::integrator_kind::mis:
            break;
    }
    return rt::mis_trace(scene);
}

int main(int argc, char** argv) {
    rt::command_line cli("ch19_scene_files");
    add_fresnel_option(cli);
    add_layout_seed_option(cli);
    add_texture_decoding_option(cli);
    std::string scene_file = rt::asset_path("scenes/cornell_box_my_way.toml"), which, dump;
    std::string integrator, samples, texture_file = rt::asset_path("globe.png");
    cli.add_text("--scene-file", scene_file, "Scene file to render (TOML)");
    cli.add_choice("--scene", which, built_in_names(),
                   "render chapter NN's scene built in code instead (chNN or chNN-NAME)", false);
    cli.add_text("--dump-scene", dump,
                 "Write the scene as a scene file (.toml) instead of rendering it", false);
    cli.add_choice("--integrator", integrator, {"sky", "normals", "path", "light", "mis"},
                   "override the scene's integrator", false);
    cli.add_choice("--sampler", samples, {"independent", "sobol"}, "override the scene's sampler",
                   false);
    cli.add_text("--texture", texture_file, "Image for the globes of built-in scenes");
    bool list = false;
    cli.add_flag("--list-scenes", list, "Print the names --scene takes, one a line, and stop");

    // The scene as chosen, with the overrides the command line gives.
    auto chosen = [&] {
        rt::described_scene described =
            which.empty() ? rt::read_scene_file(scene_file) : built_in_scene(which, texture_file);
        if (!integrator.empty()) described.integrator = *rt::integrator_named(integrator);
        if (samples == "sobol") described.scene.settings.make_sampler = rt::sobol_sampler::make;
        if (samples == "independent")
            described.scene.settings.make_sampler = rt::independent_sampler::make;
        return described;
    };
    return cli.run(
        argc, argv, [&] { return render_job_of(chosen()); },
        [&] {
            if (list) {
                for (const std::string& name : built_in_names()) std::printf("%s\n", name.c_str());
                return true;
            }
            if (dump.empty()) return false;
            rt::described_scene described = chosen();
            described.scene.settings      = cli.with_flags(described.scene.settings);
            const std::string title       = which.empty()
                                                ? "The scene file " + scene_file + ", written again"
                                                : "The built-in scene " + which +
                                                ", as chapter 19's program writes it: "
                                                      "ch19_scene_files --scene " +
                                                which + " --dump-scene FILE";
            rt::write_scene_file(described, dump, title);
            return true;
        });
}
