// Book 2's final scene is the book's own layout (chapters/ch13_final/final_layout.h). The
// expected numbers were printed by the book's own code (RayTracing/raytracing.github.io,
// v4.0.0-alpha.1 sources, src/TheNextWeek/main.cc, its default final_scene), built with g++ 12
// -O2 on x86-64, with a print in box() and the sphere constructor. The cluster comes after the
// BVH over the boxes and after the marble's Perlin tables in the book's one stream of draws, so
// its first center checks the count of both.
#include <catch2/catch.hpp>

#include "book_values.h"
#include "ch13_final/final_layout.h"
#include "rt/textures/perlin.h"

TEST_CASE("final layout: the boxes' heights and the cluster are the book's", "[ch13]") {
    const book2_final_layout layout = book2_final_draws();
    REQUIRE(layout.box_heights.size() == 400);
    REQUIRE(layout.cluster.size() == 1000);
    // Boxes (0, 0), (1, 0) and (19, 19): i runs over x in the outer loop.
    CHECK(layout.box_heights[0] == book_value(85.01877167634666));
    CHECK(layout.box_heights[20] == book_value(2.6300571616739035));
    CHECK(layout.box_heights[399] == book_value(45.25602350383997));
    // point3::random(0, 165) draws z first.
    check_book_vector(layout.cluster[0], 148.31555939046666, 33.988111687358469,
                      149.51706342631951);
    check_book_vector(layout.cluster[1], 52.941361062694341, 104.60802891058847,
                      49.162666636984795);
    check_book_vector(layout.cluster[999], 162.55792600801215, 145.56747295428067,
                      156.46185136400163);
}

TEST_CASE("final layout: the book's BVH draws one split axis per node it builds", "[ch13]") {
    // bvh_node(n objects): a node, then both halves; one or two objects make a single node.
    CHECK(book_bvh_draws(1) == 1);
    CHECK(book_bvh_draws(2) == 1);
    CHECK(book_bvh_draws(3) == 3);  // 1 + (1) + (2)
    CHECK(book_bvh_draws(4) == 3);
    CHECK(book_bvh_draws(5) == 5);  // 1 + (2) + (3)
    CHECK(book_bvh_draws(400) == 511);
}

TEST_CASE("final layout: the marble's Perlin noise is the book's", "[ch13]") {
    // The book's perlin built after 400 + 511 draws, at four points: noise, then turbulence.
    book2_final_layout layout = book2_final_draws();
    const rt::perlin marble(layout.marble_draws);
    CHECK(marble.noise({0.5, 0.25, 0.75}) == book_value(0.011251742124841403));
    CHECK(marble.turbulence({0.5, 0.25, 0.75}) == book_value(0.011421158613663461));
    CHECK(marble.noise({3.3, -1.7, 12.1}) == book_value(-0.2408557126264711));
    CHECK(marble.turbulence({-20.4, 7.9, 0.3}) == book_value(0.091069899347882857));
    // Far from the origin, at a point float holds exactly (a point it rounds moves the noise by
    // more than float's precision of the sums).
    CHECK(marble.noise({100.125, -50.625, 7.75}) == book_value(-0.14241185163513415));
}
