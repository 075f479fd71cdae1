#include "anchor_geometry.h"

#include "ch06_defocus/random_spheres.h"
#include "ch11_instances/cornell_box.h"
#include "ch13_final/final_layout.h"
#include "rt/geometry/box.h"
#include "rt/geometry/instance.h"
#include "rt/materials/lambertian.h"
#include "single_precision.h"

namespace rt_bench {

void anchor_geometry::add(const rt::sphere& s) {
    spheres.push_back({to_float(s.center()), to_float(s.radius())});
}

void anchor_geometry::add(const rt::quad& q) {
    quads.push_back({to_float(q.corner()), to_float(q.edge_u()), to_float(q.edge_v())});
}

std::vector<rt::bounded_object> anchor_geometry::objects() const {
    // Materials play no part in finding hits; one for all.
    auto gray = std::make_shared<rt::lambertian>(rt::color(0.5, 0.5, 0.5));
    std::vector<rt::bounded_object> out;
    for (const auto& s : spheres)
        out.emplace_back(std::make_shared<rt::sphere>(s.center, s.radius, gray));
    for (const auto& q : quads)
        out.emplace_back(std::make_shared<rt::quad>(q.corner, q.u, q.v, gray));
    return out;
}

anchor_geometry book1_geometry() {
    anchor_geometry g;
    for (const auto& s : random_spheres()) g.add(*s);
    return g;
}

anchor_geometry bouncing_geometry() {
    anchor_geometry g;
    for (const auto& s : random_sphere_layout(/*bouncing=*/true)) g.add(*s.sphere);
    return g;
}

anchor_geometry book2_final_geometry() {
    // The numbers of book2_final_scene(), from the same draws (final_layout.h); that
    // function builds a scene whose BVH does not show its shapes, so they are repeated here
    // (the anchor checks them against the real scene: embree_anchor.cpp).
    using rt::point3, rt::vec3;
    anchor_geometry g;
    const book2_final_layout layout = book2_final_draws();
    auto ground                     = std::make_shared<rt::lambertian>(rt::color(0.48, 0.83, 0.53));
    for (int i = 0; i < 20; ++i) {
        for (int j = 0; j < 20; ++j) {
            double x0 = -1000.0 + i * 100.0, z0 = -1000.0 + j * 100.0;
            double y1 = layout.box_heights[std::size_t(i * 20 + j)];
            for (const auto& face :
                 rt::box_faces(point3(x0, 0, z0), point3(x0 + 100, y1, z0 + 100), ground))
                g.add(dynamic_cast<const rt::quad&>(*face.object));
        }
    }
    g.add(rt::quad(point3(123, 554, 147), vec3(300, 0, 0), vec3(0, 0, 265), ground));

    g.add(rt::sphere(point3(400, 400, 200), 50));  // the moving sphere at time 0
    g.add(rt::sphere(point3(260, 150, 45), 50));
    g.add(rt::sphere(point3(0, 150, 145), 50));
    g.add(rt::sphere(point3(360, 150, 145), 70));  // the glass ball around the blue medium
    g.add(rt::sphere(point3(400, 200, 400), 100));
    g.add(rt::sphere(point3(220, 280, 300), 80));

    // The cluster: turned 15 degrees about y, then moved; its spheres' centers go along.
    const rt::rotate turn(std::make_shared<rt::sphere>(point3(0, 0, 0), 1), rt::axis::y, 15);
    const vec3 offset(-100, 270, 395);
    for (const point3& center : layout.cluster)
        g.add(rt::sphere(turn.to_world(center) + offset, 10));
    g.left_out =
        "the blue medium in the glass ball and the mist (media: no surface); the cluster's "
        "instance is flattened into 1000 world-space spheres";
    return g;
}

anchor_geometry cornell_box_geometry() {
    using rt::point3, rt::vec3;
    anchor_geometry g;
    auto white = std::make_shared<rt::lambertian>(rt::color(0.73, 0.73, 0.73));
    // The walls and the light of cornell_box(), as its room puts them.
    cornell_room room =
        empty_cornell_room({point3(343, 554, 332), vec3(-130, 0, 0), vec3(0, 0, -105), 15});
    for (const auto& wall : room.walls) g.add(dynamic_cast<const rt::quad&>(*wall.object));
    // The boxes of cornell_box(): size, turn about y, then the move (placed_box()).
    struct placed {
        vec3 size;
        double degrees;
        vec3 offset;
    };
    for (const placed& b : {placed{vec3(165, 330, 165), 15, vec3(265, 0, 295)},
                            placed{vec3(165, 165, 165), -18, vec3(130, 0, 65)}}) {
        const rt::rotate turn(std::make_shared<rt::sphere>(point3(0, 0, 0), 1), rt::axis::y,
                              b.degrees);
        for (const auto& face : rt::box_faces(point3(0, 0, 0), point3(0, 0, 0) + b.size, white)) {
            const auto& q = dynamic_cast<const rt::quad&>(*face.object);
            g.add(rt::quad(turn.to_world(q.corner()) + b.offset, turn.to_world(q.edge_u()),
                           turn.to_world(q.edge_v()), white));
        }
    }
    g.left_out = "nothing: the two boxes' instances are flattened into 12 world-space quads";
    return g;
}

}  // namespace rt_bench
