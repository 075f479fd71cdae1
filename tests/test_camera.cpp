// camera (common/camera.h): which ray each pixel sample gets. Chapter 01 (pinhole, viewport,
// settings), chapter 06 (positionable camera, thin lens), chapter 07 (shutter time).
// The camera draws sampler dimensions 0-1 (jitter), 2-3 (lens), 4 (time); a copy of the sampler
// taken before get_ray replays those numbers, so the expected ray can be computed exactly.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

#include "common/camera.h"
#include "common/error.h"
#include "test_helpers.h"

using Catch::Matchers::Contains;
using rt::point3;
using rt::real;
using rt::vec3;

namespace {

constexpr real eps = std::numeric_limits<real>::epsilon();

// Bit-for-bit equality of vectors (rt_test::exactly), under the name the checks read best with.
bool (&equal)(const vec3&, const vec3&) = rt_test::exactly;

struct traced {
    rt::ray r;
    rt::sample2 jitter;  // the sampler's dimensions 0-1 for this ray
    real time_u;         // dimension 4
};

traced trace(const rt::camera& cam, int i, int j, int sample_index, std::uint64_t seed = 1) {
    rt::sampler s(seed);
    s.start_pixel_sample(i, j, sample_index);
    rt::sampler replay = s;
    traced t{cam.get_ray(i, j, s), replay.next_2d(), 0};
    replay.next_2d();  // the lens position
    t.time_u = replay.next_1d();
    return t;
}

// The message of the user_error that initialize() throws, or "" (and a failed check) if none.
std::string initialize_error(rt::camera cam) {
    try {
        cam.initialize();
    } catch (const rt::user_error& e) {
        return e.what();
    }
    FAIL_CHECK("initialize() accepted invalid settings");
    return "";
}

// Where ray r meets the plane through p with unit normal n.
point3 hit_plane(const rt::ray& r, const point3& p, const vec3& n) {
    return r.at(dot(p - r.origin(), n) / dot(r.direction(), n));
}

}  // namespace

TEST_CASE("camera: image height is width / aspect rounded down, at least 1", "[camera][ch01]") {
    // The aspect ratio is a double in every build, so 400 / (16/9) is 225 rows as in the book
    // (in float, 16/9 rounds up and the quotient would fall to 224.99998).
    struct size_case {
        int width;
        double aspect;
    };
    for (size_case c :
         {size_case{400, 16.0 / 9}, size_case{1920, 16.0 / 9}, size_case{401, 2}, size_case{7, 1},
          size_case{1, 16.0 / 9}, size_case{10, 100}, size_case{3, 0.5}}) {
        rt::camera cam;
        cam.image_width  = c.width;
        cam.aspect_ratio = c.aspect;
        cam.initialize();
        CAPTURE(c.width, c.aspect);
        CHECK(cam.image_height() == std::max(1, int(double(c.width) / c.aspect)));
    }
    rt::camera cam;
    cam.image_width = 1;
    cam.initialize();
    CHECK(cam.image_height() == 1);  // int(0.5625) = 0, kept at one row
    // The book's 400 x 225, in both builds.
    rt::camera book;
    book.initialize();
    CHECK(book.image_height() == 225);
}

TEST_CASE("camera: the default ray through the image centre points along -z", "[camera][ch01]") {
    // Default: 400 wide at 16:9, vfov 90 at focus distance 1, so the viewport is 2 high and
    // 2 * 400 / 225 wide. Pixel (200, 112) has the image centre at the middle of its left edge,
    // so its ray leaves -z by exactly the jitter's offset from that point: (u du, (1/2 - v) dv).
    // Each coordinate passes through about six roundings of values below 2: 16 eps absolute.
    rt::camera cam;
    cam.initialize();
    REQUIRE(cam.image_height() == std::max(1, int(real(400) / (real(16) / 9))));
    const int h    = cam.image_height();
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
    cam.initialize();
    const int w = cam.image_width, h = cam.image_height();
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

TEST_CASE("camera: a positioned camera looks at lookat with vup up", "[camera][ch06]") {
    // An odd square image: pixel (50, 50) contains the image centre, so its ray meets the focus
    // plane (through lookat, facing the camera) within half a pixel diagonal of lookat, give or
    // take the rounding of points about |lookfrom - lookat| = 5.8 from the origin (64 eps * 6).
    rt::camera cam;
    cam.image_width  = 101;
    cam.aspect_ratio = 1;
    cam.vfov         = 20;
    cam.lookfrom     = point3(3, 3, 2);
    cam.lookat       = point3(0, 0, -1);
    cam.vup          = vec3(0, 1, 0);
    cam.initialize();
    REQUIRE(cam.image_height() == 101);

    const vec3 forward = rt::unit_vector(cam.lookat - cam.lookfrom);
    const vec3 right   = rt::unit_vector(cross(forward, cam.vup));
    const vec3 up      = cross(right, forward);
    const real focus   = (cam.lookat - cam.lookfrom).length();
    const real pixel   = 2 * std::tan(rt::degrees_to_radians(cam.vfov) / 2) * focus / 101;
    for (int k = 0; k < 8; ++k) {
        const traced centre = trace(cam, 50, 50, k);
        CHECK(equal(centre.r.origin(), cam.lookfrom));
        const point3 p = hit_plane(centre.r, cam.lookat, forward);
        CAPTURE(k, p);
        CHECK((p - cam.lookat).length() <= real(0.5) * std::sqrt(real(2)) * pixel + 64 * eps * 6);

        // The top row is above lookat along the projected vup, the left column to its left.
        const point3 top  = hit_plane(trace(cam, 50, 0, k).r, cam.lookat, forward);
        const point3 left = hit_plane(trace(cam, 0, 50, k).r, cam.lookat, forward);
        CHECK(dot(top - cam.lookat, up) > 49 * pixel);
        CHECK(dot(left - cam.lookat, right) < -49 * pixel);
    }
}

TEST_CASE("camera: invalid settings throw user_error naming the bad value", "[camera][ch01]") {
    rt::camera same;
    same.lookfrom = point3(1, 2, 3);
    same.lookat   = point3(1, 2, 3);
    CHECK_THAT(initialize_error(same), Contains("lookfrom") && Contains("(1, 2, 3)"));

    rt::camera parallel;
    parallel.vup = vec3(0, 0, 5);  // the default view is along -z
    CHECK_THAT(initialize_error(parallel), Contains("vup") && Contains("(0, 0, 5)"));

    rt::camera zero_fov;
    zero_fov.vfov = 0;
    CHECK_THAT(initialize_error(zero_fov), Contains("vfov") && Contains("got 0"));

    rt::camera flat_fov;
    flat_fov.vfov = 180;
    CHECK_THAT(initialize_error(flat_fov), Contains("vfov") && Contains("got 180"));

    rt::camera nan_fov;
    nan_fov.vfov = std::numeric_limits<real>::quiet_NaN();
    CHECK_THAT(initialize_error(nan_fov), Contains("vfov") && Contains("nan"));

    rt::camera negative_aperture;
    negative_aperture.aperture = real(-0.5);
    CHECK_THAT(initialize_error(negative_aperture), Contains("aperture") && Contains("got -0.5"));

    rt::camera no_width;
    no_width.image_width = 0;
    CHECK_THAT(initialize_error(no_width), Contains("width") && Contains("got 0"));

    rt::camera backwards_shutter;
    backwards_shutter.shutter_open  = 2;
    backwards_shutter.shutter_close = 1;
    CHECK_THAT(initialize_error(backwards_shutter), Contains("shutter") && Contains("got 2"));

    // The valid extremes are accepted.
    rt::camera edge;
    edge.vfov        = 179;
    edge.image_width = 1;
    edge.aperture    = 0;
    CHECK_NOTHROW(edge.initialize());
    edge.vfov = 1;
    CHECK_NOTHROW(edge.initialize());
}

TEST_CASE("camera: lens rays start on the lens disk and meet at the focus plane",
          "[camera][ch06]") {
    // Thin lens: origins uniform on a disk of radius aperture/2 about lookfrom, in the plane
    // facing the view; every ray of one pixel sample passes through the point the pinhole ray
    // of the same jitter would hit on the focus plane, which is what keeps that plane sharp.
    rt::camera lens;
    lens.image_width = 64;
    lens.lookfrom    = point3(3, 1, 2);
    lens.lookat      = point3(0, 0, 0);
    lens.aperture    = 2;
    lens.initialize();
    rt::camera pinhole = lens;
    pinhole.aperture   = 0;
    pinhole.initialize();

    const vec3 w = rt::unit_vector(lens.lookfrom - lens.lookat);
    // Origins are within |lookfrom| + radius ~ 4.7 of the origin and focus points within ~7.6
    // (the viewport's corner); each coordinate carries a handful of roundings, the plane
    // intersection a handful more: 64 eps * 10 absolute.
    const real tol = 64 * eps * 10;
    real widest    = 0;
    int errors     = 0;
    for (int k = 0; k < 10000; ++k) {
        const int i = k % 64, j = (k / 64) % lens.image_height();
        const traced t    = trace(lens, i, j, k);
        const traced pin  = trace(pinhole, i, j, k);
        const vec3 offset = t.r.origin() - lens.lookfrom;
        widest            = std::max(widest, offset.length());
        const point3 a = hit_plane(t.r, lens.lookat, w), b = hit_plane(pin.r, lens.lookat, w);
        if (!(offset.length() <= 1 + tol && std::fabs(dot(offset, w)) <= tol &&
              (a - b).length() <= tol)) {
            UNSCOPED_INFO("pixel (" << i << ", " << j << ") sample " << k << ": origin offset "
                                    << offset << ", focus points " << a << " vs " << b);
            ++errors;
        }
    }
    CHECK(errors == 0);
    // 10000 uniform disk samples all inside radius 0.99 has probability 0.98^10000 ~ 1e-88:
    // this catches a lens that is ignored or shrunk.
    CHECK(widest > real(0.99));
}

TEST_CASE("camera: aperture 0 gives the pinhole's rays bit for bit", "[camera][ch06]") {
    rt::camera pinhole;
    pinhole.initialize();
    rt::camera thin_lens;
    thin_lens.aperture   = 0;
    thin_lens.focus_dist = 1;  // |lookfrom - lookat|, the pinhole's own focus distance
    thin_lens.initialize();
    rt::camera wide = thin_lens;
    wide.aperture   = real(0.5);
    wide.initialize();

    for (int k = 0; k < 1000; ++k) {
        const int i = (k * 37) % 400, j = (k * 11) % pinhole.image_height();
        rt::sampler a(3), b(3), c(3);
        a.start_pixel_sample(i, j, k);
        b.start_pixel_sample(i, j, k);
        c.start_pixel_sample(i, j, k);
        const rt::ray ra = pinhole.get_ray(i, j, a), rb = thin_lens.get_ray(i, j, b);
        wide.get_ray(i, j, c);
        CAPTURE(i, j, k);
        CHECK(equal(ra.origin(), pinhole.lookfrom));
        CHECK(equal(rb.origin(), ra.origin()));
        CHECK(equal(rb.direction(), ra.direction()));
        CHECK(rb.time() == ra.time());
        // Every camera draws the same five dimensions, so what follows (the first bounce) sees
        // the same numbers whatever the lens.
        const real next = a.next_1d();
        CHECK(b.next_1d() == next);
        CHECK(c.next_1d() == next);
    }
}

TEST_CASE("camera: ray times are uniform from shutter_open up to shutter_close", "[camera][ch07]") {
    rt::camera cam;
    cam.shutter_open  = real(0.25);
    cam.shutter_close = real(0.75);
    cam.initialize();
    real earliest = 1, latest = 0;
    int errors = 0;
    for (int k = 0; k < 10000; ++k) {
        const traced t  = trace(cam, k % 400, k % 225, k);
        const real time = t.r.time();
        earliest        = std::min(earliest, time);
        latest          = std::max(latest, time);
        // Dimension 4 scaled to the shutter interval, exactly as documented.
        if (!(time >= real(0.25) && time < real(0.75) &&
              time == real(0.25) + t.time_u * real(0.5))) {
            UNSCOPED_INFO("sample " << k << ": time " << time << " from u = " << t.time_u);
            ++errors;
        }
    }
    CHECK(errors == 0);
    // The ends are reached: 10000 uniform times all missing the first or last 1% has
    // probability 2 * 0.99^10000 ~ 1e-43.
    CHECK(earliest < real(0.255));
    CHECK(latest > real(0.745));

    rt::camera instant;
    instant.shutter_open  = real(0.5);
    instant.shutter_close = real(0.5);
    instant.initialize();
    CHECK(trace(instant, 10, 10, 0).r.time() == real(0.5));
}

TEST_CASE("camera: a shutter outside [0, 1] is refused", "[camera][ch07]") {
    // Moving spheres are defined, and bounded for the BVH, only for times in [0, 1]: a longer
    // shutter would silently clip their blur.
    struct shutter_case {
        real open, close;
    };
    for (shutter_case c : {shutter_case{0, 2}, shutter_case{-0.5, 0.5}, shutter_case{0.7, 0.2},
                           shutter_case{0, rt::infinity}}) {
        rt::camera cam;
        cam.shutter_open  = c.open;
        cam.shutter_close = c.close;
        CAPTURE(c.open, c.close);
        CHECK_THROWS_AS(cam.initialize(), rt::user_error);
    }
    rt::camera instant;
    instant.shutter_open = instant.shutter_close = real(0.25);
    CHECK_NOTHROW(instant.initialize());
}
