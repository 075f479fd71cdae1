// Chapter 11's second scene (--scene rotations): three equal boxes in the Cornell room, turned
// about their own centers by 35 degrees about x, y and z in turn (left to right in the image),
// so that every rotation of rt::rotate is seen once. About x the box leans towards the camera
// (the angle is -35: right-handed about x, +35 would tip its top away), about y it twists, about
// z it leans sideways.
#pragma once

#include <memory>

#include "cornell_box.h"
#include "rt/geometry/box.h"
#include "rt/geometry/instance.h"

// A box of the given size centered on the origin, turned about `about` by `degrees`, then moved
// so that its center is above (x, z) and its lowest point rests on the floor y = 0.
inline std::shared_ptr<rt::translate> box_turned_about(rt::axis about, double degrees,
                                                       rt::vec3 size, double x, double z,
                                                       std::shared_ptr<rt::material> mat) {
    auto shape  = rt::box(rt::point3(0, 0, 0) - size / 2, rt::point3(0, 0, 0) + size / 2, mat);
    auto turned = std::make_shared<rt::rotate>(shape, about, degrees);
    double lift = -turned->bounding_box().y.min;
    return std::make_shared<rt::translate>(turned, rt::vec3(x, lift, z));
}

inline rt::scene turned_boxes() {
    using rt::point3, rt::vec3, rt::axis;
    // The larger light of chapter 12's room: less noise than book 2's small one.
    cornell_room room =
        empty_cornell_room({point3(113, 554, 127), vec3(330, 0, 0), vec3(0, 0, 305), 7});
    auto objects = room.walls;
    const vec3 size(90, 180, 90);
    // The camera's right is -x: the box at the largest x is on the image's left.
    objects.emplace_back(box_turned_about(axis::x, -35, size, 440, 250, room.white));
    objects.emplace_back(box_turned_about(axis::y, 35, size, 278, 250, room.white));
    objects.emplace_back(box_turned_about(axis::z, 35, size, 110, 250, room.white));
    rt::scene scene = cornell_scene(objects);
    // Book 2's camera moved up and in, looking down a little, so that the lean about x shows.
    auto cam          = std::make_shared<rt::thin_lens_camera>();
    cam->aspect_ratio = 1;
    cam->vfov         = 40;
    cam->lookfrom     = point3(278, 400, -500);
    cam->lookat       = point3(278, 150, 250);
    scene.cam         = cam;
    return scene;
}
