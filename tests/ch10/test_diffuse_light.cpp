// Tests for diffuse_light.h (chapter 10): a light emits its radiance on both faces, reflects
// nothing, is seen at the first hit even with max_depth 1, emits its texture's value at the hit,
// and refuses radiance that is negative or not finite. Every case here is exact: the path tracer
// adds Le at a hit and multiplies by an attenuation that is 1 or a power of two, so the answers
// are compared bit for bit.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <utility>

#include "rt/camera/thin_lens_camera.h"
#include "rt/core/error.h"
#include "rt/geometry/quad.h"
#include "rt/integrators/path_tracer.h"
#include "rt/materials/diffuse_light.h"
#include "rt/materials/metal.h"
#include "rt/render/film.h"
#include "rt/samplers/independent_sampler.h"
#include "rt/scene/hittable_list.h"
#include "rt/scene/scene.h"
#include "rt/textures/texture.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::point3, rt::real, rt::vec3;

const rt::interval forward(0, rt::infinity);
const color radiance(4, 2, 1);

using rt_test::exactly;

// A 2 x 2 light quad in the plane z = 0, centered on the origin, normal u x v = +z.
std::shared_ptr<rt::quad> light_quad(const color& L) {
    return std::make_shared<rt::quad>(point3(-1, -1, 0), vec3(2, 0, 0), vec3(0, 2, 0),
                                      std::make_shared<rt::diffuse_light>(L));
}

// A 16 x 16 square camera at `from` looking at the origin; vfov 20 degrees from distance 3 sees
// a square of half-width 3 tan(10 deg) = 0.53 at the light: every camera ray hits the light.
rt::scene looking_at_light(const point3& from, const color& background) {
    auto world = std::make_shared<rt::hittable_list>();
    world->add(light_quad(radiance));
    auto cam          = std::make_shared<rt::thin_lens_camera>();
    cam->aspect_ratio = 1;
    cam->vfov         = 20;
    cam->lookfrom     = from;
    cam->lookat       = point3(0, 0, 0);
    rt::scene sc;
    sc.world          = world;
    sc.sky            = rt::background::uniform(background);
    sc.cam            = cam;
    sc.settings.width = 16;
    return sc;
}

struct view_check {
    int paths = 0, hits = 0, wrong = 0;
    std::string first_wrong;
};

// Traces every pixel of the scene's film x 4 samples through its path-traced render job and
// compares every path with `expected` bit for bit.
view_check trace_view(const rt::scene& sc, int max_depth, const color& expected) {
    const rt::render_job job = rt::path_trace(sc);
    const rt::film f         = rt::film::for_aspect(job.settings.width, job.cam->aspect_ratio);
    job.cam->initialize(f);
    view_check c;
    rt::independent_sampler s(7);
    for (int j = 0; j < f.height; ++j) {
        for (int i = 0; i < f.width; ++i) {
            for (int k = 0; k < 4; ++k) {
                s.start_pixel_sample(i, j, k);
                rt::ray r = job.cam->get_ray(i, j, s);
                rt::hit_record rec;
                ++c.paths;
                if (sc.world->hit(r, forward, rec)) ++c.hits;
                color L = job.estimator->radiance(r, s, max_depth);
                if (!exactly(L, expected) && c.wrong++ == 0) {
                    std::ostringstream what;
                    what << "pixel (" << i << ", " << j << ") sample " << k << " gave " << L;
                    c.first_wrong = what.str();
                }
            }
        }
    }
    return c;
}

// A texture that shows the (u, v) it is asked about, and p.z.
class uv_texture : public rt::texture {
  public:
    color value(real u, real v, const point3& p) const override { return color(u, v, p.z()); }
    bool uses_uv() const override { return true; }
};

}  // namespace

TEST_CASE("diffuse_light: a light quad seen from the front shows exactly its radiance", "[ch10]") {
    // Black background: anything but L means the light added or lost something.
    auto c = trace_view(looking_at_light(point3(0, 0, 3), color(0, 0, 0)), 50, radiance);
    INFO(c.wrong << " of " << c.paths << " paths wrong; first: " << c.first_wrong);
    CHECK(c.paths == 16 * 16 * 4);
    CHECK(c.hits == c.paths);
    CHECK(c.wrong == 0);
}

TEST_CASE("diffuse_light: a light quad seen from behind shows the same radiance (both faces)",
          "[ch10]") {
    // From z = -3 every ray hits the back face (front_face false), which emits too, as in book 2.
    auto sc = looking_at_light(point3(0, 0, -3), color(0, 0, 0));
    rt::hit_record rec;
    REQUIRE(sc.world->hit(rt::ray(point3(0, 0, -3), vec3(0, 0, 1)), forward, rec));
    CHECK_FALSE(rec.front_face);
    auto c = trace_view(sc, 50, radiance);
    INFO(c.wrong << " of " << c.paths << " paths wrong; first: " << c.first_wrong);
    CHECK(c.hits == c.paths);
    CHECK(c.wrong == 0);
}

TEST_CASE("diffuse_light: a light never scatters, so a bright background adds nothing to it",
          "[ch10]") {
    // Background 1: a light that scattered would add some of it to L (or the path would reach
    // it after a bounce). Only exactly L is right.
    for (const point3& from : {point3(0, 0, 3), point3(0, 0, -3)}) {
        auto c = trace_view(looking_at_light(from, color(1, 1, 1)), 50, radiance);
        INFO("camera at " << from << ": " << c.wrong << " of " << c.paths
                          << " paths wrong; first: " << c.first_wrong);
        CHECK(c.hits == c.paths);
        CHECK(c.wrong == 0);
    }

    // And asked directly, from either side, it absorbs and still emits.
    rt::diffuse_light light(radiance);
    rt::independent_sampler s(1);
    s.start_pixel_sample(0, 0, 0);
    auto quad = light_quad(radiance);
    for (real z : {real(2), real(-2)}) {
        rt::ray in(point3(0.25, 0.5, z), vec3(0, 0, -z));
        rt::hit_record rec;
        REQUIRE(quad->hit(in, forward, rec));
        CHECK_FALSE(light.scatter(in, rec, s));
        CHECK(exactly(light.emitted(in, rec), radiance));
    }
}

TEST_CASE("diffuse_light: with max_depth 1 the light is still seen (emission at the first hit)",
          "[ch10]") {
    for (const point3& from : {point3(0, 0, 3), point3(0, 0, -3)}) {
        auto c = trace_view(looking_at_light(from, color(0, 0, 0)), 1, radiance);
        INFO("camera at " << from << ": " << c.wrong << " of " << c.paths
                          << " paths wrong; first: " << c.first_wrong);
        CHECK(c.wrong == 0);
    }
    // max_depth 0 follows no segment, so it sees nothing at all.
    auto sc = looking_at_light(point3(0, 0, 3), color(0, 0, 0));
    const rt::path_tracer tracer(sc.world, sc.sky);
    rt::independent_sampler s(1);
    s.start_pixel_sample(0, 0, 0);
    CHECK(exactly(tracer.radiance(rt::ray(point3(0, 0, 3), vec3(0, 0, -1)), s, 0), color()));
}

TEST_CASE("diffuse_light: emission is added at every hit, weighted by the path's throughput",
          "[ch10]") {
    // A camera 1 above a horizontal mirror (albedo 0.5, no fuzz) looks straight down; the ray
    // reflects straight up into a light at y = 2 (a power-of-two albedo keeps 0.5 L exact).
    // Segment 1 hits the mirror (Le = 0), segment 2 the light: L = 0.5 * (4, 2, 1).
    auto world = std::make_shared<rt::hittable_list>();
    world->add(std::make_shared<rt::quad>(point3(-5, 0, -5), vec3(10, 0, 0), vec3(0, 0, 10),
                                          std::make_shared<rt::metal>(color(0.5, 0.5, 0.5), 0)));
    world->add(std::make_shared<rt::quad>(point3(-5, 2, -5), vec3(0, 0, 10), vec3(10, 0, 0),
                                          std::make_shared<rt::diffuse_light>(radiance)));
    const rt::path_tracer tracer(world, rt::background::uniform(color(0, 0, 0)));
    rt::independent_sampler s(3);
    s.start_pixel_sample(0, 0, 0);
    const rt::ray down(point3(0.25, 1, -0.5), vec3(0, -1, 0));
    CHECK(exactly(tracer.radiance(down, s, 50), color(2, 1, 0.5)));
    // With one segment the path ends on the mirror, before it reaches the light.
    CHECK(exactly(tracer.radiance(down, s, 1), color(0, 0, 0)));
    // Looking straight up, the light itself is seen at the first hit, unweighted.
    CHECK(exactly(tracer.radiance(rt::ray(point3(0.25, 1, -0.5), vec3(0, 1, 0)), s, 50), radiance));
}

TEST_CASE("diffuse_light: a textured light emits its texture's value at the hit's (u, v) and p",
          "[ch10]") {
    // The light quad's (u, v) are its plane coordinates: at (-1 + 2a, -1 + 2b, 0) they are
    // (a, b), from the front and from behind. Dyadic points: all exact.
    auto light = std::make_shared<rt::diffuse_light>(std::make_shared<uv_texture>());
    const rt::quad quad(point3(-1, -1, 0), vec3(2, 0, 0), vec3(0, 2, 0), light);
    for (const auto& [a, b] : {std::pair<real, real>(0.25, 0.75), {0.5, 0.125}, {0.875, 0.5}}) {
        for (real z : {real(3), real(-3)}) {
            CAPTURE(a, b, z);
            const rt::ray r(point3(-1 + 2 * a, -1 + 2 * b, z), vec3(0, 0, -z));
            rt::hit_record rec;
            REQUIRE(quad.hit(r, forward, rec));
            CHECK(exactly(light->emitted(r, rec), color(a, b, 0)));
        }
    }
}

TEST_CASE("diffuse_light: the path tracer shows a textured light's value at each point seen",
          "[ch10]") {
    // The same light and points as above, now through the integrator: the emission it adds
    // is the texture's value at the hit, from the front and from behind.
    auto light = std::make_shared<rt::diffuse_light>(std::make_shared<uv_texture>());
    auto world = std::make_shared<rt::hittable_list>();
    world->add(std::make_shared<rt::quad>(point3(-1, -1, 0), vec3(2, 0, 0), vec3(0, 2, 0), light));
    const rt::path_tracer tracer(world, rt::background::uniform(color(0, 0, 0)));
    rt::independent_sampler s(4);
    for (const auto& [a, b] : {std::pair<real, real>(0.25, 0.75), {0.5, 0.125}, {0.875, 0.5}}) {
        for (real z : {real(3), real(-3)}) {
            CAPTURE(a, b, z);
            s.start_pixel_sample(0, 0, 0);
            const rt::ray r(point3(-1 + 2 * a, -1 + 2 * b, z), vec3(0, 0, -z));
            CHECK(exactly(tracer.radiance(r, s, 50), color(a, b, 0)));
        }
    }
}

TEST_CASE("diffuse_light: negative, NaN or infinite radiance, or no texture, throws a user_error",
          "[ch10]") {
    const real nan = std::numeric_limits<real>::quiet_NaN();
    const real inf = std::numeric_limits<real>::infinity();
    for (const color& bad :
         {color(-1, 0, 0), color(0, real(-1e-30), 0), color(0, 0, -4), color(nan, 1, 1),
          color(1, nan, 1), color(1, 1, nan), color(inf, 1, 1)}) {
        INFO("radiance " << bad);
        CHECK_THROWS_AS(rt::diffuse_light(bad), rt::user_error);
    }
    CHECK_THROWS_WITH(rt::diffuse_light(color(-1, 0, 0)),
                      Catch::Contains("light radiance must be >= 0 and finite per channel, got"));
    CHECK_THROWS_AS(rt::diffuse_light(std::shared_ptr<rt::texture>()), rt::user_error);
    // Zero is a light that is off, and large values are bright lights: both allowed.
    CHECK_NOTHROW(rt::diffuse_light(color(0, 0, 0)));
    CHECK_NOTHROW(rt::diffuse_light(color(1e6, 15, 0)));
}
