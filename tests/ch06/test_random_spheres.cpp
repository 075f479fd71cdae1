// Book 1's final scene and book 2's bouncing spheres are the book's own layouts
// (chapters/ch06_defocus/random_spheres.h). The expected numbers were printed by the book's own
// code (RayTracing/raytracing.github.io, v4.0.0-alpha.1 sources, src/InOneWeekend/main.cc and
// src/TheNextWeek/main.cc scene 1), built with g++ 12 -O2 on x86-64, with a print in the sphere
// and material constructors. A layout from another generator, from x drawn before z, or with
// the bounce drawn apart from its sphere, differs in its first small sphere already.
#include <catch2/catch.hpp>
#include <memory>

#include "book_values.h"
#include "ch06_defocus/random_spheres.h"
#include "rt/materials/dielectric.h"
#include "rt/materials/lambertian.h"
#include "rt/materials/metal.h"

TEST_CASE("random spheres: book 1's layout is the book's, sphere for sphere", "[ch06]") {
    const auto spheres = random_spheres();
    REQUIRE(spheres.size() == 487);  // the ground, 483 small ones, the three big ones
    int matte = 0, metal = 0, glass = 0;
    for (std::size_t k = 1; k + 3 < spheres.size(); ++k) {
        const auto& m = spheres[k]->surface();
        if (std::dynamic_pointer_cast<rt::lambertian>(m)) ++matte;
        if (std::dynamic_pointer_cast<rt::metal>(m)) ++metal;
        if (std::dynamic_pointer_cast<rt::dielectric>(m)) ++glass;
    }
    CHECK(matte == 392);
    CHECK(metal == 63);
    CHECK(glass == 28);

    // The first small sphere is metal; the last is matte, with the book's albedo.
    check_book_vector(spheres[1]->center(), -10.295210698945448, 0.2, -10.6450553660281);
    CHECK(std::dynamic_pointer_cast<rt::metal>(spheres[1]->surface()));
    check_book_vector(spheres[483]->center(), 10.547971142642201, 0.2, 10.416230813739821);
    const auto last = std::dynamic_pointer_cast<rt::lambertian>(spheres[483]->surface());
    REQUIRE(last);
    check_book_vector(last->albedo(), 0.0019927751580631802, 0.38925773163881977,
                      0.17954751492354906);
}
