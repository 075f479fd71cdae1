// Book 1's final scene (chapter 06's `--scene final`) with this chapter's BVH: the same ~480
// static spheres, camera and settings, so the image is byte for byte chapter 06's, only found
// faster (ch07_motion_blur --scene ch06-final; --accel list gives chapter 06's flat list).
// Chapter 06 stays without a BVH, as the book has it.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "ch06_defocus/lens_scenes.h"
#include "ch06_defocus/random_spheres.h"
#include "rt/accel/bounded.h"
#include "rt/accel/bvh.h"
#include "rt/scene/scene.h"

inline rt::scene book1_final_scene_in_bvh(bool use_bvh) {
    rt::scene scene = book1_final_scene(std::nullopt, std::nullopt);
    if (use_bvh) {
        std::vector<rt::bounded_object> spheres;
        for (auto& s : random_spheres()) spheres.emplace_back(s);
        scene.world = std::make_shared<rt::bvh>(spheres);
    }
    return scene;
}
