// Book 1's final scene: about 480 small spheres of the three materials on a grid, three big
// ones, on a huge ground sphere. The small spheres' placement and materials come from a PCG32
// with a fixed seed, so the scene is the same on every run and for every --seed (which only
// changes the render's noise); it is statistically like the book's, not identical to it.
// Chapter 07 reuses it as book 2's "bouncing spheres", where the diffuse spheres move.
#pragma once

#include <memory>
#include <vector>

#include "rt/core/rng.h"
#include "rt/geometry/sphere.h"
#include "rt/materials/dielectric.h"
#include "rt/materials/lambertian.h"
#include "rt/materials/metal.h"

inline std::vector<std::shared_ptr<rt::sphere>> random_spheres() {
    using rt::color, rt::point3, rt::vec3;
    rt::pcg32 rng(/*sequence=*/1, /*seed=*/2024);
    auto random_color = [&](double lo, double hi) {
        auto r     = [&] { return lo + (hi - lo) * rng.uniform(); };
        double red = r(), green = r();
        return color(red, green, r());
    };

    std::vector<std::shared_ptr<rt::sphere>> world;
    auto add = [&](point3 center, double radius, std::shared_ptr<rt::material> mat) {
        world.push_back(std::make_shared<rt::sphere>(center, radius, std::move(mat)));
    };
    add(point3(0, -1000, 0), 1000, std::make_shared<rt::lambertian>(color(0.5, 0.5, 0.5)));
    for (int a = -11; a < 11; ++a) {
        for (int b = -11; b < 11; ++b) {
            double choose = rng.uniform();
            double dx = rng.uniform(), dz = rng.uniform();
            point3 center(a + 0.9 * dx, 0.2, b + 0.9 * dz);
            if ((center - point3(4, 0.2, 0)).length() <= 0.9) continue;

            if (choose < 0.8) {  // diffuse, albedo = random * random per channel
                add(center, 0.2,
                    std::make_shared<rt::lambertian>(random_color(0, 1) * random_color(0, 1)));
            } else if (choose < 0.95) {  // metal
                add(center, 0.2,
                    std::make_shared<rt::metal>(random_color(0.5, 1), 0.5 * rng.uniform()));
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
