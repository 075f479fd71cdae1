// camera (rt/camera/camera.h): which ray each pixel sample gets from chapter 01's pinhole at the
// origin, looking down -z. Chapter 01 (chapter 06's thin_lens_camera is tested in its folder).
// The camera draws sampler dimensions 0-1 (the jitter) and no more; a copy of the sampler taken
// before get_ray replays them, so the expected ray can be computed exactly.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>

#include "ch01/camera_helpers.h"
#include "rt/camera/camera.h"
#include "rt/core/error.h"
#include "rt/render/film.h"
#include "rt/samplers/independent_sampler.h"
#include "test_helpers.h"

using Catch::Matchers::Contains;
using rt::point3;
using rt::real;
using rt::vec3;

using rt_test::book_film;
using rt_test::eps;
using rt_test::initialize_error;

namespace {

// Bit-for-bit equality of vectors (rt_test::exactly), under the name the checks read best with.
bool (&equal)(const vec3&, const vec3&) = rt_test::exactly;

struct traced {
    rt::ray r;
    rt::sample2 jitter;  // the sampler's dimensions 0-1 for this ray
};

traced trace(const rt::camera& cam, int i, int j, int sample_index, std::uint64_t seed = 1) {
    rt::independent_sampler s(seed);
    s.start_pixel_sample(i, j, sample_index);
    rt::independent_sampler replay = s;
    return {cam.get_ray(i, j, s), replay.next_2d()};
}

}  // namespace

TEST_CASE("camera: the default ray through the image centre points along -z", "[camera][ch01]") {
    // Default: vfov 90 at distance 1 on the book's 400 x 225 film, so the viewport is 2 high and
    // 2 * 400 / 225 wide. Pixel (200, 112) has the image centre at the middle of its left edge,
    // so its ray leaves -z by exactly the jitter's offset from that point: (u du, (1/2 - v) dv).
    // Each coordinate passes through about six roundings of values below 2: 16 eps absolute.
    rt::camera cam;
    cam.initialize(book_film);
    const int h = book_film.height;
    REQUIRE(h == 225);
    const double W = 2.0 * 400 / h, H = 2.0;
    const double du = W / 400, dv = H / h;
    const double tol = 16 * double(eps);
    for (int k = 0; k < 16; ++k) {
        traced t = trace(cam, 200, h / 2, k);
        CAPTURE(k, t.r.direction(), t.jitter.u, t.jitter.v);
        CHECK(equal(t.r.origin(), point3(0, 0, 0)));
        const double expected_y =
            h % 2 ? (0.5 - double(t.jitter.v)) * dv : -double(t.jitter.v) * dv;
        CHECK(std::fabs(double(t.r.direction().x()) - double(t.jitter.u) * du) <= tol);
        CHECK(std::fabs(double(t.r.direction().y()) - expected_y) <= tol);
        CHECK(std::fabs(double(t.r.direction().z()) + 1) <= tol);
    }
}

TEST_CASE("camera: corner pixels look at the corners of the field of view", "[camera][ch01]") {
    // Pixel (i, j) covers [i, i+1) x [j, j+1) of the viewport, whose top-left corner is at
    // (-W/2, H/2, -1): the ray is (-W/2 + (i + u) du, H/2 - (j + v) dv, -1). vfov = 90 puts the
    // top edge at 45 degrees: H/2 = tan(45) = 1. Coordinates up to 2, i up to 400: 64 eps.
    rt::camera cam;
    cam.initialize(book_film);
    const int w = book_film.width, h = book_film.height;
    const double W = 2.0 * w / h, H = 2.0;
    const double tol = 64 * double(eps);
    for (auto [i, j] :
         {std::pair{0, 0}, std::pair{w - 1, 0}, std::pair{0, h - 1}, std::pair{w - 1, h - 1}}) {
        for (int k = 0; k < 4; ++k) {
            traced t       = trace(cam, i, j, k);
            const double x = -W / 2 + (i + double(t.jitter.u)) * W / w;
            const double y = H / 2 - (j + double(t.jitter.v)) * H / h;
            CAPTURE(i, j, k, t.r.direction(), x, y);
            CHECK(std::fabs(double(t.r.direction().x()) - x) <= tol);
            CHECK(std::fabs(double(t.r.direction().y()) - y) <= tol);
            CHECK(std::fabs(double(t.r.direction().z()) + 1) <= tol);
            // Left pixels look left, top pixels look up, all within the 45-degree half-angle.
            CHECK((i == 0 ? x < 0 : x > 0));
            CHECK((j == 0 ? y > 0 : y < 0));
            CHECK(std::fabs(y) <= 1 + tol);
        }
    }
}

TEST_CASE("camera: the field of view sets the viewport's height", "[camera][ch01]") {
    // The top edge of the image is vfov / 2 above the axis: the top-left corner of pixel (i, 0)
    // with jitter (0, 0) lies at height tan(vfov / 2) at distance 1. A jitter of (u, v) moves it
    // by v rows down; the ray through it, divided by its own -z, must show that height.
    const rt::film f = rt::film::for_aspect(64, 1);
    for (real vfov : {real(10), real(40), real(90), real(150)}) {
        rt::camera cam;
        cam.aspect_ratio = 1;
        cam.vfov         = vfov;
        cam.initialize(f);
        const double half_height = std::tan(double(rt::degrees_to_radians(vfov)) / 2);
        for (int k = 0; k < 8; ++k) {
            const traced t   = trace(cam, 5, 0, k);
            const double top = half_height - double(t.jitter.v) * 2 * half_height / 64;
            const double y   = double(t.r.direction().y()) / -double(t.r.direction().z());
            CAPTURE(vfov, k, t.r.direction(), top);
            // Values up to tan(75) = 3.7 with a handful of roundings each: 64 eps * 4.
            CHECK(std::fabs(y - top) <= 64 * double(eps) * 4);
        }
    }
}

TEST_CASE("camera: get_ray draws exactly 2 sampler dimensions, the jitter",
          "[camera][ch01][draw-order]") {
    // What the estimator draws next (the first bounce) must be the sampler's dimension 2: a
    // camera that drew more or fewer would move every later random choice (sampler.h).
    rt::camera cam;
    cam.initialize(book_film);
    int wrong = 0;
    for (int k = 0; k < 1000; ++k) {
        const int i = (k * 37) % 400, j = (k * 11) % 225;
        rt::independent_sampler s(3);
        s.start_pixel_sample(i, j, k);
        cam.get_ray(i, j, s);
        if (s.next_1d() != rt_test::next_after_draws(3, i, j, k, 2)) ++wrong;
    }
    CHECK(wrong == 0);
}

TEST_CASE("camera: a vfov outside (0, 180) degrees throws a user_error naming it",
          "[camera][ch01]") {
    rt::camera zero_fov;
    zero_fov.vfov = 0;
    CHECK(initialize_error(zero_fov) == "camera vfov must be in (0, 180) degrees, got 0");

    rt::camera flat_fov;
    flat_fov.vfov = 180;
    CHECK_THAT(initialize_error(flat_fov), Contains("vfov") && Contains("got 180"));

    rt::camera negative_fov;
    negative_fov.vfov = -30;
    CHECK_THAT(initialize_error(negative_fov), Contains("vfov") && Contains("got -30"));

    rt::camera nan_fov;
    nan_fov.vfov = std::numeric_limits<real>::quiet_NaN();
    CHECK_THAT(initialize_error(nan_fov), Contains("vfov") && Contains("nan"));

    // The valid extremes are accepted, on the smallest film too.
    rt::camera edge;
    edge.vfov = 179;
    CHECK_NOTHROW(edge.initialize(rt::film::for_aspect(1, edge.aspect_ratio)));
    edge.vfov = 1;
    CHECK_NOTHROW(edge.initialize(rt::film::for_aspect(1, edge.aspect_ratio)));
}
