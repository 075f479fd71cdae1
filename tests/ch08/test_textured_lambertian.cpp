// Tests for textured_lambertian.h (chapter 08): chapter 03's diffuse reflector with its albedo
// looked up in a texture at each hit. It scatters exactly as a lambertian does (the same 2
// sampler dimensions, the same direction), and its attenuation is the texture's value at the
// hit's (u, v) and p.
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>
#include <utility>

#include "ch03/material_helpers.h"
#include "rt/core/error.h"
#include "rt/core/rng.h"
#include "rt/geometry/quad.h"
#include "rt/materials/lambertian.h"
#include "rt/materials/textured_lambertian.h"
#include "rt/samplers/independent_sampler.h"
#include "rt/textures/texture.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::point3, rt::real, rt::vec3;

using rt_test::any_material, rt_test::exactly, rt_test::hit_at, rt_test::random_unit;

// A texture that depends on all of u, v and p, with values in [0, 1], so that any mix-up
// (u for v, a stale p, the normal for p) changes the color.
class uvp_texture : public rt::texture {
  public:
    color value(real u, real v, const point3& p) const override {
        return color(u, v, real(0.5) + real(0.5) * std::sin(p.x() + 2 * p.y() + 3 * p.z()));
    }
    bool uses_uv() const override { return true; }
};

}  // namespace

TEST_CASE("textured_lambertian: the attenuation is the texture's value at (u, v, p)", "[ch08]") {
    auto texture = std::make_shared<uvp_texture>();
    rt::textured_lambertian mat(texture);
    rt::lambertian plain(color(0.5, 0.5, 0.5));
    // The hit's (u, v) come from the shape that recorded it: a quad's are its rec.local's first
    // two coordinates, so a record naming this quad can be given any (u, v).
    const rt::quad surface(point3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), any_material());
    rt::pcg32 rng(5, 6);
    rt::independent_sampler s(13);
    int wrong = 0, other_ray = 0;
    for (int k = 0; k < 1000; ++k) {
        real x = rng.uniform(), y = rng.uniform();
        const point3 p(10 * x - 5, 10 * y - 5, 10 * rng.uniform() - 5);
        const vec3 n = random_unit(rng);
        auto rec     = hit_at(p, n, k % 2 == 0);
        real u = rng.uniform(), v = rng.uniform();
        rec.object = &surface;
        rec.local  = vec3(u, v, 0);
        const rt::ray r_in(p + n, -n, 0.5);
        s.start_pixel_sample(k, 3, 0);
        rt::independent_sampler same = s;
        const auto sample            = mat.scatter(r_in, rec, s);
        REQUIRE(sample);
        if (!exactly(sample->weight, texture->value(u, v, rec.p))) ++wrong;
        // The same draws make the same ray as the untextured material, and leave the sampler
        // at the same place.
        const auto plain_sample = plain.scatter(r_in, rec, same);
        REQUIRE(plain_sample);
        const rt::ray &scattered = sample->scattered, &plain_scattered = plain_sample->scattered;
        if (!exactly(scattered.origin(), plain_scattered.origin()) ||
            !exactly(scattered.direction(), plain_scattered.direction()) ||
            scattered.time() != r_in.time() || s.next_1d() != same.next_1d())
            ++other_ray;
    }
    CHECK(wrong == 0);
    CHECK(other_ray == 0);

    // A checkerboard: the two cells give the two colors.
    rt::textured_lambertian checkered(std::make_shared<rt::checker_texture>(
        1, color(0.875, 0.875, 0.875), color(0.25, 0.375, 0.125)));
    for (const auto& [p, want] : {std::pair(point3(0.5, 0.5, 0.5), color(0.875, 0.875, 0.875)),
                                  std::pair(point3(1.5, 0.5, 0.5), color(0.25, 0.375, 0.125))}) {
        s.start_pixel_sample(0, 4, 0);
        const auto sample = checkered.scatter(rt::ray(p + vec3(0, 0, 1), vec3(0, 0, -1)),
                                              hit_at(p, vec3(0, 0, 1), true), s);
        REQUIRE(sample);
        CHECK(exactly(sample->weight, want));
    }
    CHECK_THROWS_AS(rt::textured_lambertian(std::shared_ptr<rt::texture>()), rt::user_error);
    CHECK_THROWS_WITH(rt::textured_lambertian(nullptr), Catch::Contains("texture is missing"));
}
