// Book 2's bouncing spheres are the book's own layout (chapters/ch06_defocus/random_spheres.h,
// random_sphere_layout(true)). The expected numbers were printed by the book's own code
// (RayTracing/raytracing.github.io, v4.0.0-alpha.1 sources, src/TheNextWeek/main.cc, scene 1),
// built with g++ 12 -O2 on x86-64, with a print in the sphere constructors. Book 2 draws each
// matte sphere's rise right after its colour: a rise drawn after the whole layout, or book 1's
// layout reused, differs from the first matte sphere on.
#include <catch2/catch.hpp>

#include "book_values.h"
#include "ch06_defocus/random_spheres.h"

TEST_CASE("random spheres: book 2's bouncing spheres draw each rise after the colour", "[ch07]") {
    const auto layout = random_sphere_layout(/*bouncing=*/true);
    REQUIRE(layout.size() == 484);  // the ground, 480 small ones, the three big ones
    int rising = 0;
    for (const auto& s : layout)
        if (s.rise > 0) ++rising;
    CHECK(rising == 384);
    // The book's first two moving spheres: their start, and their top at the shutter's close.
    std::size_t first = 0;
    while (first < layout.size() && layout[first].rise == 0) ++first;
    REQUIRE(first + 1 < layout.size());
    check_book_vector(layout[first].sphere->center(), -10.501427040016278, 0.2,
                      -9.7500027603935457);
    CHECK(0.2 + layout[first].rise == book_value(0.51785586383193727));
    check_book_vector(layout[first + 1].sphere->center(), -10.453728011623024, 0.2,
                      -8.8725577002391223);
    CHECK(0.2 + layout[first + 1].rise == book_value(0.26489522336050869));
}
