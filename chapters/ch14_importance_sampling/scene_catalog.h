// Every earlier chapter's scenes by name, for the programs of chapter 14 on. Book 3 re-renders
// book 2's Cornell box with its new sampling; in the same way a new technique reaches any earlier
// scene through the later chapter's program (--scene ch11), while chapters 03-13 keep their own
// programs, integrator and goldens. "chNN" is chapter NN's report scene (the default of its
// --scene flag), "chNN-NAME" another scene of that chapter; each comes with its chapter's own
// default settings, camera and sky.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ch03_diffuse/matte_scene.h"
#include "ch04_metal/metal_scene.h"
#include "ch05_dielectric/glass_scene.h"
#include "ch06_defocus/lens_scenes.h"
#include "ch07_motion_blur/book1_in_bvh.h"
#include "ch07_motion_blur/bouncing_spheres.h"
#include "ch08_textures/book_checker_scenes.h"
#include "ch08_textures/checker_scene.h"
#include "ch08_textures/globe_scene.h"
#include "ch09_perlin/perlin_spheres.h"
#include "ch10_lights/book_quads.h"
#include "ch10_lights/simple_light.h"
#include "ch11_instances/cornell_box.h"
#include "ch11_instances/rotations_scene.h"
#include "ch12_volumes/cornell_smoke.h"
#include "ch13_final/final_scene.h"
#include "rt/core/error.h"
#include "rt/scene/scene.h"

// One entry per scene: its name and how to build it. The texture file is the image the globes
// of ch08, ch09-globe and ch13 are wrapped in; the other scenes ignore it.
struct catalog_scene {
    std::string_view name;
    rt::scene (*build)(const std::string& texture_file);
};

// In chapter order. The one list that both scene_names() and scene_by_name() read, so that a
// name offered is always a name that builds. (A function, not an inline variable: lambdas in an
// inline function are the same in every translation unit.)
inline std::span<const catalog_scene> catalog_scenes() {
    static constexpr auto scenes = std::to_array<catalog_scene>({
        {"ch03", [](const std::string&) { return matte_spheres_on_floor(); }},
        {"ch03-book", [](const std::string&) { return book_diffuse_spheres(); }},
        {"ch04", [](const std::string&) { return metal_spheres(); }},
        {"ch05", [](const std::string&) { return glass_scene_from_origin(); }},
        {"ch06",
         [](const std::string&) { return glass_scene_through_lens(std::nullopt, std::nullopt); }},
        {"ch06-book",
         [](const std::string&) { return book_depth_of_field(std::nullopt, std::nullopt); }},
        {"ch06-final",
         [](const std::string&) { return book1_final_scene(std::nullopt, std::nullopt); }},
        {"ch07", [](const std::string&) { return bouncing_spheres(/*use_bvh=*/true); }},
        {"ch07-list", [](const std::string&) { return bouncing_spheres(/*use_bvh=*/false); }},
        {"ch07-ch06-final",
         [](const std::string&) { return book1_final_scene_in_bvh(/*use_bvh=*/true); }},
        {"ch08", [](const std::string& texture) { return globe(texture); }},
        {"ch08-checker", [](const std::string&) { return checkered_spheres(); }},
        {"ch08-bouncing", [](const std::string&) { return bouncing_spheres_on_checker(); }},
        {"ch08-two-spheres", [](const std::string&) { return two_checkered_spheres(); }},
        {"ch09",
         [](const std::string& texture) { return perlin_spheres(texture, /*with_globe=*/false); }},
        {"ch09-globe",
         [](const std::string& texture) { return perlin_spheres(texture, /*with_globe=*/true); }},
        {"ch10", [](const std::string&) { return simple_light(); }},
        {"ch10-quads", [](const std::string&) { return book_quads(); }},
        {"ch11", [](const std::string&) { return cornell_box(); }},
        {"ch11-rotations", [](const std::string&) { return turned_boxes(); }},
        {"ch12", [](const std::string&) { return cornell_smoke(); }},
        {"ch13", [](const std::string& texture) { return book2_final_scene(texture); }},
    });
    return scenes;
}

// The names, in chapter order (for a command line's list of choices).
inline std::vector<std::string> scene_names() {
    std::vector<std::string> names;
    for (const catalog_scene& entry : catalog_scenes()) names.emplace_back(entry.name);
    return names;
}

// The named scene with its chapter's default settings; an unknown name is the user's mistake.
inline rt::scene scene_by_name(const std::string& name, const std::string& texture_file) {
    std::string valid;
    for (const catalog_scene& entry : catalog_scenes()) {
        if (entry.name == name) return entry.build(texture_file);
        valid += (valid.empty() ? "" : ", ") + std::string(entry.name);
    }
    throw rt::user_error("scene must be one of " + valid + ", got " + name);
}
