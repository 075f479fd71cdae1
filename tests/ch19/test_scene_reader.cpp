// Tests of the scene file reader (chapter 19): what each key builds, the defaults of what a file
// leaves out, names shared and reused, transforms in order, and files found beside the scene.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "rt/accel/bvh.h"
#include "rt/camera/thin_lens_camera.h"
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
#include "rt/program/asset_path.h"
#include "rt/samplers/independent_sampler.h"
#include "rt/samplers/sobol_sampler.h"
#include "rt/scene/hittable_list.h"
#include "rt/scene_files/scene_reader.h"
#include "rt/textures/image_texture.h"
#include "rt/textures/noise_texture.h"

namespace {

using rt::point3, rt::vec3, rt::real;

rt::described_scene parsed(const std::string& text, const std::string& folder = "") {
    return rt::parse_scene_text(text, "test.toml", folder);
}

// The objects of a scene whose world is a list.
const std::vector<std::shared_ptr<rt::hittable>>& listed(const rt::described_scene& d) {
    const auto* list = dynamic_cast<const rt::hittable_list*>(d.scene.world.get());
    REQUIRE(list != nullptr);
    return list->objects;
}

template <typename T>
const T& as(const std::shared_ptr<rt::hittable>& object) {
    const auto* typed = dynamic_cast<const T*>(object.get());
    REQUIRE(typed != nullptr);
    return *typed;
}

bool same(const vec3& a, const vec3& b) {
    return a.x() == b.x() && a.y() == b.y() && a.z() == b.z();
}

}  // namespace

TEST_CASE("a file with only its format is an empty scene with every default", "[ch19]") {
    const rt::described_scene d = parsed("format = 1\n");
    CHECK(listed(d).empty());
    CHECK(d.integrator == rt::integrator_kind::path);
    const rt::render_settings defaults;
    CHECK(d.scene.settings.width == defaults.width);
    CHECK(d.scene.settings.samples_per_pixel == defaults.samples_per_pixel);
    CHECK(d.scene.settings.max_depth == defaults.max_depth);
    CHECK(d.scene.settings.make_sampler == rt::independent_sampler::make);
    CHECK(same(d.scene.sky.top, rt::background::sky().top));
    CHECK(same(d.scene.sky.bottom, rt::background::sky().bottom));
}

TEST_CASE("render settings, camera and sky are read as written", "[ch19]") {
    const rt::described_scene d = parsed(R"(
format = 1
[render]
width = 320
samples_per_pixel = 7
max_depth = 9
seed = 42
integrator = "mis"
sampler = "sobol"
[camera]
type = "look-at"
aspect_ratio = "16:9"
vfov = 20
lookfrom = [13, 2, 3]
lookat = [0, 0, 0]
vup = [0, 1, 0]
aperture = 0.6
focus_distance = 10
shutter = [0, 1]
[sky]
color = [0.25, 0.5, 1]
)");
    CHECK(d.scene.settings.width == 320);
    CHECK(d.scene.settings.samples_per_pixel == 7);
    CHECK(d.scene.settings.max_depth == 9);
    CHECK(d.scene.settings.seed == 42);
    CHECK(d.integrator == rt::integrator_kind::mis);
    CHECK(d.scene.settings.make_sampler == rt::sobol_sampler::make);
    const auto* cam = dynamic_cast<const rt::thin_lens_camera*>(d.scene.cam.get());
    REQUIRE(cam != nullptr);
    CHECK(cam->aspect_ratio == 16.0 / 9);  // "16:9" is the code's own 16.0 / 9, exactly
    CHECK(cam->vfov == 20);
    CHECK(same(cam->lookfrom, point3(13, 2, 3)));
    CHECK(cam->aperture == real(0.6));
    CHECK(cam->focus_dist == 10);
    CHECK(cam->shutter_open == 0);
    CHECK(cam->shutter_close == 1);
    CHECK(same(d.scene.sky.top, vec3(0.25, 0.5, 1)));
    CHECK(same(d.scene.sky.bottom, vec3(0.25, 0.5, 1)));
}

TEST_CASE("the origin camera is chapter 01's, not a lens camera", "[ch19]") {
    const rt::described_scene d =
        parsed("format = 1\n[camera]\ntype = \"origin\"\naspect_ratio = 2\nvfov = 90\n");
    CHECK(dynamic_cast<const rt::thin_lens_camera*>(d.scene.cam.get()) == nullptr);
    CHECK(d.scene.cam->aspect_ratio == 2);
}

TEST_CASE("each kind of object is built with its numbers and material", "[ch19]") {
    const rt::described_scene d = parsed(R"(
format = 1
[materials]
matte = { type = "lambertian", albedo = [0.5, 0.5, 0.5] }
gold = { type = "metal", albedo = [0.8, 0.6, 0.2], fuzz = 0.3 }
glass = { type = "dielectric", index = 1.5, fresnel = "exact" }
lamp = { type = "light", emit = [4, 4, 4] }
[world]
objects = [
  { type = "sphere", center = [0, -1000, 0], radius = 1000, material = "matte" },
  { type = "moving-sphere", centers = [[1, 0.2, 1], [1, 0.5, 1]], radius = 0.2, material = "gold" },
  { type = "quad", corner = [-3, -2, 5], u = [0, 0, -4], v = [0, 4, 0], material = "lamp" },
  { type = "sphere", center = [0, 1, 0], radius = 1, material = "glass" },
  { type = "sphere", center = [0, 0, -1], radius = 0.5 },
]
)");
    const auto& objects         = listed(d);
    REQUIRE(objects.size() == 5);
    const auto& ground = as<rt::sphere>(objects[0]);
    CHECK(same(ground.center(), point3(0, -1000, 0)));
    CHECK(ground.radius() == 1000);
    CHECK(dynamic_cast<const rt::lambertian*>(ground.surface().get())->albedo().x() == real(0.5));
    const auto& moving = as<rt::moving_sphere>(objects[1]);
    CHECK(same(moving.path().center1, point3(1, 0.5, 1)));
    const auto* gold = dynamic_cast<const rt::metal*>(moving.surface().get());
    REQUIRE(gold != nullptr);
    CHECK(gold->fuzziness() == real(0.3));
    const auto& face = as<rt::quad>(objects[2]);
    CHECK(same(face.edge_u(), vec3(0, 0, -4)));
    CHECK(dynamic_cast<const rt::diffuse_light*>(face.surface().get()) != nullptr);
    const auto* glass =
        dynamic_cast<const rt::dielectric*>(as<rt::sphere>(objects[3]).surface().get());
    REQUIRE(glass != nullptr);
    CHECK(glass->fresnel() == rt::fresnel_model::exact);
    CHECK(as<rt::sphere>(objects[4]).surface() == nullptr);  // chapter 02's: normals only
}

TEST_CASE("a named material is one material wherever it is used", "[ch19]") {
    const rt::described_scene d = parsed(R"(
format = 1
[materials]
matte = { type = "lambertian", albedo = [0.5, 0.5, 0.5] }
[world]
objects = [
  { type = "sphere", center = [0, 0, 0], radius = 1, material = "matte" },
  { type = "sphere", center = [3, 0, 0], radius = 1, material = "matte" },
  { type = "sphere", center = [6, 0, 0], radius = 1, material = { type = "metal", albedo = [1, 1, 1] } },
]
)");
    const auto& objects         = listed(d);
    CHECK(as<rt::sphere>(objects[0]).surface() == as<rt::sphere>(objects[1]).surface());
    CHECK(dynamic_cast<const rt::metal*>(as<rt::sphere>(objects[2]).surface().get()) != nullptr);
}

TEST_CASE("textures: colours, checkers of textures, marble tables from the book's stream",
          "[ch19]") {
    const rt::described_scene d = parsed(R"(
format = 1
[textures]
white = { type = "color", color = [0.9, 0.9, 0.9] }
board = { type = "checker", scale = 0.32, even = [0.2, 0.3, 0.1], odd = "white" }
stone = { type = "marble", scale = 4, perlin_seed = 7, perlin_skip = 25 }
[world]
objects = [
  { type = "sphere", center = [0, 0, 0], radius = 1, material = { type = "lambertian", albedo = "board" } },
  { type = "sphere", center = [3, 0, 0], radius = 1, material = { type = "lambertian", albedo = "stone" } },
]
)");
    const auto& objects         = listed(d);
    const auto* board =
        dynamic_cast<const rt::textured_lambertian*>(as<rt::sphere>(objects[0]).surface().get());
    REQUIRE(board != nullptr);
    const auto* checker = dynamic_cast<const rt::checker_texture*>(board->albedo_texture().get());
    REQUIRE(checker != nullptr);
    CHECK(checker->scale() == real(0.32));
    const auto* odd = dynamic_cast<const rt::solid_color*>(checker->odd_texture().get());
    REQUIRE(odd != nullptr);
    CHECK(odd->color_value().x() == real(0.9));
    const auto* stone =
        dynamic_cast<const rt::textured_lambertian*>(as<rt::sphere>(objects[1]).surface().get());
    const auto* marble = dynamic_cast<const rt::noise_texture*>(stone->albedo_texture().get());
    REQUIRE(marble != nullptr);
    CHECK(marble->tables().table_seed() == 7);
    CHECK(marble->tables().table_skip() == 25);
    // The same tables as the book's stream srand(7) after 25 draws gives.
    rt::book_random draws(7);
    draws.skip(25);
    const rt::noise_texture expected(4, draws);
    for (const point3 p : {point3(0.3, 1.7, -2.2), point3(10.5, -3.25, 0.125)})
        CHECK(marble->value(0, 0, p).x() == expected.value(0, 0, p).x());
}

TEST_CASE("a group builds a list or a BVH, and transform steps apply in order", "[ch19]") {
    const rt::described_scene d = parsed(R"(
format = 1
[materials]
white = { type = "lambertian", albedo = [0.73, 0.73, 0.73] }
[named_objects.block]
type = "box"
corners = [[0, 0, 0], [165, 330, 165]]
material = "white"
[world]
bvh = true
objects = [
  { use = "block", transform = [{ rotate = "y", degrees = 15 }, { translate = [265, 0, 295] }] },
  { use = "block" },
  { type = "group", bvh = true, objects = [{ type = "sphere", center = [0, 0, 0], radius = 1, material = "white" }] },
]
)");
    const auto* tree            = dynamic_cast<const rt::bvh*>(d.scene.world.get());
    REQUIRE(tree != nullptr);
    const auto given = tree->objects_as_given();
    REQUIRE(given.size() == 3);
    // rotate, then translate: the outer object is the translation.
    const auto& moved  = as<rt::translate>(given[0]);
    const auto& turned = as<rt::rotate>(moved.placed());
    CHECK(same(moved.displacement(), vec3(265, 0, 295)));
    CHECK(turned.degrees() == 15);
    CHECK(turned.turned_about() == rt::axis::y);
    // The named box is one object, used twice.
    CHECK(turned.placed() == given[1]);
    CHECK(dynamic_cast<const rt::bvh*>(given[2].get()) != nullptr);
}

TEST_CASE("a medium fills its boundary with the density and albedo given", "[ch19]") {
    const rt::described_scene d = parsed(R"(
format = 1
[world]
objects = [
  { type = "medium", density = 0.01, albedo = [0, 0, 0], boundary = { type = "box", corners = [[0, 0, 0], [1, 1, 1]], material = { type = "lambertian", albedo = [1, 1, 1] } } },
]
)");
    const auto& fog             = as<rt::constant_medium>(listed(d)[0]);
    CHECK(fog.density() == real(0.01));
}

TEST_CASE("texture and model files are found relative to the scene file's folder", "[ch19]") {
    const std::filesystem::path assets =
        std::filesystem::path(rt::asset_path("globe.png")).parent_path();
    const rt::described_scene d = parsed(R"(
format = 1
[world]
objects = [
  { type = "sphere", center = [0, 0, 0], radius = 2, material = { type = "lambertian", albedo = { type = "image", file = "globe.png" } } },
  { type = "mesh", file = "models/bunny.obj", material = { type = "lambertian", albedo = [0.5, 0.5, 0.5] }, fit = { base = [0, 0, 0], height = 1 } },
]
)",
                                         assets.string());
    const auto* globe =
        dynamic_cast<const rt::textured_lambertian*>(as<rt::sphere>(listed(d)[0]).surface().get());
    REQUIRE(globe != nullptr);
    const auto* image = dynamic_cast<const rt::image_texture*>(globe->albedo_texture().get());
    REQUIRE(image != nullptr);
    CHECK(image->width() > 0);
    const auto& bunny = as<rt::bvh>(listed(d)[1]);
    CHECK(bunny.object_count() == 3674);                         // the committed bunny's triangles
    CHECK(std::fabs(bunny.bounding_box().y.size() - 1) < 1e-4);  // fitted to height 1
}

TEST_CASE("read_scene_file reads the chapter's own scene file", "[ch19]") {
    const rt::described_scene d =
        rt::read_scene_file(rt::asset_path("scenes/cornell_box_my_way.toml"));
    CHECK(d.integrator == rt::integrator_kind::mis);
    CHECK(d.scene.settings.make_sampler == rt::sobol_sampler::make);
    CHECK(dynamic_cast<const rt::bvh*>(d.scene.world.get())->objects_as_given().size() == 8);
}

TEST_CASE("comments, strings and quoted names may hold any UTF-8 text", "[ch19]") {
    const rt::described_scene d = parsed(R"(# Scène de la classe : la boîte de Cornell — 日本
format = 1
[materials]
"rouge écarlate" = { type = "lambertian", albedo = [0.65, 0.05, 0.05] }  # §
[world]
objects = [{ type = "sphere", center = [0, 0, 0], radius = 1, material = "rouge écarlate" }]
)");
    CHECK(as<rt::sphere>(listed(d)[0]).surface() != nullptr);
}
