// Every scene built in code in chapters 01-17, as a scene file would describe it: the scene and
// the integrator (and sampler) its chapter's program renders it with. "chNN" is chapter NN's
// report scene, "chNN-NAME" another scene of that chapter (chapter 14's catalogue); ch15, ch16
// and ch17 are chapter 14's and chapter 13's scenes with the estimators those chapters add.
#pragma once

#include <string>
#include <vector>

#include "ch01_background/empty_sky.h"
#include "ch02_sphere/sphere_scene.h"
#include "ch14_importance_sampling/book3_cornell_box.h"
#include "ch14_importance_sampling/scene_catalog.h"
#include "rt/core/error.h"
#include "rt/samplers/sobol_sampler.h"
#include "rt/scene_files/described_scene.h"

// Chapter 01 renders no scene, only the sky: its camera and settings with an empty world.
inline rt::described_scene chapter01_sky() {
    const rt::render_job job = empty_sky();
    rt::described_scene d;
    d.scene.cam      = job.cam;
    d.scene.settings = job.settings;
    d.integrator     = rt::integrator_kind::sky;
    return d;
}

inline rt::described_scene with_estimator(rt::scene s, rt::integrator_kind integrator,
                                          bool sobol = false) {
    if (sobol) s.settings.make_sampler = rt::sobol_sampler::make;
    return {std::move(s), integrator};
}

// The names, in chapter order.
inline std::vector<std::string> built_in_names() {
    std::vector<std::string> names{"ch01", "ch02"};
    for (const std::string& name : scene_names()) names.push_back(name);
    for (const char* name : {"ch14", "ch15", "ch16", "ch17"}) names.emplace_back(name);
    return names;
}

// The scene `name` as its chapter renders it; the texture file is the globes' image.
inline rt::described_scene built_in_scene(const std::string& name,
                                          const std::string& texture_file) {
    using rt::integrator_kind;
    if (name == "ch01") return chapter01_sky();
    if (name == "ch02") return with_estimator(sphere_on_ground(), integrator_kind::normals);
    if (name == "ch14") return with_estimator(book3_cornell_box(), integrator_kind::light);
    if (name == "ch15") return with_estimator(book3_cornell_box(), integrator_kind::mis);
    if (name == "ch16") return with_estimator(book3_cornell_box(), integrator_kind::mis, true);
    if (name == "ch17")
        return with_estimator(book2_final_scene(texture_file), integrator_kind::mis, true);
    return with_estimator(scene_by_name(name, texture_file), integrator_kind::path);
}
