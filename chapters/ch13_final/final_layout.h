// What book 2's final scene draws at random, in the book's order, from the book's random
// numbers (rt/core/book_random.h): the ground boxes' heights, then (after the draws of the
// book's BVH over those boxes) the marble sphere's Perlin tables, then the cluster's 1000
// sphere centers. The scene (final_scene.h) and the Embree anchor's copy of its geometry
// (bench/anchor_geometry.cpp) both read it, so they cannot drift apart.
#pragma once

#include <cstddef>
#include <vector>

#include "rt/core/book_random.h"
#include "rt/core/vec3.h"
#include "rt/textures/perlin.h"

// The book's bvh_node draws one random_int(0, 2) for its split axis in every node it builds,
// leaves of one or two objects included, left subtree first: 1 + draws(n/2) + draws(n - n/2).
// The count depends on n alone, not on where the objects are.
inline std::size_t book_bvh_draws(std::size_t objects) {
    if (objects <= 2) return 1;
    return 1 + book_bvh_draws(objects / 2) + book_bvh_draws(objects - objects / 2);
}

struct book2_final_layout {
    std::vector<double> box_heights;  // 20 x 20 boxes, box (i, j) at i * 20 + j
    rt::book_random marble_draws;     // the stream as the book's noise_texture(0.1) finds it
    std::vector<rt::point3> cluster;  // the 1000 centers, before the cluster is turned and moved
};

inline book2_final_layout book2_final_draws() {
    book2_final_layout layout;
    rt::book_random draws;
    for (int k = 0; k < 20 * 20; ++k) layout.box_heights.push_back(draws.uniform(1, 101));
    draws.skip(book_bvh_draws(20 * 20));
    layout.marble_draws = draws;
    rt::perlin tables(draws);  // draws what the marble texture draws, to find the cluster's
    for (int k = 0; k < 1000; ++k) layout.cluster.push_back(draws.vector(0, 165));
    return layout;
}
