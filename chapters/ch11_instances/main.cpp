// Chapter 11: instances. A box is six quads; to turn and place it we do not move its quads but
// move each ray the opposite way into the box's own space, hit the box there, and carry the hit
// point and normal back out. About the y axis by theta:
//   x' = cos(theta) x + sin(theta) z,   z' = -sin(theta) x + cos(theta) z.
#include <memory>

#include "common/bvh.h"
#include "common/options.h"
#include "cornell_box.h"

// Book 2's Cornell box: a tall box turned 15 degrees and a short one turned -18 degrees
// (placed_box, in cornell_box.h, wraps rt::box in rt::rotate and rt::translate).
rt::scene cornell_box() {
    using rt::point3, rt::vec3;
    std::shared_ptr<rt::lambertian> white;
    rt::scene scene = cornell_room({point3(343, 554, 332), vec3(-130, 0, 0), vec3(0, 0, -105), 15},
                                   white);
    scene.world.add(placed_box(vec3(165, 330, 165), 15, vec3(265, 0, 295), white));
    scene.world.add(placed_box(vec3(165, 165, 165), -18, vec3(130, 0, 65), white));
    // A BVH over the walls and boxes: the same image as a list (tested in chapter 07), faster.
    scene.world = rt::hittable_list(std::make_shared<rt::bvh>(scene.world.objects));
    return scene;
}

int main(int argc, char** argv) {
    rt::command_line cli("ch11_instances",
                         {.width = 600, .render = {.samples_per_pixel = 200, .max_depth = 50}});
    return cli.run(argc, argv, cornell_box);
}
