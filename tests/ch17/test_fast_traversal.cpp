// Tests for fast_traversal.h (chapter 17): every earlier chapter's scene, its world rewritten with
// wide BVHs, answers every ray as the world it came from, record for record, transmittance for
// transmittance, and finds the same lights in the same order; and the rewrite shares what it does
// not change.
#include <catch2/catch.hpp>
#include <memory>
#include <string>
#include <vector>

#include "ch03/material_helpers.h"
#include "ch14_importance_sampling/scene_catalog.h"
#include "rt/accel/bvh.h"
#include "rt/accel/fast_traversal.h"
#include "rt/accel/wide_bvh.h"
#include "rt/core/rng.h"
#include "rt/geometry/box.h"
#include "rt/geometry/instance.h"
#include "rt/lights/light_set.h"
#include "rt/render/film.h"
#include "rt/samplers/independent_sampler.h"
#include "rt/scene/hittable_list.h"
#include "test_helpers.h"

namespace {

using rt::interval, rt::point3, rt::real, rt::vec3;
using rt_test::any_material, rt_test::exactly, rt_test::random_unit;

// Every object the world holds directly or through lists and BVHs, in the order they are shown.
struct collector : rt::part_visitor {
    std::vector<const rt::hittable*> parts;
    void visit(const rt::hittable& part) override {
        parts.push_back(&part);
        part.visit_parts(*this);
    }
};

}  // namespace

TEST_CASE("fast_traversal: every catalog scene answers every ray as it did before the rewrite",
          "[ch17]") {
    // A 2 x 1 texture for the globes: a blue and a green texel.
    rt_test::temp_folder folder("fast_traversal", "catalog");
    const std::string texture = folder.file("texture.png");
    rt::image img(2, 1);
    img.set(0, 0, rt::color(0.1, 0.2, 0.8));
    img.set(1, 0, rt::color(0.1, 0.7, 0.2));
    rt_test::write_image_file(texture, img);
    for (const catalog_scene& entry : catalog_scenes()) {
        INFO("scene " << entry.name);
        const rt::scene before = entry.build(texture);
        const rt::scene after  = rt::with_fast_traversal(before);
        CHECK(after.cam == before.cam);
        CHECK(after.settings.samples_per_pixel == before.settings.samples_per_pixel);

        // Camera rays, each followed through up to 8 hits in random directions from where it
        // hit: rays from outside, from surfaces and from inside objects.
        const rt::film f = rt::film::for_aspect(24, before.cam->aspect_ratio);
        before.cam->initialize(f);
        rt::independent_sampler s(5);
        rt::pcg32 rng(34, 7);
        long long segments = 0, hits = 0, differ = 0;
        for (int j = 0; j < f.height; ++j) {
            for (int i = 0; i < f.width; ++i) {
                s.start_pixel_sample(i, j, 0);
                rt::ray r = before.cam->get_ray(i, j, s);
                for (int k = 0; k < 8; ++k, ++segments) {
                    rt::hit_record a, b;
                    const bool hit_before = before.world->hit(r, interval(0, rt::infinity), a);
                    const bool hit_after  = after.world->hit(r, interval(0, rt::infinity), b);
                    const real t_before   = before.world->transmittance(r, interval(0, 1e4));
                    const real t_after    = after.world->transmittance(r, interval(0, 1e4));
                    if (hit_before != hit_after || t_before != t_after) ++differ;
                    if (!hit_before || !hit_after) break;
                    ++hits;
                    if (a.t != b.t || !exactly(a.p, b.p) || a.p_error != b.p_error ||
                        !exactly(a.normal, b.normal) || a.front_face != b.front_face ||
                        a.mat != b.mat || a.object != b.object || !exactly(a.local, b.local))
                        ++differ;
                    r = r.continued(a.p, random_unit(rng));
                }
            }
        }
        INFO(segments << " segments, " << hits << " hits");
        CHECK(differ == 0);
        CHECK(hits > 0);

        // The same parts, in the same order, down to the shapes: the lights found are the same.
        collector parts_before, parts_after;
        parts_before.visit(*before.world);
        parts_after.visit(*after.world);
        std::vector<const rt::hittable*> shapes_before, shapes_after;
        for (const auto* p : parts_before.parts)
            if (dynamic_cast<const rt::bvh*>(p) == nullptr &&
                dynamic_cast<const rt::hittable_list*>(p) == nullptr)
                shapes_before.push_back(p);
        for (const auto* p : parts_after.parts)
            if (dynamic_cast<const rt::wide_bvh*>(p) == nullptr &&
                dynamic_cast<const rt::hittable_list*>(p) == nullptr)
                shapes_after.push_back(p);
        // Instances are placed again (new objects); shapes, media and what else the world holds
        // are shared, so compare the kinds where instances stand and the objects elsewhere.
        REQUIRE(shapes_before.size() == shapes_after.size());
        for (std::size_t k = 0; k < shapes_before.size(); ++k) {
            const bool instance = dynamic_cast<const rt::translate*>(shapes_before[k]) ||
                                  dynamic_cast<const rt::rotate*>(shapes_before[k]);
            if (instance)
                CHECK(typeid(*shapes_before[k]) == typeid(*shapes_after[k]));
            else
                CHECK(shapes_before[k] == shapes_after[k]);
        }
        const rt::light_set lights_before(*before.world, before.sky);
        const rt::light_set lights_after(*after.world, after.sky);
        CHECK(lights_before.size() == lights_after.size());
    }
}

TEST_CASE("fast_traversal: what holds no bvh is shared, and what is placed twice stays one",
          "[ch17]") {
    auto ball = std::make_shared<rt::sphere>(point3(0, 0, 0), 1, any_material());
    CHECK(rt::with_wide_bvhs(ball) == ball);
    auto list = std::make_shared<rt::hittable_list>();
    list->add(ball);
    CHECK(rt::with_wide_bvhs(list) == list);
    CHECK(rt::with_wide_bvhs(nullptr) == nullptr);

    // One box (a bvh of six faces) placed by two instances, and both in a list: the rewritten
    // instances hold one wide_bvh, with the same boxes as before.
    auto box   = rt::box(point3(0, 0, 0), point3(1, 2, 3), any_material());
    auto left  = std::make_shared<rt::translate>(box, vec3(-5, 0, 0));
    auto right = std::make_shared<rt::rotate>(box, rt::axis::z, 30);
    auto world = std::make_shared<rt::hittable_list>();
    world->add(left);
    world->add(right);
    world->add(ball);
    auto packed = std::dynamic_pointer_cast<rt::hittable_list>(rt::with_wide_bvhs(world));
    REQUIRE(packed);
    REQUIRE(packed->objects.size() == 3);
    CHECK(packed->objects[2] == ball);
    auto new_left  = std::dynamic_pointer_cast<rt::translate>(packed->objects[0]);
    auto new_right = std::dynamic_pointer_cast<rt::rotate>(packed->objects[1]);
    REQUIRE(new_left);
    REQUIRE(new_right);
    CHECK(new_left->placed() == new_right->placed());
    CHECK(dynamic_cast<const rt::wide_bvh*>(new_left->placed().get()) != nullptr);
    CHECK(new_left->displacement().x() == -5);
    CHECK(new_right->degrees() == 30);
    CHECK(new_right->turned_about() == rt::axis::z);
    for (const auto& [a, b] : {std::pair{rt::bounding_box(*left), rt::bounding_box(*new_left)},
                               std::pair{rt::bounding_box(*right), rt::bounding_box(*new_right)}}) {
        CHECK(a.x.min == b.x.min);
        CHECK(a.y.max == b.y.max);
        CHECK(a.z.min == b.z.min);
    }
}
