// Tests for thin_lens_camera.h, chapter 07's shutter: with shutter_close > shutter_open each ray
// gets an instant uniform in [open, close), drawn as one sampler dimension after the jitter (2)
// and the lens (2, only with an aperture); with open == close no dimension is drawn and every ray
// is at that one instant. A copy of the sampler taken before get_ray replays its numbers, so the
// expected ray and the sampler's position afterwards are known exactly.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "ch01/camera_helpers.h"
#include "rt/camera/thin_lens_camera.h"
#include "rt/core/error.h"
#include "rt/render/film.h"
#include "rt/samplers/independent_sampler.h"
#include "test_helpers.h"

using rt_test::book_film;
using rt_test::eps;
using rt_test::initialize_error;

namespace {

using rt::point3, rt::real, rt::vec3;

using rt_test::exactly;

struct traced {
    rt::ray r;
    real time_u;  // the dimension after the jitter (and the lens, if any)
    real next;    // the sampler's next number after get_ray: where the camera left it
};

traced trace(const rt::thin_lens_camera& cam, int i, int j, int sample_index,
             std::uint64_t seed = 1) {
    rt::independent_sampler s(seed);
    s.start_pixel_sample(i, j, sample_index);
    rt::independent_sampler replay = s;
    traced t{cam.get_ray(i, j, s), 0, 0};
    replay.next_2d();                        // the jitter
    if (cam.aperture > 0) replay.next_2d();  // the lens position
    t.time_u = replay.next_1d();
    t.next   = s.next_1d();
    return t;
}

}  // namespace

TEST_CASE("thin_lens_camera: ray times are uniform from shutter_open up to shutter_close",
          "[camera][ch07]") {
    rt::thin_lens_camera cam;
    cam.shutter_open  = real(0.25);
    cam.shutter_close = real(0.75);
    cam.initialize(book_film);
    real earliest = 1, latest = 0;
    int errors = 0;
    for (int k = 0; k < 10000; ++k) {
        const traced t  = trace(cam, k % 400, k % 225, k);
        const real time = t.r.time();
        earliest        = std::min(earliest, time);
        latest          = std::max(latest, time);
        // The dimension after the jitter, scaled to the shutter interval, as documented.
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

    // A shutter open for an instant photographs that instant.
    rt::thin_lens_camera instant;
    instant.shutter_open  = real(0.5);
    instant.shutter_close = real(0.5);
    instant.initialize(book_film);
    for (int k = 0; k < 16; ++k) CHECK(trace(instant, 10, 10, k).r.time() == real(0.5));
    // The default shutter (0, 0): every ray at time 0.
    rt::thin_lens_camera still;
    still.initialize(book_film);
    CHECK(trace(still, 10, 10, 0).r.time() == 0);
}

TEST_CASE(
    "thin_lens_camera: an open shutter draws exactly one more dimension, after the jitter "
    "and the lens, and its time is at least open and below close",
    "[camera][ch07][draw-order]") {
    // For a pinhole and for a lens, the same pixel samples with the shutter closed (open ==
    // close, drawing nothing) and open: the open camera leaves the sampler exactly one number
    // further on, and its origin and direction are those of the closed camera bit for bit (the
    // time comes last, so the jitter and the lens see the same numbers).
    rt::pcg32 rng(74, 5);
    for (real aperture : {real(0), real(0.5)}) {
        CAPTURE(aperture);
        int misplaced = 0, moved = 0, outside = 0;
        for (int k = 0; k < 2000; ++k) {
            // Random shutters within [0, 1], at least 1e-3 long, some reaching 0 or 1.
            real open  = k % 5 == 0 ? real(0) : rng.uniform();
            real close = k % 7 == 0 ? real(1) : rng.uniform();
            if (open > close) std::swap(open, close);
            if (close - open < real(1e-3)) continue;

            rt::thin_lens_camera closed_cam;
            closed_cam.lookfrom           = point3(1, 2, 3);
            closed_cam.lookat             = point3(0, 0, -1);
            closed_cam.aperture           = aperture;
            closed_cam.focus_dist         = 4;
            closed_cam.shutter_open       = open;
            closed_cam.shutter_close      = open;
            rt::thin_lens_camera open_cam = closed_cam;
            open_cam.shutter_close        = close;
            closed_cam.initialize(book_film);
            open_cam.initialize(book_film);

            const int i = k % 400, j = k % 225;
            // The closed camera draws 2 (+2): its next number is the open camera's time draw.
            const traced shut = trace(closed_cam, i, j, k);
            const traced lit  = trace(open_cam, i, j, k);
            if (shut.next != lit.time_u || shut.next != shut.time_u) ++misplaced;
            // One more draw: the open camera's next number is the one after that.
            if (lit.next != rt_test::next_after_draws(1, i, j, k, aperture > 0 ? 5 : 3))
                ++misplaced;
            if (!exactly(shut.r.origin(), lit.r.origin()) ||
                !exactly(shut.r.direction(), lit.r.direction()))
                ++moved;
            if (!(lit.r.time() >= open && lit.r.time() < close) || shut.r.time() != open) ++outside;
        }
        CHECK(misplaced == 0);
        CHECK(moved == 0);
        CHECK(outside == 0);
    }
}

TEST_CASE("thin_lens_camera: a shutter outside [0, 1], or closing before it opens, is refused",
          "[camera][ch07]") {
    // Moving spheres are defined, and bounded for the BVH, only for times in [0, 1]: a longer
    // shutter would silently clip their blur.
    struct shutter_case {
        real open, close;
    };
    const real nan = std::numeric_limits<real>::quiet_NaN();
    for (shutter_case c : {shutter_case{0, 2}, shutter_case{real(-0.5), real(0.5)},
                           shutter_case{real(0.7), real(0.2)}, shutter_case{0, rt::infinity},
                           shutter_case{nan, 0.5}, shutter_case{0.5, nan}}) {
        rt::thin_lens_camera cam;
        cam.shutter_open  = c.open;
        cam.shutter_close = c.close;
        CAPTURE(c.open, c.close);
        CHECK_THAT(initialize_error(cam),
                   Catch::Contains("camera shutter must satisfy 0 <= open <= close <= 1, got"));
    }
    // Both ends are named, so the user sees which one is wrong.
    rt::thin_lens_camera late;
    late.shutter_close = 2;
    CHECK(initialize_error(late) ==
          "camera shutter must satisfy 0 <= open <= close <= 1, got open 0, close 2");
    rt::thin_lens_camera instant;
    instant.shutter_open = instant.shutter_close = real(0.25);
    CHECK_NOTHROW(instant.initialize(book_film));
    rt::thin_lens_camera whole;
    whole.shutter_close = 1;
    CHECK_NOTHROW(whole.initialize(book_film));
}
