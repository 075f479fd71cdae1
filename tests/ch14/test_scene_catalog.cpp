// Tests for chapters/ch14_importance_sampling/scene_catalog.h: every earlier chapter's scene is
// reachable by name, in chapter order, with its chapter's defaults, and a name that is not in
// the catalog is refused with a message that names it. The globes get a tiny texture written
// into a temporary folder, so the test needs no asset on disk.
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "ch14_importance_sampling/scene_catalog.h"
#include "rt/accel/bvh.h"
#include "rt/core/error.h"
#include "rt/core/interval.h"
#include "rt/image/image.h"
#include "rt/image/image_io.h"
#include "rt/render/film.h"
#include "rt/samplers/independent_sampler.h"
#include "rt/scene/hittable_list.h"
#include "test_helpers.h"

namespace {

using rt_test::temp_folder;

// A 2 x 1 texture: a blue and a green texel.
std::string write_texture(const temp_folder& folder) {
    rt::image img(2, 1);
    img.set(0, 0, rt::color(0.1, 0.2, 0.8));
    img.set(1, 0, rt::color(0.1, 0.7, 0.2));
    std::string path = folder.file("texture.png");
    rt_test::write_image_file(path, img);
    return path;
}

// The message of the user_error that scene_by_name throws, or "" (and a failed check) if none.
std::string refusal(const std::string& name) {
    try {
        scene_by_name(name, "unused.png");
    } catch (const rt::user_error& e) {
        return e.what();
    }
    FAIL_CHECK("scene_by_name accepted " << name);
    return "";
}

}  // namespace

TEST_CASE("scene_catalog: the names of chapters 03-13's scenes, in chapter order", "[ch14]") {
    const std::vector<std::string> expected = {"ch03",          "ch03-book",
                                               "ch04",          "ch05",
                                               "ch06",          "ch06-book",
                                               "ch06-final",    "ch07",
                                               "ch07-list",     "ch07-ch06-final",
                                               "ch08",          "ch08-checker",
                                               "ch08-bouncing", "ch08-two-spheres",
                                               "ch09",          "ch09-globe",
                                               "ch10",          "ch10-quads",
                                               "ch11",          "ch11-rotations",
                                               "ch12",          "ch13"};
    CHECK(scene_names() == expected);
}

TEST_CASE("scene_catalog: every name builds a scene whose camera sees its world", "[ch14]") {
    temp_folder folder("scene_catalog", "every_name");
    const std::string texture = write_texture(folder);
    int hits                  = 0;
    for (const std::string& name : scene_names()) {
        INFO("scene " << name);
        rt::scene scene = scene_by_name(name, texture);
        REQUIRE(scene.world);
        REQUIRE(scene.cam);
        CHECK(scene.settings.width > 0);
        CHECK(scene.settings.samples_per_pixel > 0);
        CHECK(scene.settings.max_depth > 0);

        // A ray from the camera through the middle of a small image: the camera accepts the
        // scene's settings, and the world answers it (a hit or the sky, never a crash).
        const rt::film f = rt::film::for_aspect(32, scene.cam->aspect_ratio);
        scene.cam->initialize(f);
        rt::independent_sampler s(1);
        s.start_pixel_sample(f.width / 2, f.height / 2, 0);
        const rt::ray r = scene.cam->get_ray(f.width / 2, f.height / 2, s);
        rt::hit_record rec;
        if (scene.world->hit(r, rt::interval(0, rt::infinity), rec)) {
            ++hits;
            CHECK(std::isfinite(rec.t));
            CHECK(rec.t > 0);
        }
    }
    // Every report scene puts something in the middle of its picture; only if the cameras all
    // looked away would none be hit.
    CHECK(hits > 0);
}

TEST_CASE("scene_catalog: a chapter's scenes differ as its flags do", "[ch14]") {
    // ch07 is the report scene in a BVH, ch07-list the same spheres in a list (--accel list).
    CHECK(std::dynamic_pointer_cast<rt::bvh>(scene_by_name("ch07", "").world));
    CHECK(std::dynamic_pointer_cast<rt::hittable_list>(scene_by_name("ch07-list", "").world));
    // ch06 is the glass scene at 400 wide (the report scene), ch06-final book 1's at 1200.
    CHECK(scene_by_name("ch06", "").settings.width == 400);
    CHECK(scene_by_name("ch06-final", "").settings.width == 1200);
}

TEST_CASE("scene_catalog: an unknown name is refused with one line that names it", "[ch14]") {
    for (const std::string name : {"moon", "ch14", "ch6", "CH03", "ch03 ", "ch06-glass", ""}) {
        INFO("name '" << name << "'");
        const std::string message = refusal(name);
        CHECK(message.ends_with(", got " + name));
        CHECK(message.find("ch03, ch03-book, ch04") !=
              std::string::npos);  // the valid names are listed
        CHECK(message.find("ch13") != std::string::npos);
        CHECK(message.find('\n') == std::string::npos);
    }
}
