// The empty Cornell box of book 2 (the walls and the light), shared by chapters 11 and 12.
// A 555-unit room open at z = 0: green wall at x = 555, red at x = 0, white floor, ceiling and
// back; a light just under the ceiling. The camera at (278, 278, -800) looks in along +z, so the
// green wall is on the left of the image.
// At the end, book 2's Cornell box itself, cornell_box(): chapter 11's report scene, and
// --scene ch11 of later chapters' programs.
#pragma once

#include <memory>
#include <vector>

#include "rt/accel/bvh.h"
#include "rt/camera/thin_lens_camera.h"
#include "rt/geometry/box.h"
#include "rt/geometry/instance.h"
#include "rt/geometry/quad.h"
#include "rt/materials/diffuse_light.h"
#include "rt/materials/lambertian.h"
#include "rt/scene/scene.h"

// Where the room stands: each point p of book 2's room goes to scale * p + offset. The book's
// room is the identity; the scale hard case (tests/ch11/test_scale.cpp) renders the same room at
// 1e-4 ... 1e4 and far from the origin, and expects the same image.
struct room_placement {
    rt::real scale  = 1;
    rt::vec3 offset = rt::vec3(0, 0, 0);
    rt::point3 at(const rt::point3& p) const { return scale * p + offset; }
    rt::vec3 size(const rt::vec3& v) const { return scale * v; }
};

struct cornell_light {
    rt::point3 Q;
    rt::vec3 u, v;
    rt::real radiance;
};

// A box of the given size turned about y by `degrees`, then moved by `offset`: the way book 2
// places the Cornell boxes (rotate first, about the box's own corner, then translate).
inline std::shared_ptr<rt::translate> placed_box(rt::vec3 size, double degrees, rt::vec3 offset,
                                                 std::shared_ptr<rt::material> mat,
                                                 const room_placement& room = {}) {
    rt::vec3 extent = room.size(size);
    auto shape  = rt::box(rt::point3(0, 0, 0), rt::point3(extent.x(), extent.y(), extent.z()), mat);
    auto turned = std::make_shared<rt::rotate>(shape, rt::axis::y, degrees);
    return std::make_shared<rt::translate>(turned, room.at(offset));
}

// The room's walls and light; its white is returned too, for the boxes inside.
struct cornell_room {
    std::vector<rt::bounded_object> walls;
    std::shared_ptr<rt::lambertian> white;
};

inline cornell_room empty_cornell_room(const cornell_light& light_quad,
                                       const room_placement& place = {}) {
    using rt::color, rt::point3, rt::vec3;
    auto red   = std::make_shared<rt::lambertian>(color(0.65, 0.05, 0.05));
    auto green = std::make_shared<rt::lambertian>(color(0.12, 0.45, 0.15));
    auto light = std::make_shared<rt::diffuse_light>(color(1, 1, 1) * light_quad.radiance);
    cornell_room room{{}, std::make_shared<rt::lambertian>(color(0.73, 0.73, 0.73))};

    auto add_quad = [&](point3 Q, vec3 u, vec3 v, std::shared_ptr<rt::material> m) {
        room.walls.emplace_back(
            std::make_shared<rt::quad>(place.at(Q), place.size(u), place.size(v), std::move(m)));
    };
    add_quad(point3(555, 0, 0), vec3(0, 555, 0), vec3(0, 0, 555), green);
    add_quad(point3(0, 0, 0), vec3(0, 555, 0), vec3(0, 0, 555), red);
    add_quad(light_quad.Q, light_quad.u, light_quad.v, light);
    add_quad(point3(0, 0, 0), vec3(555, 0, 0), vec3(0, 0, 555), room.white);          // floor
    add_quad(point3(555, 555, 555), vec3(-555, 0, 0), vec3(0, 0, -555), room.white);  // ceiling
    add_quad(point3(0, 0, 555), vec3(555, 0, 0), vec3(0, 555, 0), room.white);        // back
    return room;
}

// The room with what was put in it, seen by book 2's Cornell camera in the dark. The objects go
// into a BVH: the same image as a list (tested in chapter 07), faster.
inline rt::scene cornell_scene(const std::vector<rt::bounded_object>& objects,
                               const room_placement& place = {}) {
    auto cam          = std::make_shared<rt::thin_lens_camera>();
    cam->aspect_ratio = 1;
    cam->vfov         = 40;
    cam->lookfrom     = place.at(rt::point3(278, 278, -800));
    cam->lookat       = place.at(rt::point3(278, 278, 0));

    rt::scene scene;
    scene.world    = std::make_shared<rt::bvh>(objects);
    scene.sky      = rt::background::uniform(rt::color(0, 0, 0));
    scene.cam      = cam;
    scene.settings = {.width = 600, .samples_per_pixel = 200, .max_depth = 50};
    return scene;
}

// Book 2's Cornell box: a tall box turned 15 degrees and a short one turned -18 degrees
// (placed_box, above, wraps rt::box in rt::rotate and rt::translate).
inline rt::scene cornell_box() {
    using rt::point3, rt::vec3;
    cornell_room room =
        empty_cornell_room({point3(343, 554, 332), vec3(-130, 0, 0), vec3(0, 0, -105), 15});
    auto objects = room.walls;
    objects.emplace_back(placed_box(vec3(165, 330, 165), 15, vec3(265, 0, 295), room.white));
    objects.emplace_back(placed_box(vec3(165, 165, 165), -18, vec3(130, 0, 65), room.white));
    return cornell_scene(objects);
}
