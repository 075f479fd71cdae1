// show_normals (rt/integrators/show_normals.h): chapter 02's way of seeing a scene. Each sample
// shows the unit outward normal n of the nearest hit as the color 0.5 (n + 1), whichever side the
// ray comes from, and the sky where nothing is hit; it draws nothing from the sampler. Chapter 02.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "rt/core/error.h"
#include "rt/geometry/sphere.h"
#include "rt/integrators/show_normals.h"
#include "rt/samplers/independent_sampler.h"
#include "rt/scene/background.h"
#include "rt/scene/hittable_list.h"
#include "rt/scene/scene.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::point3, rt::real, rt::vec3;

using rt_test::exactly;

const rt::background sky = rt::background::sky();

rt::color shown(const rt::radiance_estimator& estimator, const rt::ray& r) {
    rt::independent_sampler s(1);
    s.start_pixel_sample(0, 0, 0);
    return estimator.radiance(r, s, 50);
}

}  // namespace

TEST_CASE("show_normals: a head-on hit on a unit sphere shows 0.5 (n + 1) exactly, outside and in",
          "[ch02]") {
    // Rays along the axes meet the unit sphere at the poles, where every coordinate is 0 or +-1:
    // the normal, and so the color, is exact. From outside the ray meets the near pole, whose
    // outward normal faces it; from the centre it meets the pole ahead from inside, where the
    // outward normal points along the ray (the hit record's normal faces the ray instead: the
    // picture must show the outward one).
    const rt::normals_estimator normals(std::make_shared<rt::sphere>(point3(0, 0, 0), 1), sky);
    const vec3 axes[] = {vec3(1, 0, 0),  vec3(0, 1, 0),  vec3(0, 0, 1),
                         vec3(-1, 0, 0), vec3(0, -1, 0), vec3(0, 0, -1)};
    for (const vec3& n : axes) {
        const color expected = real(0.5) * (n + color(1, 1, 1));
        CAPTURE(n, expected);
        CHECK(exactly(shown(normals, rt::ray(5 * n, -n)), expected));               // outside
        CHECK(exactly(shown(normals, rt::ray(point3(0, 0, 0), n)), expected));      // inside
        CHECK(exactly(shown(normals, rt::ray(point3(0, 0, 0), 3 * n)), expected));  // any length
    }
    // The book's first sphere, seen straight on: the colour of +z, (0.5, 0.5, 1).
    CHECK(exactly(shown(normals, rt::ray(point3(0, 0, 4), vec3(0, 0, -1))), color(0.5, 0.5, 1)));
}

TEST_CASE("show_normals: any hit shows 0.5 (n + 1) of the outward normal at the hit", "[ch02]") {
    // Random rays at a sphere off the origin, from outside and from inside: the color is
    // 0.5 (unit(p - c) + 1) up to the normal's few ulps, with nothing of the sky added.
    const point3 center(0.5, -1, 2);
    auto ball = std::make_shared<rt::sphere>(center, 1);
    const rt::normals_estimator normals(ball, sky);
    rt::pcg32 rng(12, 34);
    int hits = 0, wrong = 0;
    for (int k = 0; k < 2000; ++k) {
        const real distance = k % 2 == 0 ? 3 : real(0.5);  // even: outside, odd: inside
        const vec3 from     = distance * rt_test::random_unit(rng);
        const vec3 to       = real(0.9) * rt_test::random_unit(rng);
        const rt::ray r(center + from, to - from);
        rt::hit_record rec;
        if (!ball->hit(r, rt::interval(0, rt::infinity), rec)) continue;
        ++hits;
        const color expected = real(0.5) * (rt::unit_vector(rec.p - center) + color(1, 1, 1));
        const color L        = shown(normals, r);
        if (!((L - expected).length() <= 8 * std::numeric_limits<real>::epsilon())) {
            UNSCOPED_INFO("ray from " << r.origin() << " along " << r.direction() << " shows " << L
                                      << ", expected " << expected);
            ++wrong;
        }
    }
    CHECK(hits > 1800);
    CHECK(wrong == 0);
}

TEST_CASE("show_normals: a miss shows the sky, and the nearest object wins", "[ch02]") {
    auto world = std::make_shared<rt::hittable_list>();
    world->add(std::make_shared<rt::sphere>(point3(0, 0, -10), 1));
    world->add(std::make_shared<rt::sphere>(point3(0, 0, -3), 1));
    const rt::background two_tone{color(real(0.2), real(0.3), real(0.4)), color(1, real(0.5), 0)};
    const rt::normals_estimator normals(world, two_tone);
    for (const vec3& d : {vec3(0, 1, 0), vec3(0, 0, 1), vec3(1, 1, -1), vec3(-3, -1, 0)}) {
        CAPTURE(d);
        CHECK(exactly(shown(normals, rt::ray(point3(0, 0, 0), d)), two_tone.radiance(d)));
    }
    // Straight ahead, the near sphere's front pole (+z) hides the far one.
    CHECK(exactly(shown(normals, rt::ray(point3(0, 0, 0), vec3(0, 0, -1))), color(0.5, 0.5, 1)));
    // An empty world is all sky.
    const rt::normals_estimator nothing(std::make_shared<rt::hittable_list>(), two_tone);
    CHECK(exactly(shown(nothing, rt::ray(point3(0, 0, 0), vec3(0, 0, -1))),
                  two_tone.radiance(vec3(0, 0, -1))));
}

TEST_CASE("show_normals: the estimator draws no sampler dimension", "[ch02]") {
    // Hit or miss, the next number is the sampler's first: the camera's jitter and the normals
    // are all that chapter 02's pictures draw.
    const rt::normals_estimator normals(std::make_shared<rt::sphere>(point3(0, 0, -2), 1), sky);
    rt::pcg32 rng(5, 1);
    int drew = 0, hits = 0;
    for (int k = 0; k < 1000; ++k) {
        const vec3 d = rt::unit_vector(vec3(0, 0, -1) + real(0.8) * rt_test::random_unit(rng));
        rt::independent_sampler s(9);
        s.start_pixel_sample(k, 1, 0);
        const color L = normals.radiance(rt::ray(point3(0, 0, 0), d), s, 50);
        hits += !exactly(L, sky.radiance(d));
        if (s.next_1d() != rt_test::next_after_draws(9, k, 1, 0, 0)) ++drew;
    }
    CHECK(hits > 100);  // both kinds of rays were asked
    CHECK(hits < 900);
    CHECK(drew == 0);
}

TEST_CASE("show_normals: the job shows the scene's world through its camera and settings",
          "[ch02]") {
    rt::scene sc;
    sc.world     = std::make_shared<rt::sphere>(point3(0, 0, -1), real(0.5));
    sc.sky       = rt::background::uniform(color(real(0.25), real(0.5), real(0.75)));
    sc.cam->vfov = 60;
    sc.settings.samples_per_pixel = 7;
    sc.settings.seed              = 99;
    const rt::render_job job      = rt::show_normals(sc);
    CHECK(job.cam == sc.cam);  // the same camera, not a copy
    CHECK(job.settings.samples_per_pixel == 7);
    CHECK(job.settings.seed == 99);
    REQUIRE(job.estimator != nullptr);
    rt::independent_sampler s(1);
    s.start_pixel_sample(0, 0, 0);
    // The sphere's front pole, and a miss that sees the scene's own sky.
    CHECK(exactly(job.estimator->radiance(rt::ray(point3(0, 0, 0), vec3(0, 0, -1)), s, 50),
                  color(0.5, 0.5, 1)));
    CHECK(exactly(job.estimator->radiance(rt::ray(point3(0, 0, 0), vec3(0, 1, 0)), s, 50),
                  color(real(0.25), real(0.5), real(0.75))));
}

TEST_CASE("show_normals: a scene without a world is refused", "[ch02]") {
    CHECK_THROWS_AS(rt::normals_estimator(nullptr, sky), rt::user_error);
    CHECK_THROWS_WITH(rt::show_normals(rt::scene{}), Catch::Contains("world"));
}
