// The static geometry of a benchmark scene as plain numbers (spheres and parallelograms), so
// that the same shapes can be built in our BVH and in Embree. Every number is rounded to float
// (single_precision.h): both tracers then see exactly the same shapes.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "rt/accel/bounded.h"

namespace rt_bench {

struct anchor_geometry {
    struct sphere_shape {
        rt::point3 center;
        rt::real radius;
    };
    struct quad_shape {
        rt::point3 corner;
        rt::vec3 u, v;  // the edges: the points corner + a u + b v, a and b in [0, 1]
    };
    std::vector<sphere_shape> spheres;
    std::vector<quad_shape> quads;
    std::string left_out;  // what the scene has that is not here, for the report

    void add(const rt::sphere& s);
    void add(const rt::quad& q);

    // Our objects for these shapes: spheres first, then quads, in the order above, so that
    // object k of the result is shape k (spheres numbered 0.., quads after them).
    std::vector<rt::bounded_object> objects() const;
};

// Book 1's final scene: its spheres (random_spheres()).
anchor_geometry book1_geometry();

// Book 2's bouncing spheres at time 0, where each moving sphere is at its start (book 2 lays
// them out with draws of its own: random_sphere_layout(true)).
anchor_geometry bouncing_geometry();

// Book 2's final scene (chapters/ch13_final/final_scene.h) at time 0: the 2,400 faces of the
// ground boxes, the light, the spheres (the moving one at its start), and the 1,000 spheres of
// the turned and moved cluster placed in the world (an instance of spheres is spheres). Left
// out: the two media (the blue one inside the glass ball, whose surface is here, and the mist,
// whose boundary is no surface).
anchor_geometry book2_final_geometry();

// Book 2's Cornell box (chapters/ch11_instances/cornell_box.h): the five walls and the light,
// and the twelve faces of the two boxes, each face turned and moved into the world as the
// scene's rotate and translate instances place it (an instance of quads is quads).
anchor_geometry cornell_box_geometry();

}  // namespace rt_bench
