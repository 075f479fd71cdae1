// Chapter 18's scenes: a model from a file in book 3's Cornell box, where book 3's glass sphere
// stood (its tall box stays), as a white diffuse object, as glass, and as a light; smooth or
// flat.
#pragma once

#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "ch11_instances/cornell_box.h"
#include "rt/geometry/triangle_mesh.h"
#include "rt/materials/dielectric.h"
#include "rt/materials/diffuse_light.h"
#include "rt/materials/lambertian.h"
#include "rt/models/model_fit.h"
#include "rt/models/obj_model.h"
#include "rt/models/vertex_normals.h"

// The kinds of model the chapter shows.
enum class model_look { white, glass, light };

// Smooth: the file's vertex normals, or normals averaged from the triangles where it has none.
// Flat: the triangles' own normals, facets and all.
enum class model_shading { smooth, flat };

// The model in book 3's Cornell box: 180 units tall, standing where the glass sphere did. Its
// warnings (materials ignored, degenerate triangles dropped) go to stderr, one line each.
inline rt::scene model_in_cornell_box(const std::string& model_file, model_look look,
                                      model_shading shading = model_shading::smooth) {
    using rt::color, rt::point3, rt::vec3;
    cornell_room room =
        empty_cornell_room({point3(343, 554, 332), vec3(-130, 0, 0), vec3(0, 0, -105), 15});
    auto objects = room.walls;
    objects.emplace_back(placed_box(vec3(165, 330, 165), 15, vec3(265, 0, 295), room.white));
    std::shared_ptr<rt::material> surface;
    if (look == model_look::white) surface = room.white;
    if (look == model_look::glass) surface = std::make_shared<rt::dielectric>(1.5);
    if (look == model_look::light) surface = std::make_shared<rt::diffuse_light>(color(4, 3, 1.5));
    rt::obj_model model = rt::read_obj(model_file);
    if (shading == model_shading::flat) model.mesh.normals.clear();
    if (shading == model_shading::smooth && model.mesh.normals.empty())
        rt::add_smooth_normals(model.mesh);
    model.mesh = rt::fitted(std::move(model.mesh), point3(190, 0, 190), 180);
    std::vector<std::string> warnings;
    auto mesh = rt::mesh_of_model(std::move(model), surface, model_file, warnings);
    for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
    objects.emplace_back(rt::mesh_object(mesh));
    rt::scene scene                  = cornell_scene(objects);
    scene.settings.samples_per_pixel = 100;
    return scene;
}
