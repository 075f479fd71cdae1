// Tests for path_tracer.h with chapter 12's media: a medium draws its random number by hashing the
// ray of the path segment that crosses it, not from the sampler. So a medium costs a path no
// sampler dimension (a scene's samples do not move when a medium is added), and each segment of a
// path is a ray of its own, with its own number.
#include <catch2/catch.hpp>
#include <memory>
#include <vector>

#include "ch03/material_helpers.h"
#include "ch12/ray_recorder.h"
#include "rt/geometry/box.h"
#include "rt/geometry/quad.h"
#include "rt/integrators/path_tracer.h"
#include "rt/materials/lambertian.h"
#include "rt/media/constant_medium.h"
#include "rt/samplers/independent_sampler.h"
#include "rt/scene/hittable_list.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::point3, rt::real, rt::vec3;

using rt_test::any_material, rt_test::exactly;

const color albedo(real(0.6), real(0.6), real(0.6));

// Records the rays it is asked about and passes them on to the object it wraps.
using rt_test::ray_recorder;

}  // namespace

TEST_CASE(
    "path_tracer: media draw no sampler dimensions, and each path segment is a ray of its "
    "own",
    "[ch12][draw-order]") {
    // A Lambertian floor under a uniform sky, max_depth 2: segment 1 (the camera ray) hits the
    // floor, segment 2 leaves it for the sky, so the path returns the albedo. Both segments
    // cross a thin haze (density 1e-9: over a few units it scatters with chance ~1e-8, and
    // with this seed never does). The path must draw just the Lambertian bounce's 2 dimensions
    // and bring back the same radiance as without the haze; the haze must be asked about two
    // different rays, with two different numbers.
    auto floor = std::make_shared<rt::quad>(point3(-10, 0, -10), vec3(20, 0, 0), vec3(0, 0, 20),
                                            std::make_shared<rt::lambertian>(albedo));
    auto haze  = std::make_shared<rt::constant_medium>(
        rt::box(point3(-20, 0.25, -20), point3(20, 5, 20), any_material()), real(1e-9),
        color(1, 1, 1));
    auto recorder = std::make_shared<ray_recorder>(haze);
    auto hazy     = std::make_shared<rt::hittable_list>(),
         clear    = std::make_shared<rt::hittable_list>();
    hazy->add(floor);
    hazy->add(recorder);
    clear->add(floor);
    const auto sky = rt::background::uniform(color(1, 1, 1));
    const rt::path_tracer through_haze(hazy, sky), in_clear_air(clear, sky);
    rt::independent_sampler s(77);
    int not_albedo = 0, not_clear = 0, same_rays = 0, same_numbers = 0, misplaced = 0;
    for (int k = 0; k < 1000; ++k) {
        s.start_pixel_sample(3, 4, k);
        rt::independent_sampler expected = s;  // replays the draws the path should make
        rt::independent_sampler clear_s  = s;
        expected.next_2d();  // the Lambertian bounce, and nothing else
        recorder->rays.clear();
        const rt::ray camera_ray(point3(0, 1, 0), vec3(0.25, -1, 0.5));
        const color L = through_haze.radiance(camera_ray, s, 2);
        not_albedo += !exactly(L, albedo);  // one bounce, then the sky: 2 segments
        not_clear += !exactly(L, in_clear_air.radiance(camera_ray, clear_s, 2));
        REQUIRE(recorder->rays.size() == 2);
        const rt::ray &first = recorder->rays[0], &second = recorder->rays[1];
        same_rays += exactly(first.origin(), second.origin()) ||
                     exactly(first.direction(), second.direction());
        same_numbers += haze->random_for(first) == haze->random_for(second);
        // Both paths leave the sampler where the bounce alone leaves it.
        const real next = expected.next_1d();
        misplaced += s.next_1d() != next;
        misplaced += clear_s.next_1d() != next;
    }
    CHECK(not_albedo == 0);
    CHECK(not_clear == 0);
    CHECK(same_rays == 0);
    CHECK(same_numbers == 0);
    CHECK(misplaced == 0);
}
