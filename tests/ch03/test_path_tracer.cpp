// Tests for path_tracer.h (chapter 03): the path tracer's bookkeeping, on scenes whose answer is
// known exactly rather than on average.
//
// "No shadow acne": one Lambertian object of albedo a = 0.6 in a uniform background of 1, with
// max_depth 2. A path that hits the object scatters once; the scattered ray leaves a convex
// object and so cannot hit it again; it reaches the background and the path returns
// a * 1 = 0.6, exactly, every time. A path whose bounce re-hits its own surface (acne) instead
// runs out of depth and returns 0. So every single path is checked, not a mean.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <sstream>
#include <string>

#include "ch03/material_helpers.h"
#include "rt/camera/camera.h"
#include "rt/core/error.h"
#include "rt/geometry/quad.h"
#include "rt/geometry/spawn_ray.h"
#include "rt/geometry/sphere.h"
#include "rt/integrators/path_tracer.h"
#include "rt/materials/lambertian.h"
#include "rt/render/film.h"
#include "rt/samplers/independent_sampler.h"
#include "rt/scene/hittable_list.h"
#include "rt/scene/scene.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::point3, rt::real, rt::vec3;

const rt::interval forward(0, rt::infinity);

using rt_test::exactly;

// One object in a uniform background of 1, seen from `eye` looking down -z through a square
// view. Chapter 01's camera stands at the origin; its rays are moved to start at eye instead
// (their origin is (0, 0, 0), so eye + origin is eye exactly), which is how these scenes sit far
// from the origin, where a fixed t > 0.001 would both cut off real hits and miss self-hits.
struct furnace {
    std::shared_ptr<rt::hittable> world;
    point3 eye;
    rt::film f = rt::film::for_aspect(50, 1);
    rt::camera cam;
    rt::path_tracer tracer;

    furnace(std::shared_ptr<rt::hittable> object, const point3& from, real vfov)
        : world(std::move(object)),
          eye(from),
          tracer(world, rt::background::uniform(color(1, 1, 1))) {
        cam.aspect_ratio = 1;
        cam.vfov         = vfov;
        cam.initialize(f);
    }

    rt::ray get_ray(int i, int j, rt::sampler& s) const {
        const rt::ray r = cam.get_ray(i, j, s);
        return rt::ray(eye + r.origin(), r.direction());
    }
};

struct path_check {
    long long on = 0, off = 0;              // paths whose camera ray hit / missed the world
    long long wrong_on = 0, wrong_off = 0;  // of those, paths not returning the expected value
    std::string first_wrong;
};

std::ostream& operator<<(std::ostream& out, const path_check& c) {
    out << c.on << " paths hit the object, " << c.wrong_on << " of them wrong; " << c.off
        << " missed, " << c.wrong_off << " of them wrong";
    if (!c.first_wrong.empty()) out << " (first: " << c.first_wrong << ")";
    return out;
}

// 50 x 50 pixels x 40 samples = 1e5 camera paths, each compared bit for bit with the answer.
path_check trace_every_pixel(const furnace& sc, int max_depth, const color& expect_on,
                             const color& expect_off) {
    path_check c;
    rt::independent_sampler s(42);
    for (int j = 0; j < sc.f.height; ++j) {
        for (int i = 0; i < sc.f.width; ++i) {
            for (int k = 0; k < 40; ++k) {
                s.start_pixel_sample(i, j, k);
                rt::ray r = sc.get_ray(i, j, s);
                rt::hit_record rec;
                bool on        = sc.world->hit(r, forward, rec);
                color L        = sc.tracer.radiance(r, s, max_depth);
                const color& e = on ? expect_on : expect_off;
                ++(on ? c.on : c.off);
                if (!exactly(L, e)) {
                    ++(on ? c.wrong_on : c.wrong_off);
                    if (c.first_wrong.empty()) {
                        std::ostringstream what;
                        what << "pixel (" << i << ", " << j << ") sample " << k << " gave " << L;
                        c.first_wrong = what.str();
                    }
                }
            }
        }
    }
    return c;
}

const color albedo(0.6, 0.6, 0.6);

std::shared_ptr<rt::hittable> gray_sphere(const point3& center, real radius) {
    return std::make_shared<rt::sphere>(center, radius, std::make_shared<rt::lambertian>(albedo));
}

std::shared_ptr<rt::hittable> gray_quad(const point3& Q, const vec3& u, const vec3& v) {
    return std::make_shared<rt::quad>(Q, u, v, std::make_shared<rt::lambertian>(albedo));
}

// A material that absorbs every ray, having drawn nothing.
class absorber : public rt::material {
  public:
    std::optional<rt::scatter_sample> scatter(const rt::ray&, const rt::hit_record&,
                                              rt::sampler&) const override {
        return std::nullopt;
    }
};

// A material that lets every ray go straight on through its surface, weighted by a fixed color,
// having drawn nothing: a colored filter. A path through several of them has a known product.
class filter : public rt::material {
  public:
    explicit filter(const color& w) : weight(w) {}
    std::optional<rt::scatter_sample> scatter(const rt::ray& r_in, const rt::hit_record& rec,
                                              rt::sampler&) const override {
        return rt::scatter_sample{rt::spawn_ray(rec, r_in, r_in.direction()), weight};
    }

  private:
    color weight;
};

}  // namespace

TEST_CASE("path_tracer: no shadow acne, every path off a Lambertian sphere returns its albedo",
          "[ch03]") {
    // A unit sphere 4 ahead, and a 1e-3 sphere about 1e3 from the origin seen from 0.004 away.
    // Float keeps 24 bits: such a sphere spans 16 of its ulps, so whether a ray grazing its rim
    // enters or leaves is decided by rounding alone. Its far sphere is a 1e-2 one 1e2 away
    // instead: a million to one in double, ten thousand to one in float.
    const bool is_double = std::numeric_limits<real>::digits >= 53;
    const real far_scale = is_double ? real(1) : real(0.1),
               small     = is_double ? real(1e-3) : real(1e-2);
    const point3 far_center(500 * far_scale, -300 * far_scale, 800 * far_scale);
    const furnace scenes[] = {
        furnace(gray_sphere(point3(0, 0, 0), 1), point3(0, 0, 4), 40),
        furnace(gray_sphere(far_center, small), far_center + vec3(0, 0, 4 * small), 40),
    };
    for (const auto& sc : scenes) {
        auto c = trace_every_pixel(sc, 2, albedo, color(1, 1, 1));
        INFO(c);
        CHECK(c.on > 10000);
        CHECK(c.off > 10000);
        CHECK(c.wrong_on == 0);
        CHECK(c.wrong_off == 0);
    }
}

TEST_CASE("path_tracer: no shadow acne, every path off a Lambertian quad floor returns its albedo",
          "[ch03]") {
    // A bounce off a plane leaves to the side it came from, so it cannot meet the floor again.
    // The eye stands 1 above the floor; the lower half of the view sees it up to the horizon.
    const furnace scenes[] = {
        furnace(gray_quad(point3(-10, 0, -10), vec3(20, 0, 0), vec3(0, 0, 20)), point3(0, 1, 3),
                90),
        furnace(gray_quad(point3(900, 250, 900), vec3(200, 0, 0), vec3(0, 0, 200)),
                point3(1000, 251, 1000), 90),
    };
    for (const auto& sc : scenes) {
        auto c = trace_every_pixel(sc, 2, albedo, color(1, 1, 1));
        INFO(c);
        CHECK(c.on > 10000);
        CHECK(c.off > 1000);
        CHECK(c.wrong_on == 0);
        CHECK(c.wrong_off == 0);
    }
}

TEST_CASE("path_tracer: at max_depth 1 a Lambertian hit returns 0, a miss the background",
          "[ch03]") {
    // The one segment ends on the surface; the path runs out of depth before reaching any light.
    const furnace sc(gray_sphere(point3(0, 0, 0), 1), point3(0, 0, 4), 40);
    auto c = trace_every_pixel(sc, 1, color(0, 0, 0), color(1, 1, 1));
    INFO(c);
    CHECK(c.on > 10000);
    CHECK(c.off > 10000);
    CHECK(c.wrong_on == 0);
    CHECK(c.wrong_off == 0);

    // And max_depth 0 follows no segment at all.
    rt::independent_sampler s(1);
    s.start_pixel_sample(0, 0, 0);
    CHECK(
        exactly(sc.tracer.radiance(rt::ray(point3(0, 0, 4), vec3(0, 1, 0)), s, 0), color(0, 0, 0)));
}

TEST_CASE("path_tracer: an absorbed path returns what it gathered before, here nothing", "[ch03]") {
    auto world = std::make_shared<rt::sphere>(point3(0, 0, -3), 1, std::make_shared<absorber>());
    const rt::path_tracer tracer(world, rt::background::uniform(color(1, 1, 1)));
    rt::independent_sampler s(1);
    s.start_pixel_sample(0, 0, 0);
    CHECK(
        exactly(tracer.radiance(rt::ray(point3(0, 0, 0), vec3(0, 0, -1)), s, 50), color(0, 0, 0)));
    CHECK(exactly(tracer.radiance(rt::ray(point3(0, 0, 0), vec3(0, 0, 1)), s, 50), color(1, 1, 1)));
}

TEST_CASE("path_tracer: the weights of a path's bounces multiply, first to last", "[ch03]") {
    // Three filters across the view at z = -1, -2, -3, then a uniform sky of 1: every path
    // crosses all three and returns w1 w2 w3, exactly (the weights are powers of 2). A tracer
    // that replaced its throughput by each new weight instead of multiplying it in would
    // return the last filter's weight alone; one that left the sky unweighted would return 1.
    const color w1(real(0.5), real(0.25), 1), w2(real(0.5), 1, real(0.25)),
        w3(1, real(0.5), real(0.5));
    const color product(real(0.25), real(0.125), real(0.125));
    auto world            = std::make_shared<rt::hittable_list>();
    const color weights[] = {w1, w2, w3};
    for (int k = 0; k < 3; ++k)
        world->add(std::make_shared<rt::quad>(point3(-4, -4, real(-1 - k)), vec3(8, 0, 0),
                                              vec3(0, 8, 0), std::make_shared<filter>(weights[k])));
    const rt::path_tracer tracer(world, rt::background::uniform(color(1, 1, 1)));
    for (const vec3& d : {vec3(0, 0, -1), vec3(real(0.25), real(-0.5), -1), vec3(-1, 1, -2)}) {
        rt::independent_sampler s(5);
        s.start_pixel_sample(0, 0, 0);
        // 3 filters and the sky: 4 segments.
        const color L = tracer.radiance(rt::ray(point3(0, 0, 0), d), s, 4);
        INFO("through filters " << w1 << ", " << w2 << ", " << w3 << " along " << d
                                << " the path must return their product " << product << ", got "
                                << L);
        CHECK(exactly(L, product));
    }
}

TEST_CASE("path_tracer: a path draws only what its materials draw, 2 per Lambertian bounce",
          "[ch03][draw-order]") {
    // A Lambertian floor under a uniform sky, max_depth 2: the camera ray hits the floor, the
    // bounce leaves it for the sky. The path must draw exactly the bounce's 2 dimensions
    // (sampler.h), so whatever comes next sees the dimension after them.
    auto floor = gray_quad(point3(-10, 0, -10), vec3(20, 0, 0), vec3(0, 0, 20));
    const rt::path_tracer tracer(floor, rt::background::uniform(color(1, 1, 1)));
    int wrong_value = 0, drew_wrong = 0;
    for (int k = 0; k < 1000; ++k) {
        rt::independent_sampler s(77);
        s.start_pixel_sample(3, 4, k);
        color L = tracer.radiance(rt::ray(point3(0, 1, 0), vec3(0.25, -1, 0.5)), s, 2);
        wrong_value += !exactly(L, albedo);  // one bounce, then the sky: 2 segments
        drew_wrong += s.next_1d() != rt_test::next_after_draws(77, 3, 4, k, 2);
    }
    CHECK(wrong_value == 0);
    CHECK(drew_wrong == 0);

    // A miss draws nothing.
    rt::independent_sampler s(77);
    s.start_pixel_sample(3, 4, 0);
    CHECK(exactly(tracer.radiance(rt::ray(point3(0, 1, 0), vec3(0, 1, 0)), s, 2), color(1, 1, 1)));
    CHECK(s.next_1d() == rt_test::next_after_draws(77, 3, 4, 0, 0));
}

TEST_CASE("path_tracer: the job path traces the scene's world through its camera and settings",
          "[ch03]") {
    rt::scene sc;
    sc.world              = gray_sphere(point3(0, 0, -2), 1);
    sc.sky                = rt::background::uniform(color(real(0.25), real(0.5), real(0.75)));
    sc.settings.max_depth = 3;
    sc.settings.samples_per_pixel = 5;
    const rt::render_job job      = rt::path_trace(sc);
    CHECK(job.cam == sc.cam);  // the same camera, not a copy
    CHECK(job.settings.max_depth == 3);
    CHECK(job.settings.samples_per_pixel == 5);
    REQUIRE(job.estimator != nullptr);
    rt::independent_sampler s(1);
    s.start_pixel_sample(0, 0, 0);
    // A miss sees the scene's own sky; a hit off the sphere's pole sees albedo * sky.
    CHECK(exactly(job.estimator->radiance(rt::ray(point3(0, 0, 0), vec3(0, 1, 0)), s, 3),
                  color(real(0.25), real(0.5), real(0.75))));
    CHECK(exactly(job.estimator->radiance(rt::ray(point3(0, 0, 0), vec3(0, 0, -1)), s, 3),
                  albedo * color(real(0.25), real(0.5), real(0.75))));
}

TEST_CASE("path_tracer: a scene without a world is refused", "[ch03]") {
    CHECK_THROWS_AS(rt::path_tracer(nullptr, rt::background::sky()), rt::user_error);
    CHECK_THROWS_WITH(rt::path_trace(rt::scene{}), Catch::Contains("world"));
}
