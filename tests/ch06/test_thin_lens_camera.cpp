// thin_lens_camera (rt/camera/thin_lens_camera.h): a camera that stands anywhere and focuses like a
// thin lens. Chapter 06. (Its shutter is chapter 07's.)
// It draws sampler dimensions 0-1 (jitter), then 2-3 (the lens) only when aperture > 0; a copy
// of the sampler taken before get_ray replays those numbers, so the expected ray can be computed.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "ch01/camera_helpers.h"
#include "rt/camera/camera.h"
#include "rt/camera/thin_lens_camera.h"
#include "rt/core/error.h"
#include "rt/render/film.h"
#include "rt/samplers/independent_sampler.h"
#include "rt/samplers/sampling.h"
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
    rt::sample2 lens;    // dimensions 2-3
};

traced trace(const rt::camera& cam, int i, int j, int sample_index, std::uint64_t seed = 1) {
    rt::independent_sampler s(seed);
    s.start_pixel_sample(i, j, sample_index);
    rt::independent_sampler replay = s;
    traced t{cam.get_ray(i, j, s), replay.next_2d(), {0, 0}};
    t.lens = replay.next_2d();
    return t;
}

// Where ray r meets the plane through p with unit normal n.
point3 hit_plane(const rt::ray& r, const point3& p, const vec3& n) {
    return r.at(dot(p - r.origin(), n) / dot(r.direction(), n));
}

}  // namespace

TEST_CASE("thin_lens_camera: a positioned camera looks at lookat with vup up", "[camera][ch06]") {
    // An odd square image: pixel (50, 50) contains the image centre, so its ray meets the focus
    // plane (through lookat, facing the camera) within half a pixel diagonal of lookat, give or
    // take the rounding of points about |lookfrom - lookat| = 5.8 from the origin (64 eps * 6).
    const rt::film f = rt::film::for_aspect(101, 1);
    REQUIRE(f.height == 101);
    rt::thin_lens_camera cam;
    cam.aspect_ratio = 1;
    cam.vfov         = 20;
    cam.lookfrom     = point3(3, 3, 2);
    cam.lookat       = point3(0, 0, -1);
    cam.vup          = vec3(0, 1, 0);
    cam.initialize(f);

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

TEST_CASE("thin_lens_camera: invalid settings throw user_error naming the bad value",
          "[camera][ch06]") {
    rt::thin_lens_camera same;
    same.lookfrom = point3(1, 2, 3);
    same.lookat   = point3(1, 2, 3);
    CHECK_THAT(initialize_error(same), Contains("lookfrom") && Contains("(1, 2, 3)"));

    rt::thin_lens_camera parallel;
    parallel.vup = vec3(0, 0, 5);  // the default view is along -z
    CHECK_THAT(initialize_error(parallel), Contains("vup") && Contains("(0, 0, 5)"));

    rt::thin_lens_camera negative_aperture;
    negative_aperture.aperture = real(-0.5);
    CHECK(initialize_error(negative_aperture) ==
          "camera aperture must be >= 0 and finite, got -0.5");

    rt::thin_lens_camera infinite_aperture;
    infinite_aperture.aperture = rt::infinity;
    CHECK_THAT(initialize_error(infinite_aperture), Contains("aperture") && Contains("inf"));

    rt::thin_lens_camera negative_focus;
    negative_focus.focus_dist = -2;
    CHECK_THAT(initialize_error(negative_focus), Contains("focus distance") && Contains("got -2"));

    rt::thin_lens_camera nan_focus;
    nan_focus.focus_dist = std::numeric_limits<real>::quiet_NaN();
    CHECK_THAT(initialize_error(nan_focus), Contains("focus distance") && Contains("nan"));

    // Its field of view is checked as chapter 01's camera checks it.
    rt::thin_lens_camera zero_fov;
    zero_fov.vfov = 0;
    CHECK(initialize_error(zero_fov) == "camera vfov must be in (0, 180) degrees, got 0");
    rt::thin_lens_camera flat_fov;
    flat_fov.vfov = 180;
    CHECK_THAT(initialize_error(flat_fov), Contains("vfov") && Contains("got 180"));

    // The valid extremes are accepted.
    rt::thin_lens_camera edge;
    edge.vfov       = 179;
    edge.aperture   = 0;
    edge.focus_dist = 0;  // means |lookfrom - lookat|
    CHECK_NOTHROW(edge.initialize(rt::film::for_aspect(1, edge.aspect_ratio)));
    edge.vfov = 1;
    CHECK_NOTHROW(edge.initialize(book_film));
}

TEST_CASE("thin_lens_camera: lens rays start on the lens disk and meet at the focus plane",
          "[camera][ch06]") {
    // Thin lens: origins uniform on a disk of radius aperture/2 about lookfrom, in the plane
    // facing the view, at the disk point that dimensions 2-3 choose; every ray of one pixel
    // sample passes through the point the pinhole ray of the same jitter would hit on the focus
    // plane, which is what keeps that plane sharp.
    const rt::film f = rt::film::for_aspect(64, 16.0 / 9);
    rt::thin_lens_camera lens;
    lens.lookfrom = point3(3, 1, 2);
    lens.lookat   = point3(0, 0, 0);
    lens.aperture = 2;
    lens.initialize(f);
    rt::thin_lens_camera pinhole = lens;
    pinhole.aperture             = 0;
    pinhole.initialize(f);

    const vec3 w = rt::unit_vector(lens.lookfrom - lens.lookat);
    const vec3 u = rt::unit_vector(cross(lens.vup, w)), v = cross(w, u);
    // Origins are within |lookfrom| + radius ~ 4.7 of the origin and focus points within ~7.6
    // (the viewport's corner); each coordinate carries a handful of roundings, the plane
    // intersection a handful more: 64 eps * 10 absolute.
    const real tol = 64 * eps * 10;
    real widest    = 0;
    int errors     = 0;
    for (int k = 0; k < 10000; ++k) {
        const int i = k % 64, j = (k / 64) % f.height;
        const traced t    = trace(lens, i, j, k);
        const traced pin  = trace(pinhole, i, j, k);
        const vec3 offset = t.r.origin() - lens.lookfrom;
        widest            = std::max(widest, offset.length());
        const point3 a = hit_plane(t.r, lens.lookat, w), b = hit_plane(pin.r, lens.lookat, w);
        const vec3 disk    = rt::sample_uniform_disk(t.lens);
        const vec3 on_lens = disk.x() * u + disk.y() * v;  // radius 1 = aperture / 2
        if (!(offset.length() <= 1 + tol && std::fabs(dot(offset, w)) <= tol &&
              (offset - on_lens).length() <= tol && (a - b).length() <= tol)) {
            UNSCOPED_INFO("pixel (" << i << ", " << j << ") sample " << k << ": origin offset "
                                    << offset << " (lens point " << on_lens << "), focus points "
                                    << a << " vs " << b);
            ++errors;
        }
    }
    CHECK(errors == 0);
    // 10000 uniform disk samples all inside radius 0.99 has probability 0.98^10000 ~ 1e-88:
    // this catches a lens that is ignored or shrunk.
    CHECK(widest > real(0.99));
}

TEST_CASE("thin_lens_camera: focus_dist moves the sharp plane", "[camera][ch06]") {
    // With focus_dist set, the rays of one pixel sample meet on the plane at that distance, not
    // at lookat: an object there is sharp, lookat itself blurred. Each lens ray is compared with
    // the pinhole ray of the same jitter, through the same point of the focus plane.
    const rt::film f = rt::film::for_aspect(32, 1);
    rt::thin_lens_camera cam;
    cam.aspect_ratio = 1;
    cam.lookfrom     = point3(0, 0, 0);
    cam.lookat       = point3(0, 0, -10);
    cam.aperture     = 1;
    cam.focus_dist   = 3;
    cam.initialize(f);
    rt::thin_lens_camera pinhole = cam;
    pinhole.aperture             = 0;
    pinhole.initialize(f);

    const vec3 w(0, 0, 1);
    const point3 focus_plane(0, 0, -3), lookat_plane(0, 0, -10);
    real spread_at_focus = 0, spread_at_lookat = 0;
    for (int k = 0; k < 200; ++k) {
        const traced t = trace(cam, 10, 20, k), p = trace(pinhole, 10, 20, k);
        spread_at_focus =
            std::max(spread_at_focus,
                     (hit_plane(t.r, focus_plane, w) - hit_plane(p.r, focus_plane, w)).length());
        spread_at_lookat =
            std::max(spread_at_lookat,
                     (hit_plane(t.r, lookat_plane, w) - hit_plane(p.r, lookat_plane, w)).length());
    }
    // Coordinates up to ~10, a handful of roundings each.
    const real tol = 64 * eps * 10;
    CHECK(spread_at_focus <= tol);
    // A lens point at radius r <= 1/2 puts the ray r (10 - 3) / 3 from the pinhole ray at
    // distance 10: at most 7/6. 200 uniform lens points all within 0.943 of the rim's radius
    // (spread below 1.1) has probability 0.889^200 ~ 6e-11.
    CHECK(spread_at_lookat > real(1.1));
    CHECK(spread_at_lookat <= real(7) / 6 + tol);
}

TEST_CASE("thin_lens_camera: aperture 0 draws 2 sampler dimensions, aperture > 0 draws 4",
          "[camera][ch06][draw-order]") {
    // A scene pays only for what its camera has (sampler.h): a pinhole-like thin lens leaves
    // the first bounce the same dimension as chapter 01's camera does.
    rt::thin_lens_camera pinhole;
    pinhole.lookfrom = point3(1, 2, 3);
    pinhole.lookat   = point3(-1, 0, -4);
    pinhole.initialize(book_film);
    rt::thin_lens_camera lens = pinhole;
    lens.aperture             = real(0.5);
    lens.initialize(book_film);
    int wrong_pinhole = 0, wrong_lens = 0;
    for (int k = 0; k < 1000; ++k) {
        const int i = (k * 37) % 400, j = (k * 11) % 225;
        rt::independent_sampler a(3), b(3);
        a.start_pixel_sample(i, j, k);
        b.start_pixel_sample(i, j, k);
        pinhole.get_ray(i, j, a);
        lens.get_ray(i, j, b);
        if (a.next_1d() != rt_test::next_after_draws(3, i, j, k, 2)) ++wrong_pinhole;
        if (b.next_1d() != rt_test::next_after_draws(3, i, j, k, 4)) ++wrong_lens;
    }
    CHECK(wrong_pinhole == 0);
    CHECK(wrong_lens == 0);
}

TEST_CASE(
    "thin_lens_camera: aperture 0 at the origin looking down -z is chapter 01's camera, "
    "bit for bit",
    "[camera][ch06]") {
    // The same vfov and film: the same viewport, laid the same way, and the same jitter.
    rt::camera first;
    first.vfov = 70;
    first.initialize(book_film);
    rt::thin_lens_camera thin_lens;
    thin_lens.vfov     = 70;
    thin_lens.lookfrom = point3(0, 0, 0);
    thin_lens.lookat   = point3(0, 0, -1);
    thin_lens.vup      = vec3(0, 1, 0);
    thin_lens.aperture = 0;
    thin_lens.initialize(book_film);

    int differ = 0;
    for (int k = 0; k < 1000; ++k) {
        const int i = (k * 37) % 400, j = (k * 11) % 225;
        rt::independent_sampler a(3), b(3);
        a.start_pixel_sample(i, j, k);
        b.start_pixel_sample(i, j, k);
        const rt::ray ra = first.get_ray(i, j, a), rb = thin_lens.get_ray(i, j, b);
        if (!equal(rb.origin(), ra.origin()) || !equal(rb.direction(), ra.direction())) {
            UNSCOPED_INFO("pixel (" << i << ", " << j << ") sample " << k << ": " << rb.direction()
                                    << " vs " << ra.direction());
            ++differ;
        }
    }
    CHECK(differ == 0);
    // Chapter 01's camera really stands at the origin.
    CHECK(equal(trace(first, 0, 0, 0).r.origin(), point3(0, 0, 0)));
}
