// Book 3's Cornell box: book 2's room and tall box, with a glass sphere where the short box
// stood. Book 3 also lists the glass sphere among its "lights" so that some rays aim at it; we
// find lights in the scene itself (rt/lights/light_set.h), so only the ceiling lamp is aimed at.
#pragma once

#include <memory>

#include "ch11_instances/cornell_box.h"
#include "rt/geometry/sphere.h"
#include "rt/materials/dielectric.h"

inline rt::scene book3_cornell_box() {
    using rt::point3, rt::vec3;
    cornell_room room =
        empty_cornell_room({point3(343, 554, 332), vec3(-130, 0, 0), vec3(0, 0, -105), 15});
    auto objects = room.walls;
    objects.emplace_back(placed_box(vec3(165, 330, 165), 15, vec3(265, 0, 295), room.white));
    objects.emplace_back(std::make_shared<rt::sphere>(point3(190, 90, 190), 90,
                                                      std::make_shared<rt::dielectric>(1.5)));
    rt::scene scene = cornell_scene(objects);
    // Book 3's settings: 600 wide, 100 samples per pixel, 50 segments.
    scene.settings.samples_per_pixel = 100;
    return scene;
}
