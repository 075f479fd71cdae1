// Tests for light_set.h (chapter 14): the lights are found in the scene itself (quads and
// spheres with a diffuse_light material, through lists and BVHs, nested; not inside instances
// or media; not shapes that do not emit), plus the sky when it is not black. One light is chosen
// uniformly per sample, and the density it reports includes that choice: for lights that do not
// overlap it is pdf() of the direction drawn, and pdf_of_hit() of the point the direction meets.
// Where they overlap (the sky is behind everything), pdf() is the mixture's density, which the
// chi-square checks against the directions drawn.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "ch03/material_helpers.h"
#include "ch03/sampling_checks.h"
#include "ch14/direction_checks.h"
#include "rt/accel/bvh.h"
#include "rt/geometry/box.h"
#include "rt/geometry/instance.h"
#include "rt/geometry/quad.h"
#include "rt/geometry/sphere.h"
#include "rt/lights/light_set.h"
#include "rt/lights/sky_light.h"
#include "rt/materials/diffuse_light.h"
#include "rt/materials/lambertian.h"
#include "rt/media/constant_medium.h"
#include "rt/scene/hittable_list.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::point3, rt::real, rt::vec3;
using rt_test::direction_checks::direction_bins;

const rt::background black = rt::background::uniform(color(0, 0, 0));
const rt::interval forward(0, rt::infinity);

std::shared_ptr<rt::material> emitter() {
    return std::make_shared<rt::diffuse_light>(color(4, 4, 4));
}

std::shared_ptr<rt::quad> light_quad(const point3& q, const vec3& u, const vec3& v) {
    return std::make_shared<rt::quad>(q, u, v, emitter());
}

std::shared_ptr<rt::sphere> light_sphere(const point3& c, real r) {
    return std::make_shared<rt::sphere>(c, r, emitter());
}

// Three lights around the origin that no direction from it sees two of: a quad overhead, a
// tilted quad to the side and a sphere below.
std::shared_ptr<rt::hittable_list> three_lights() {
    auto world = std::make_shared<rt::hittable_list>();
    world->add(light_quad(point3(-1, 2, -1), vec3(2, 0, 0), vec3(0, 0, 1.5)));
    world->add(light_quad(point3(3, -0.5, -1), vec3(0, 1.5, 0.5), vec3(0.3, 0, 2)));
    world->add(light_sphere(point3(-0.5, -3, 0.5), real(0.8)));
    return world;
}

rt_test::direction_checks::direction_test test_set(const rt::light_set& lights, const point3& ref,
                                                   bool report_set_pdf, std::uint64_t sequence) {
    // Bins over the whole sphere, about an axis that no light is centered on.
    const direction_bins bins(rt::unit_vector(vec3(0.2, 1, 0.3)), 2, 12, 16);
    auto draw = [&](rt::pcg32& rng, vec3& wi, real& pdf) {
        rt::light_sample out;
        const real pick = rng.uniform();
        if (!lights.sample(ref, pick, rt_test::sampling_checks::next_sample2(rng), out))
            return false;
        wi  = out.wi;
        pdf = report_set_pdf ? lights.pdf(ref, wi) : out.pdf;
        return true;
    };
    auto pdf = [&](const vec3& wi) { return lights.pdf(ref, wi); };
    return rt_test::direction_checks::test_directions(
        bins, draw, pdf, 100000, sequence, 1000 * double(std::numeric_limits<real>::epsilon()));
}

}  // namespace

TEST_CASE("light_set: without overlaps, a sample's pdf (choice included) is pdf() of it",
          "[ch14]") {
    auto world = three_lights();
    rt::light_set lights(*world, black);
    REQUIRE(lights.size() == 3);
    const point3 ref(0.1, 0, 0.2);
    // The directions drawn follow pdf(), which integrates to 1, and each reports pdf() itself:
    // the light's own density divided by 3.
    rt_test::direction_checks::check_directions(test_set(lights, ref, false, 41));

    // And pdf_of_hit() of the point the direction meets says the same.
    rt::pcg32 rng(41, 2);
    int wrong = 0;
    for (int k = 0; k < 3000; ++k) {
        rt::light_sample out;
        const real pick = rng.uniform();
        REQUIRE(lights.sample(ref, pick, rt_test::sampling_checks::next_sample2(rng), out));
        rt::hit_record rec;
        REQUIRE(world->hit(rt::ray(ref, out.wi), forward, rec));
        const real by_hit = lights.pdf_of_hit(ref, out.wi, rec);
        wrong += !(std::fabs(by_hit - out.pdf) <= 1e-4 * out.pdf);
        wrong += lights.pdf_of_sky(ref, out.wi) != 0;  // no sky in this set
    }
    CHECK(wrong == 0);
}

TEST_CASE("light_set: with the sky behind every light, directions follow the mixture's pdf()",
          "[ch14]") {
    auto world = three_lights();
    rt::light_set lights(*world, rt::background::sky());
    REQUIRE(lights.size() == 4);
    const point3 ref(0.1, 0, 0.2);
    rt_test::direction_checks::check_directions(test_set(lights, ref, true, 42));

    // The sky's share: pdf_of_sky is a quarter of the sky's own density; a direction towards
    // the overhead quad has both the quad's and the sky's share in pdf(), only the quad's in
    // pdf_of_hit().
    rt::sky_light sky(rt::background::sky());
    const vec3 up(0, 1, 0);
    CHECK(lights.pdf_of_sky(ref, up) == Approx(sky.pdf(ref, up) / 4).epsilon(1e-6));
    rt::hit_record rec;
    REQUIRE(world->hit(rt::ray(ref, up), forward, rec));
    CHECK(lights.pdf(ref, up) ==
          Approx(lights.pdf_of_hit(ref, up, rec) + lights.pdf_of_sky(ref, up)).epsilon(1e-6));
}

TEST_CASE("light_set: finds emitting quads and spheres in lists and BVHs, nested", "[ch14]") {
    // world = list {
    //   light quad A, lambertian quad, light sphere B,
    //   BVH { lambertian sphere, light quad C, BVH { light sphere D }, light box (6 quads) },
    //   list { list { light quad E } },
    //   translate(light quad), rotate(light sphere), a medium in an emitting box,
    //   light quad A again }
    // finds A, B, C, D, E and the box's 6 faces: 11 lights; A only once.
    auto world = std::make_shared<rt::hittable_list>();
    auto a     = light_quad(point3(-1, 5, -1), vec3(2, 0, 0), vec3(0, 0, 2));
    auto b     = light_sphere(point3(0, -5, 0), 1);
    auto c     = light_quad(point3(5, -1, -1), vec3(0, 2, 0), vec3(0, 0, 2));
    auto d     = light_sphere(point3(-5, 0, 0), 1);
    auto e     = light_quad(point3(-1, -1, 5), vec3(2, 0, 0), vec3(0, 2, 0));
    auto dull  = std::make_shared<rt::quad>(point3(-1, -1, -5), vec3(2, 0, 0), vec3(0, 2, 0),
                                           rt_test::any_material());
    world->add(a);
    world->add(dull);
    world->add(b);
    auto inner_bvh = std::make_shared<rt::bvh>(std::vector<rt::bounded_object>{d});
    auto outer_bvh = std::make_shared<rt::bvh>(std::vector<rt::bounded_object>{
        std::make_shared<rt::sphere>(point3(7, 7, 7), 1, rt_test::any_material()), c, inner_bvh,
        rt::box(point3(20, 20, 20), point3(21, 21, 21), emitter())});
    world->add(outer_bvh);
    auto inner_list = std::make_shared<rt::hittable_list>();
    inner_list->add(e);
    auto middle_list = std::make_shared<rt::hittable_list>();
    middle_list->add(inner_list);
    world->add(middle_list);
    world->add(std::make_shared<rt::translate>(
        light_quad(point3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0)), vec3(10, 0, 0)));
    world->add(std::make_shared<rt::rotate>(light_sphere(point3(0, 10, 0), 1), rt::axis::y, 30));
    world->add(std::make_shared<rt::constant_medium>(
        rt::box(point3(-30, -30, -30), point3(-29, -29, -29), emitter()), 1, color(1, 1, 1)));
    world->add(a);

    rt::light_set lights(*world, black);
    CHECK(lights.size() == 11);
    CHECK_FALSE(lights.empty());

    // Each light found can be aimed at from the origin: pdf() > 0 towards it.
    const point3 origin(0, 0, 0);
    for (const vec3& towards : {vec3(0, 1, 0), vec3(0, -1, 0), vec3(1, 0, 0), vec3(-1, 0, 0),
                                vec3(0, 0, 1), vec3(1, 1, 1)}) {
        INFO("towards " << towards);
        CHECK(lights.pdf(origin, rt::unit_vector(towards)) > 0);
    }
    // Not the lambertian quad, nor the lambertian sphere (they are not lights at all).
    CHECK(lights.pdf(origin, vec3(0, 0, -1)) == 0);
    CHECK(lights.pdf(point3(7, 7, 4), vec3(0, 0, 1)) == 0);
    // Not the instances, nor the medium's emitting boundary.
    CHECK(lights.pdf(point3(10.5, 0.5, -3), vec3(0, 0, 1)) == 0);
    CHECK(lights.pdf(point3(0, 10, 3), vec3(0, 0, -1)) == 0);
    CHECK(lights.pdf(point3(-29.5, -29.5, -35), vec3(0, 0, 1)) == 0);
}

TEST_CASE("light_set: the sky is a light only when it is not black", "[ch14]") {
    auto world = three_lights();
    CHECK(rt::light_set(*world, black).size() == 3);
    CHECK(rt::light_set(*world, rt::background::sky()).size() == 4);
    CHECK(rt::light_set(*world, {color(0, 0, 0), color(0, 0.1, 0)}).size() == 4);
    CHECK(rt::light_set(*world, {color(0.1, 0, 0), color(0, 0, 0)}).size() == 4);

    // A scene without emitters under a black sky has no lights: nothing to sample, no density.
    rt::hittable_list dark;
    dark.add(std::make_shared<rt::sphere>(point3(0, 0, -2), 1, rt_test::any_material()));
    rt::light_set none(dark, black);
    CHECK(none.empty());
    rt::light_sample out;
    CHECK_FALSE(none.sample(point3(0, 0, 0), real(0.5), {real(0.5), real(0.5)}, out));
    CHECK(none.pdf(point3(0, 0, 0), vec3(0, 0, -1)) == 0);
    CHECK(none.pdf_of_sky(point3(0, 0, 0), vec3(0, 0, -1)) == 0);

    // Under the sky alone, every direction has the sky's density.
    rt::light_set sky_only(dark, rt::background::sky());
    REQUIRE(sky_only.size() == 1);
    rt::sky_light sky(rt::background::sky());
    CHECK(sky_only.pdf_of_sky(point3(0, 0, 0), vec3(0, 1, 0)) ==
          Approx(sky.pdf(point3(0, 0, 0), vec3(0, 1, 0))).epsilon(1e-6));
}

TEST_CASE("light_set: pdf_of_hit is 0 for objects that are not lights", "[ch14]") {
    auto world = three_lights();
    auto dull  = std::make_shared<rt::quad>(point3(-1, -1, -3), vec3(2, 0, 0), vec3(0, 2, 0),
                                           rt_test::any_material());
    world->add(dull);
    // An emitting quad inside an instance: hit, but never aimed at.
    world->add(std::make_shared<rt::translate>(
        light_quad(point3(-1, -1, 0), vec3(2, 0, 0), vec3(0, 2, 0)), vec3(0, 0, 3)));
    rt::light_set lights(*world, rt::background::sky());
    const point3 ref(0, 0, 0);
    rt::hit_record rec;
    REQUIRE(world->hit(rt::ray(ref, vec3(0, 0, -1)), forward, rec));
    CHECK(rec.object == dull.get());
    CHECK(lights.pdf_of_hit(ref, vec3(0, 0, -1), rec) == 0);
    REQUIRE(world->hit(rt::ray(ref, vec3(0, 0, 1)), forward, rec));
    CHECK(lights.pdf_of_hit(ref, vec3(0, 0, 1), rec) == 0);
    // A hit record of no object at all.
    CHECK(lights.pdf_of_hit(ref, vec3(0, 0, 1), rt::hit_record()) == 0);
}

TEST_CASE("light_set: a light shape also placed through an instance: the copy is no light",
          "[ch14][hardcase]") {
    // One emitting quad added to the world directly and, the same object, moved by a
    // translate. The direct one is found; the moved copy is not aimed at, so a path that hits
    // it must count it with full weight: pdf_of_hit 0. The copy's hit record names the shared
    // quad (rec.object is the shape, whatever instance placed it), so a lookup by object alone
    // mistakes the copy for the light, and MIS then weighs light that no light sample finds.
    auto shared = light_quad(point3(-1, 2, -1), vec3(2, 0, 0), vec3(0, 0, 2));
    auto world  = std::make_shared<rt::hittable_list>();
    world->add(shared);
    world->add(std::make_shared<rt::translate>(shared, vec3(0, -4, 0)));
    rt::light_set lights(*world, black);
    REQUIRE(lights.size() == 1);
    const point3 ref(0, 0, 0);
    rt::hit_record rec;
    REQUIRE(world->hit(rt::ray(ref, vec3(0, 1, 0)), forward, rec));
    CHECK(lights.pdf_of_hit(ref, vec3(0, 1, 0), rec) > 0);  // the light itself
    REQUIRE(world->hit(rt::ray(ref, vec3(0, -1, 0)), forward, rec));
    CHECK(rec.p.y() == Approx(-2));  // the copy below
    CHECK(lights.pdf_of_hit(ref, vec3(0, -1, 0), rec) == 0);
}
