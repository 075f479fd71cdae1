// Tests of the scene file writer (chapter 19): numbers written so that they read back exactly,
// every built-in scene written, read and written again to the same text, sharing kept, and what
// the format cannot say refused. (That the file renders the compiled scene's image byte for
// byte is the CTest entries scene_file_round_trip_*, through the chapter's program.)
#include <toml++/toml.h>

#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <random>
#include <set>
#include <string>

#include "ch19_scene_files/built_in_scenes.h"
#include "rt/core/error.h"
#include "rt/geometry/sphere.h"
#include "rt/geometry/triangle_mesh.h"
#include "rt/materials/lambertian.h"
#include "rt/program/asset_path.h"
#include "rt/scene/hittable_list.h"
#include "rt/scene_files/scene_reader.h"
#include "rt/scene_files/scene_writer.h"

namespace {

namespace fs = std::filesystem;

// The double a TOML reader makes of the text.
double read_back(const std::string& text) {
    const toml::table t = toml::parse("x = " + text);
    if (const auto* i = t["x"].as_integer()) return double(i->get());
    return t["x"].as_floating_point()->get();
}

}  // namespace

TEST_CASE("numbers are written so that they read back as the very same double", "[ch19]") {
    for (double x : {0.0, -0.0, 1.0, -1.0, 0.1, 1.0 / 3, 16.0 / 9, 1e-300, 4.9e-324, 1e300,
                     9007199254740991.0, 9007199254740992.0, 9007199254740993.0 * 3, 1e22,
                     std::numeric_limits<double>::max(), -std::numeric_limits<double>::min()}) {
        INFO(x << " written " << rt::number_text(x));
        const double y = read_back(rt::number_text(x));
        CHECK(std::bit_cast<std::uint64_t>(y) == std::bit_cast<std::uint64_t>(x));
    }
    // Any finite double, by its bits.
    std::mt19937_64 bits(19);
    int checked = 0;
    while (checked < 20000) {
        const double x = std::bit_cast<double>(bits());
        if (!std::isfinite(x)) continue;
        ++checked;
        const double y = read_back(rt::number_text(x));
        if (std::bit_cast<std::uint64_t>(y) != std::bit_cast<std::uint64_t>(x))
            FAIL(x << " written " << rt::number_text(x) << " read back as " << y);
    }
    CHECK(rt::number_text(1000) == "1000");  // whole numbers as a person writes them
    CHECK(rt::number_text(0.5) == "0.5");
    CHECK(rt::number_text(-0.0) == "-0.0");
}

TEST_CASE("every built-in scene, written and read, is written again to the same text", "[ch19]") {
    const std::string texture = rt::asset_path("globe.png");
    const std::string folder  = fs::path(rt::asset_path("scenes")).string();
    for (const std::string& name : built_in_names()) {
        INFO(name);
        const rt::described_scene built = built_in_scene(name, texture);
        const std::string text          = rt::scene_file_text(built, folder, name);
        const rt::described_scene read  = rt::parse_scene_text(text, name + ".toml", folder);
        CHECK(rt::scene_file_text(read, folder, name) == text);
        CHECK(read.integrator == built.integrator);
        CHECK(read.scene.settings.make_sampler == built.scene.settings.make_sampler);
    }
}

TEST_CASE("an object held twice is written once, as a named object, and read back shared",
          "[ch19]") {
    auto mat   = std::make_shared<rt::lambertian>(rt::color(0.5, 0.5, 0.5));
    auto ball  = std::make_shared<rt::sphere>(rt::point3(0, 0, 0), 1, mat);
    auto world = std::make_shared<rt::hittable_list>();
    world->add(ball);
    world->add(ball);
    rt::described_scene d;
    d.scene.world          = world;
    const std::string text = rt::scene_file_text(d, "", "shared");
    CHECK_THAT(text, Catch::Contains("[named_objects.object1]"));
    const rt::described_scene read = rt::parse_scene_text(text, "shared.toml", "");
    const auto* list               = dynamic_cast<const rt::hittable_list*>(read.scene.world.get());
    REQUIRE(list != nullptr);
    REQUIRE(list->objects.size() == 2);
    CHECK(list->objects[0] == list->objects[1]);
}

TEST_CASE("a mesh made in code names no model file: refused", "[ch19]") {
    rt::mesh_data data;
    data.positions = {rt::point3(0, 0, 0), rt::point3(1, 0, 0), rt::point3(0, 1, 0)};
    data.triangles = {{0, 1, 2}};
    auto world     = std::make_shared<rt::hittable_list>();
    world->add(rt::mesh_object(std::move(data),
                               std::make_shared<rt::lambertian>(rt::color(0.5, 0.5, 0.5))));
    rt::described_scene d;
    d.scene.world = world;
    CHECK_THROWS_AS(rt::scene_file_text(d, "", "mesh"), rt::user_error);
}

TEST_CASE("a file that cannot be written is named, and nothing is left", "[ch19]") {
    rt::described_scene d;
    const std::string path = (fs::temp_directory_path() / "no_such_folder" / "x.toml").string();
    CHECK_THROWS_WITH(rt::write_scene_file(d, path, "x"), Catch::Contains(path));
    CHECK_FALSE(fs::exists(path));
}

TEST_CASE("assets/scenes/book holds one file for each built-in scene, and no other", "[ch19]") {
    const fs::path folder = fs::path(rt::asset_path("scenes")) / "book";
    std::set<std::string> files, names;
    for (const auto& entry : fs::directory_iterator(folder))
        if (entry.path().extension() == ".toml") files.insert(entry.path().stem().string());
    for (const std::string& name : built_in_names()) names.insert(name);
    CHECK(files == names);  // tools/make-scene-files writes them
}
