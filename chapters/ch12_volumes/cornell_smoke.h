// Chapter 12's report scene: book 2's Cornell smoke, the Cornell box whose two boxes are
// replaced by black smoke and white fog. Later chapters' programs render it as --scene ch12.
#pragma once

#include <memory>

#include "ch11_instances/cornell_box.h"
#include "rt/media/constant_medium.h"
#include "rt/scene/scene.h"

// Chapter 11's placed box as the boundary of a medium of density 0.01 (the boundary's own
// material is never seen: the medium replaces its surface).
inline std::shared_ptr<rt::constant_medium> smoke_box(rt::vec3 size, double degrees,
                                                      rt::vec3 offset, rt::color albedo,
                                                      std::shared_ptr<rt::material> any) {
    return std::make_shared<rt::constant_medium>(placed_box(size, degrees, offset, any), 0.01,
                                                 albedo);
}

// Book 2's Cornell smoke: the two boxes become black smoke and white fog, under a bigger light.
inline rt::scene cornell_smoke() {
    using rt::color, rt::point3, rt::vec3;
    cornell_room room =
        empty_cornell_room({point3(113, 554, 127), vec3(330, 0, 0), vec3(0, 0, 305), 7});
    auto objects = room.walls;
    objects.emplace_back(
        smoke_box(vec3(165, 330, 165), 15, vec3(265, 0, 295), color(0, 0, 0), room.white));
    objects.emplace_back(
        smoke_box(vec3(165, 165, 165), -18, vec3(130, 0, 65), color(1, 1, 1), room.white));
    return cornell_scene(objects);
}
