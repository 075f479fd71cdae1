// Book 2's final scene: every feature at once. The random box heights, the marble's Perlin
// tables and the cluster's sphere positions are the book's own (final_layout.h).
#pragma once

#include <memory>
#include <string>

#include "final_layout.h"
#include "rt/accel/bvh.h"
#include "rt/camera/thin_lens_camera.h"
#include "rt/geometry/box.h"
#include "rt/geometry/instance.h"
#include "rt/geometry/moving_sphere.h"
#include "rt/geometry/quad.h"
#include "rt/geometry/sphere.h"
#include "rt/materials/dielectric.h"
#include "rt/materials/diffuse_light.h"
#include "rt/materials/lambertian.h"
#include "rt/materials/metal.h"
#include "rt/materials/textured_lambertian.h"
#include "rt/media/constant_medium.h"
#include "rt/scene/scene.h"
#include "rt/textures/image_texture.h"
#include "rt/textures/noise_texture.h"

inline rt::scene book2_final_scene(const std::string& globe_texture) {
    using rt::color, rt::point3, rt::vec3;
    book2_final_layout layout = book2_final_draws();
    std::vector<rt::bounded_object> objects;

    // Ground: 20 x 20 boxes of random height; their faces go straight into the BVH.
    auto ground = std::make_shared<rt::lambertian>(color(0.48, 0.83, 0.53));
    for (int i = 0; i < 20; ++i) {
        for (int j = 0; j < 20; ++j) {
            double x0 = -1000.0 + i * 100.0, z0 = -1000.0 + j * 100.0;
            double y1  = layout.box_heights[std::size_t(i * 20 + j)];
            auto faces = rt::box_faces(point3(x0, 0, z0), point3(x0 + 100, y1, z0 + 100), ground);
            objects.insert(objects.end(), faces.begin(), faces.end());
        }
    }

    auto light = std::make_shared<rt::diffuse_light>(color(7, 7, 7));
    objects.push_back(
        std::make_shared<rt::quad>(point3(123, 554, 147), vec3(300, 0, 0), vec3(0, 0, 265), light));

    // A sphere moving 30 units during the shutter, glass, brushed metal.
    objects.push_back(std::make_shared<rt::moving_sphere>(
        point3(400, 400, 200), point3(430, 400, 200), 50,
        std::make_shared<rt::lambertian>(color(0.7, 0.3, 0.1))));
    objects.push_back(std::make_shared<rt::sphere>(point3(260, 150, 45), 50,
                                                   std::make_shared<rt::dielectric>(1.5)));
    objects.push_back(std::make_shared<rt::sphere>(
        point3(0, 150, 145), 50, std::make_shared<rt::metal>(color(0.8, 0.8, 0.9), 1.0)));

    // Subsurface look: a glass sphere filled with a blue medium.
    auto glass_ball = std::make_shared<rt::sphere>(point3(360, 150, 145), 70,
                                                   std::make_shared<rt::dielectric>(1.5));
    objects.push_back(glass_ball);
    objects.push_back(std::make_shared<rt::constant_medium>(glass_ball, 0.2, color(0.2, 0.4, 0.9)));

    // A thin mist over everything: a medium inside a sphere of radius 5000 (no surface).
    auto mist_boundary =
        std::make_shared<rt::sphere>(point3(0, 0, 0), 5000, std::make_shared<rt::dielectric>(1.5));
    objects.push_back(std::make_shared<rt::constant_medium>(mist_boundary, 0.0001, color(1, 1, 1)));

    // The globe and a marble sphere.
    objects.push_back(
        std::make_shared<rt::sphere>(point3(400, 200, 400), 100,
                                     std::make_shared<rt::textured_lambertian>(
                                         std::make_shared<rt::image_texture>(globe_texture))));
    objects.push_back(std::make_shared<rt::sphere>(
        point3(220, 280, 300), 80,
        std::make_shared<rt::textured_lambertian>(
            std::make_shared<rt::noise_texture>(0.1, layout.marble_draws))));

    // A cluster of 1000 small spheres in its own BVH, turned and moved as one instance.
    auto white = std::make_shared<rt::lambertian>(color(0.73, 0.73, 0.73));
    std::vector<rt::bounded_object> cluster;
    for (const point3& center : layout.cluster)
        cluster.push_back(std::make_shared<rt::sphere>(center, 10, white));
    objects.push_back(std::make_shared<rt::translate>(
        std::make_shared<rt::rotate>(std::make_shared<rt::bvh>(cluster), rt::axis::y, 15),
        vec3(-100, 270, 395)));

    auto cam           = std::make_shared<rt::thin_lens_camera>();
    cam->aspect_ratio  = 1;
    cam->vfov          = 40;
    cam->lookfrom      = point3(478, 278, -600);
    cam->lookat        = point3(278, 278, 0);
    cam->shutter_close = 1;  // the moving sphere blurs

    rt::scene scene;
    scene.world = std::make_shared<rt::bvh>(objects);
    scene.sky   = rt::background::uniform(color(0, 0, 0));
    scene.cam   = cam;
    // The book's default run, final_scene(400, 250, 4); its "real" run is 800 wide, 10000 spp,
    // depth 40.
    scene.settings = {.width = 400, .samples_per_pixel = 250, .max_depth = 4};
    return scene;
}
