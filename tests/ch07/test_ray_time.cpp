// The ray's instant (chapter 07's line in ray.h): 0 unless a shutter sets it, and carried along
// a path, so that no scattering code has to name it.
#include <catch2/catch.hpp>

#include "ch03/material_helpers.h"
#include "rt/camera/thin_lens_camera.h"
#include "rt/core/ray.h"
#include "rt/materials/lambertian.h"
#include "rt/samplers/independent_sampler.h"
#include "test_helpers.h"

TEST_CASE("ray: the instant defaults to 0 and continued() carries it", "[ray][ch07]") {
    const rt::ray still(rt::point3(1, 2, 3), rt::vec3(0, 0, -1));
    CHECK(still.time() == 0);

    const rt::ray timed(rt::point3(1, 2, 3), rt::vec3(0, 0, -1), rt::real(0.25));
    CHECK(timed.time() == rt::real(0.25));
    const rt::ray next = timed.continued(rt::point3(4, 5, 6), rt::vec3(1, 0, 0));
    CHECK(next.time() == rt::real(0.25));
    CHECK(rt_test::exactly(next.origin(), rt::point3(4, 5, 6)));
    CHECK(rt_test::exactly(next.direction(), rt::vec3(1, 0, 0)));
}

TEST_CASE("ray: a scattered ray keeps the instant of the ray that arrived", "[ray][ch07]") {
    rt::lambertian matte(rt::color(0.5, 0.5, 0.5));
    rt::hit_record rec = rt_test::hit_at(rt::point3(0, 0, 0), rt::vec3(0, 1, 0), true);
    const rt::ray arriving(rt::point3(0, 1, 0), rt::vec3(0, -1, 0), rt::real(0.75));
    rt::independent_sampler s(1);
    s.start_pixel_sample(0, 0, 0);
    const auto sample = matte.scatter(arriving, rec, s);
    REQUIRE(sample);
    CHECK(sample->scattered.time() == rt::real(0.75));
}

TEST_CASE("thin_lens_camera: with the shutter closed, rays are at instant 0 and draw no time",
          "[camera][ch07][draw-order]") {
    rt::thin_lens_camera cam;
    cam.initialize(rt::film::for_aspect(64, 16.0 / 9));
    rt::independent_sampler s(3), fresh(3);
    s.start_pixel_sample(5, 7, 11);
    fresh.start_pixel_sample(5, 7, 11);
    const rt::ray r = cam.get_ray(5, 7, s);
    CHECK(r.time() == 0);
    fresh.next_2d();  // the jitter: the only draw of a pinhole with a closed shutter
    CHECK(s.next_1d() == fresh.next_1d());
}
