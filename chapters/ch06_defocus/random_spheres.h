// Book 1's final scene: about 480 small spheres of the three materials on a grid, three big
// ones, on a huge ground sphere. The small spheres' places and materials are the book's own:
// drawn from the book's random numbers (rt/core/book_random.h: glibc's rand() from its default
// seed, in the order the book's code, compiled by g++, calls it), so the scene is the book's
// image, the same on every run and for every --seed (which only changes the render's noise).
// Chapter 07 reuses the layout as book 2's bouncing spheres, where the matte spheres move up:
// book 2 draws each one's rise right after its colour, so from the first matte sphere on its
// layout is another than book 1's.
#pragma once

#include <memory>
#include <vector>

#include "rt/core/book_random.h"
#include "rt/geometry/sphere.h"
#include "rt/materials/dielectric.h"
#include "rt/materials/lambertian.h"
#include "rt/materials/metal.h"

// One sphere of the layout, and how far it rises while the shutter is open (book 2's bouncing
// matte spheres; 0 for every other sphere).
struct laid_out_sphere {
    std::shared_ptr<rt::sphere> sphere;
    double rise = 0;
};

// Book 1's layout (bouncing = false), or book 2's bouncing spheres (bouncing = true).
inline std::vector<laid_out_sphere> random_sphere_layout(bool bouncing) {
    using rt::color, rt::point3;
    rt::book_random draws;
    std::vector<laid_out_sphere> world;
    auto add = [&](point3 center, double radius, std::shared_ptr<rt::material> mat,
                   double rise = 0) {
        world.push_back({std::make_shared<rt::sphere>(center, radius, std::move(mat)), rise});
    };
    add(point3(0, -1000, 0), 1000, std::make_shared<rt::lambertian>(color(0.5, 0.5, 0.5)));
    for (int a = -11; a < 11; ++a) {
        for (int b = -11; b < 11; ++b) {
            const double choose = draws.uniform();
            // point3(a + 0.9*random_double(), 0.2, b + 0.9*random_double()): z is drawn first.
            const double dz = draws.uniform(), dx = draws.uniform();
            const point3 center(a + 0.9 * dx, 0.2, b + 0.9 * dz);
            if ((center - point3(4, 0.2, 0)).length() <= 0.9) continue;

            if (choose < 0.8) {  // diffuse, albedo = random() * random() per channel
                const rt::vec3 albedo = draws.vector(0, 1) * draws.vector(0, 1);
                const double rise     = bouncing ? draws.uniform(0, 0.5) : 0;
                add(center, 0.2, std::make_shared<rt::lambertian>(albedo), rise);
            } else if (choose < 0.95) {  // metal
                const rt::vec3 albedo = draws.vector(0.5, 1);
                add(center, 0.2, std::make_shared<rt::metal>(albedo, draws.uniform(0, 0.5)));
            } else {  // glass
                add(center, 0.2, std::make_shared<rt::dielectric>(1.5));
            }
        }
    }
    add(point3(0, 1, 0), 1.0, std::make_shared<rt::dielectric>(1.5));
    add(point3(-4, 1, 0), 1.0, std::make_shared<rt::lambertian>(color(0.4, 0.2, 0.1)));
    add(point3(4, 1, 0), 1.0, std::make_shared<rt::metal>(color(0.7, 0.6, 0.5), 0.0));
    return world;
}

// Book 1's final scene: its spheres, none of them moving.
inline std::vector<std::shared_ptr<rt::sphere>> random_spheres() {
    std::vector<std::shared_ptr<rt::sphere>> spheres;
    for (auto& s : random_sphere_layout(false)) spheres.push_back(std::move(s.sphere));
    return spheres;
}
