// Tests for integrator.h (chapter 03): the path tracer's bookkeeping, on scenes whose answer is
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
#include <vector>

#include "common/integrator.h"
#include "common/lambertian.h"
#include "common/normal_shading.h"
#include "common/quad.h"
#include "common/rng.h"
#include "common/sampling.h"
#include "common/sphere.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::point3, rt::real, rt::vec3;

const rt::interval forward(0, rt::infinity);

using rt_test::exactly;

// A uniform background of 1 and a square camera looking from `from` at `at`.
rt::scene furnace(std::shared_ptr<rt::hittable> object, const point3& from, const point3& at,
                  real vfov) {
    rt::scene sc;
    sc.world.add(std::move(object));
    sc.sky              = rt::background::uniform(color(1, 1, 1));
    sc.cam.aspect_ratio = 1;
    sc.cam.image_width  = 50;
    sc.cam.vfov         = vfov;
    sc.cam.lookfrom     = from;
    sc.cam.lookat       = at;
    sc.cam.initialize();
    return sc;
}

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
path_check trace_every_pixel(const rt::scene& sc, int max_depth, const color& expect_on,
                             const color& expect_off) {
    path_check c;
    rt::sampler s(42);
    for (int j = 0; j < sc.cam.image_height(); ++j) {
        for (int i = 0; i < sc.cam.image_width; ++i) {
            for (int k = 0; k < 40; ++k) {
                s.start_pixel_sample(i, j, k);
                rt::ray r = sc.cam.get_ray(i, j, s);
                rt::hit_record rec;
                bool on        = sc.world.hit(r, forward, rec);
                color L        = rt::trace_path(sc, r, s, max_depth);
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

}  // namespace

TEST_CASE("integrator: no shadow acne, every path off a Lambertian sphere returns its albedo",
          "[ch03]") {
    // A unit sphere at the origin, and a 1e-3 sphere about 1e3 from the origin, where a fixed
    // t > 0.001 would both cut off real hits and miss self-hits.
    const rt::scene scenes[] = {
        furnace(gray_sphere(point3(0, 0, 0), 1), point3(0, 0, 4), point3(0, 0, 0), 40),
        furnace(gray_sphere(point3(500, -300, 800), 1e-3), point3(500, -300, 800.004),
                point3(500, -300, 800), 40),
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

TEST_CASE("integrator: no shadow acne, every path off a Lambertian quad floor returns its albedo",
          "[ch03]") {
    // A bounce off a plane leaves to the side it came from, so it cannot meet the floor again.
    const rt::scene scenes[] = {
        furnace(gray_quad(point3(-10, 0, -10), vec3(20, 0, 0), vec3(0, 0, 20)), point3(0, 1, 3),
                point3(0, 0, -1), 90),
        furnace(gray_quad(point3(900, 250, 900), vec3(200, 0, 0), vec3(0, 0, 200)),
                point3(1000, 251, 1000), point3(1000, 250, 996), 90),
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

TEST_CASE("integrator: at max_depth 1 a Lambertian hit returns 0, a miss the background",
          "[ch03]") {
    // The one segment ends on the surface; the path runs out of depth before reaching any light.
    auto sc = furnace(gray_sphere(point3(0, 0, 0), 1), point3(0, 0, 4), point3(0, 0, 0), 40);
    auto c  = trace_every_pixel(sc, 1, color(0, 0, 0), color(1, 1, 1));
    INFO(c);
    CHECK(c.on > 10000);
    CHECK(c.off > 10000);
    CHECK(c.wrong_on == 0);
    CHECK(c.wrong_off == 0);

    // And max_depth 0 follows no segment at all.
    rt::sampler s(1);
    s.start_pixel_sample(0, 0, 0);
    CHECK(
        exactly(rt::trace_path(sc, rt::ray(point3(0, 0, 4), vec3(0, 1, 0)), s, 0), color(0, 0, 0)));
}

TEST_CASE("integrator: the normal_shading material shows 0.5 * (n + 1) and nothing else",
          "[ch03]") {
    const point3 center(0.5, -1, 2);
    rt::scene sc;
    sc.world.add(std::make_shared<rt::sphere>(center, 1, std::make_shared<rt::normal_shading>()));
    sc.sky = rt::background::uniform(color(1, 1, 1));
    rt::sampler s(3);
    s.start_pixel_sample(0, 0, 0);

    // Exact cases: the front pole facing -z, and from inside the far pole facing +z (the outward
    // normal, not the one facing the ray).
    CHECK(exactly(rt::trace_path(sc, rt::ray(center - vec3(0, 0, 5), vec3(0, 0, 1)), s, 50),
                  color(0.5, 0.5, 0)));
    CHECK(exactly(rt::trace_path(sc, rt::ray(center, vec3(0, 0, 1)), s, 50), color(0.5, 0.5, 1)));

    // Random rays: the color is 0.5 * (unit(p - c) + 1) up to the normal's few ulps, with no
    // background added (the material absorbs).
    rt::pcg32 rng(12, 34);
    int hits = 0, wrong = 0;
    for (int k = 0; k < 1000; ++k) {
        real u       = rng.uniform();
        vec3 outside = 3 * rt::sample_uniform_sphere({u, rng.uniform()});
        u            = rng.uniform();
        vec3 target  = real(0.9) * rt::sample_uniform_sphere({u, rng.uniform()});
        rt::ray r(center + outside, target - outside);
        rt::hit_record rec;
        if (!sc.world.hit(r, forward, rec)) continue;
        ++hits;
        color expected = real(0.5) * (rt::unit_vector(rec.p - center) + color(1, 1, 1));
        color L        = rt::trace_path(sc, r, s, 50);
        if ((L - expected).length() > 8 * std::numeric_limits<real>::epsilon()) ++wrong;
    }
    INFO(wrong << " of " << hits << " hits shaded wrong");
    CHECK(hits > 900);
    CHECK(wrong == 0);
}

namespace {

// Hits like the object it wraps and records the random key of every ray it is asked about.
class key_recorder : public rt::hittable {
  public:
    explicit key_recorder(std::shared_ptr<rt::hittable> wrapped) : object(std::move(wrapped)) {}
    bool hit(const rt::ray& r, rt::interval ray_t, rt::hit_record& rec) const override {
        keys.push_back(r.random_key());
        return object->hit(r, ray_t, rec);
    }
    rt::aabb bounding_box() const override { return object->bounding_box(); }
    mutable std::vector<std::uint64_t> keys;

  private:
    std::shared_ptr<rt::hittable> object;
};

}  // namespace

TEST_CASE("integrator: every path segment gets a fresh random key, drawn from the sampler",
          "[ch12]") {
    // A Lambertian floor under a uniform sky, max_depth 2: segment 1 (the camera ray) hits the
    // floor, segment 2 leaves it for the sky. Each segment must carry its own key (media along
    // it make their choices from it), drawn at the documented place in the sampler's sequence:
    // next_key() first, then the material's 2 dimensions (sampler.h).
    auto recorder = std::make_shared<key_recorder>(
        gray_quad(point3(-10, 0, -10), vec3(20, 0, 0), vec3(0, 0, 20)));
    rt::scene sc;
    sc.world.add(recorder);
    sc.sky = rt::background::uniform(color(1, 1, 1));
    rt::sampler s(77);
    int same_keys = 0, misplaced = 0;
    for (int k = 0; k < 1000; ++k) {
        s.start_pixel_sample(3, 4, k);
        rt::sampler expected = s;  // replays the draws trace_path should make
        std::uint64_t key1   = expected.next_key();
        expected.next_2d();  // the Lambertian bounce
        std::uint64_t key2 = expected.next_key();
        recorder->keys.clear();
        color L = rt::trace_path(sc, rt::ray(point3(0, 1, 0), vec3(0.25, -1, 0.5)), s, 2);
        REQUIRE(exactly(L, albedo));  // one bounce, then the sky: the path really had 2 segments
        REQUIRE(recorder->keys.size() == 2);
        same_keys += recorder->keys[0] == recorder->keys[1];
        misplaced += recorder->keys[0] != key1 || recorder->keys[1] != key2;
    }
    CHECK(same_keys == 0);
    CHECK(misplaced == 0);
}
