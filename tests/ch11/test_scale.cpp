// The scale hard case: book 2's Cornell box (chapter 11's scene) built at 1e-4, 1e-2, 1e2 and
// 1e4 times its size, and moved by (1e5, 1e5, 1e5), must show the same image as the book's room
// within noise. Nothing in the renderer may depend on the scene's absolute size or place: spawn
// offsets, box bounds and every tolerance are relative (hittable.h, aabb.h, instance.cpp). The
// geometry itself is scaled (room_placement in cornell_box.h), so intersections, instances, the
// BVH and the camera all work at that scale; only the light's radiance is unchanged.
#include <catch2/catch.hpp>

#include "ch11_instances/cornell_box.h"
#include "noise_statistic.h"
#include "rt/integrators/path_tracer.h"

namespace {

constexpr int width = 40;

rt::scene placed_cornell_box(const room_placement& place) {
    using rt::point3, rt::vec3;
    cornell_room room =
        empty_cornell_room({point3(343, 554, 332), vec3(-130, 0, 0), vec3(0, 0, -105), 15}, place);
    auto objects = room.walls;
    objects.emplace_back(placed_box(vec3(165, 330, 165), 15, vec3(265, 0, 295), room.white, place));
    objects.emplace_back(placed_box(vec3(165, 165, 165), -18, vec3(130, 0, 65), room.white, place));
    return cornell_scene(objects, place);
}

rt::render_result render_room(const room_placement& place, int spp, std::uint64_t seed) {
    rt::render_job job = rt::path_trace(placed_cornell_box(place));
    rt::film f         = rt::film::for_aspect(width, job.cam->aspect_ratio);
    job.cam->initialize(f);
    rt::render_settings settings = job.settings;
    settings.samples_per_pixel   = spp;
    settings.seed                = seed;
    return rt::render(f, *job.cam, *job.estimator, settings);
}

struct placement_case {
    const char* name;
    room_placement place;
    bool holds_in_float;  // float's 24 bits: see the bound stated below
};

}  // namespace

TEST_CASE("scale: the Cornell box looks the same at every scale and far from the origin",
          "[scale][hardcase][ch11]") {
    // The reference: the book's room, many samples.
    const int reference_spp = 1024, test_spp = 128;
    const rt::render_result reference = render_room({}, reference_spp, 1001);

    const rt::real far = 1e5;
    // In float the room 1e5 units from the origin has coordinates with ulps of 2^-7 = 0.008,
    // 1.4e-5 of its size: far below a pixel at 40 wide, so it holds too. What float cannot hold
    // is the room at 1e-4 placed at 1e5: its walls, 0.0555 wide, would be seven ulps of their
    // coordinates; that case runs in double only (ulps of 1.5e-11 there, 2.6e-10 of the room).
    // The four scales give the same image to rounding (the same worst z): the renderer has no
    // length of its own.
    const placement_case cases[] = {
        {"1e-4", {rt::real(1e-4), rt::vec3(0, 0, 0)}, true},
        {"1e-2", {rt::real(1e-2), rt::vec3(0, 0, 0)}, true},
        {"1e2", {rt::real(1e2), rt::vec3(0, 0, 0)}, true},
        {"1e4", {rt::real(1e4), rt::vec3(0, 0, 0)}, true},
        {"moved by 1e5", {1, rt::vec3(far, far, far)}, true},
        {"1e-4 moved by 1e5", {rt::real(1e-4), rt::vec3(far, far, far)}, false},
    };
    for (const auto& c : cases) {
        if (!c.holds_in_float && std::numeric_limits<rt::real>::digits < 53) continue;
        const rt::render_result test = render_room(c.place, test_spp, 7);
        const auto result =
            rt_test::compare_within_noise(test.mean, test.mean_variance, reference.mean,
                                          reference.mean_variance, reference_spp / test_spp,
                                          /*block_size=*/8, /*alpha=*/1e-4);
        INFO("room " << c.name << ": " << result.failed << " of " << result.blocks
                     << " block tests beyond |z| = " << result.z_limit
                     << ", worst z = " << result.worst_z);
        CHECK(result.failed == 0);
        // And no pixel may be NaN or infinite.
        bool finite = true;
        for (float v : test.mean.data()) finite = finite && std::isfinite(v);
        CHECK(finite);
    }
}
