// Tests for lambertian.h (chapter 03): the ideal diffuse reflector scatters into the hemisphere of
// the normal with density cos(theta) / pi, weighted by exactly its albedo, and refuses albedos
// that would create energy. The sampler's own distribution is tested by chi-square in
// test_sampling; here we test what the material does with it.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <utility>

#include "common/error.h"
#include "common/lambertian.h"
#include "common/rng.h"
#include "common/sampling.h"
#include "common/texture.h"
#include "statistics.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::point3, rt::real, rt::vec3;

using rt_test::exactly, rt_test::random_unit;

// A hit at p with normal n (facing the incoming ray), as a shape would report it.
rt::hit_record hit_at(const point3& p, const vec3& n, bool front_face) {
    rt::hit_record rec;
    rec.p          = p;
    rec.normal     = n;
    rec.front_face = front_face;
    rec.t          = 1;
    rec.p_error    = 64 * std::numeric_limits<real>::epsilon() * (1 + rt::max_abs_component(p));
    return rec;
}

}  // namespace

TEST_CASE("lambertian: scattered directions lie in the hemisphere of the normal", "[ch03]") {
    rt::lambertian mat(color(0.5, 0.5, 0.5));
    rt::pcg32 rng(3, 4);
    rt::sampler s(17);
    // The poles and the axes are where an orthonormal basis is most easily built wrong.
    vec3 normals[8] = {vec3(0, 0, 1), vec3(0, 0, -1), vec3(1, 0, 0), vec3(0, -1, 0)};
    for (int i = 4; i < 8; ++i) normals[i] = random_unit(rng);

    int sample = 0;
    for (const vec3& n : normals) {
        int below = 0, wrong_origin = 0, wrong_time = 0;
        for (int k = 0; k < 5000; ++k, ++sample) {
            auto rec = hit_at(point3(1, 2, 3), n, k % 2 == 0);
            rt::ray r_in(point3(0, 0, 0), -n, 0.25);
            s.start_pixel_sample(sample, 0, 0);
            color attenuation;
            rt::ray scattered;
            REQUIRE(mat.scatter(r_in, rec, s, attenuation, scattered));
            // The density cos/pi vanishes at the horizon, so every sample is strictly above it.
            if (!(dot(scattered.direction(), n) > 0)) ++below;
            // Spawned on the normal's side, by hit_record::spawn_ray.
            if (!exactly(scattered.origin(), rec.p + rec.p_error * n)) ++wrong_origin;
            if (scattered.time() != real(0.25)) ++wrong_time;
        }
        INFO("normal " << n << ": " << below << " of 5000 below the horizon, " << wrong_origin
                       << " not spawned off the surface, " << wrong_time << " with a new time");
        CHECK(below == 0);
        CHECK(wrong_origin == 0);
        CHECK(wrong_time == 0);
    }
}

TEST_CASE("lambertian: the mean cosine to the normal is 2/3, as for density cos(theta) / pi",
          "[ch03]") {
    // E[cos] = integral of cos^2 / pi over the hemisphere = 2/3, with variance
    // E[cos^2] - 4/9 = 1/2 - 4/9 = 1/18: 1e5 samples give a standard error of 7.5e-4, while a
    // uniform hemisphere (E[cos] = 1/2) would sit 220 standard errors away.
    rt::lambertian mat(color(0.5, 0.5, 0.5));
    const vec3 n = rt::unit_vector(vec3(0.3, -0.8, 0.52));
    rt::sampler s(5);
    rt_test::running_mean cosines;
    int absorbed = 0;
    for (int k = 0; k < 100000; ++k) {
        s.start_pixel_sample(k, 1, 0);
        color attenuation;
        rt::ray scattered;
        if (!mat.scatter(rt::ray(point3(0, 0, 0), -n), hit_at(point3(0, 0, 0), n, true), s,
                         attenuation, scattered))
            ++absorbed;
        cosines.add(double(dot(rt::unit_vector(scattered.direction()), n)));
    }
    CHECK(absorbed == 0);
    auto check = rt_test::mean_within_tolerance(cosines.estimate(), 2.0 / 3.0, 5);
    INFO(check.summary);
    CHECK(check.passed);
}

TEST_CASE("lambertian: the attenuation is exactly the albedo", "[ch03]") {
    rt::sampler s(9);
    for (const color& albedo : {color(0.6, 0.6, 0.6), color(0.1, 0.2, 0.5), color(0, 1, 0.3)}) {
        rt::lambertian mat(albedo);
        for (int k = 0; k < 100; ++k) {
            s.start_pixel_sample(k, 2, 0);
            color attenuation;
            rt::ray scattered;
            REQUIRE(mat.scatter(rt::ray(point3(0, 0, 1), vec3(0, 0, -1)),
                                hit_at(point3(0, 0, 0), vec3(0, 0, 1), true), s, attenuation,
                                scattered));
            INFO("albedo " << albedo << ", attenuation " << attenuation);
            REQUIRE(exactly(attenuation, albedo));
        }
    }
}

TEST_CASE("lambertian: an albedo outside 0..1 throws a user_error naming it", "[ch03]") {
    const real nan = std::numeric_limits<real>::quiet_NaN();
    for (const color& albedo : {color(-0.1, 0.5, 0.5), color(0.5, 1.25, 0.5), color(0.5, 0.5, nan),
                                color(rt::infinity, 0, 0)}) {
        std::ostringstream printed;
        printed << albedo;
        INFO("albedo " << printed.str());
        std::string message;
        try {
            rt::lambertian mat(albedo);
        } catch (const rt::user_error& e) {
            message = e.what();
        }
        CHECK_THAT(message, Catch::Contains("albedo") && Catch::Contains(printed.str()));
    }
    CHECK_NOTHROW(rt::lambertian(color(0, 0, 0)));
    CHECK_NOTHROW(rt::lambertian(color(1, 1, 1)));
}

TEST_CASE("lambertian: with a texture, the attenuation is the texture's value at (u, v, p)",
          "[ch08]") {
    // A texture that depends on all of u, v and p, with values in [0, 1], so that any mix-up
    // (u for v, a stale p, the normal for p) changes the color.
    class uvp_texture : public rt::texture {
      public:
        color value(real u, real v, const point3& p) const override {
            return color(u, v, real(0.5) + real(0.5) * std::sin(p.x() + 2 * p.y() + 3 * p.z()));
        }
    };
    auto texture = std::make_shared<uvp_texture>();
    rt::lambertian mat(texture);
    rt::pcg32 rng(5, 6);
    rt::sampler s(13);
    int wrong = 0;
    for (int k = 0; k < 1000; ++k) {
        real x = rng.uniform(), y = rng.uniform();
        const point3 p(10 * x - 5, 10 * y - 5, 10 * rng.uniform() - 5);
        const vec3 n = random_unit(rng);
        auto rec     = hit_at(p, n, k % 2 == 0);
        rec.u        = rng.uniform();
        rec.v        = rng.uniform();
        s.start_pixel_sample(k, 3, 0);
        color attenuation;
        rt::ray scattered;
        REQUIRE(mat.scatter(rt::ray(p + n, -n, 0.5), rec, s, attenuation, scattered));
        if (!exactly(attenuation, texture->value(rec.u, rec.v, rec.p))) ++wrong;
    }
    CHECK(wrong == 0);

    // A checkerboard: the two cells give the two colors.
    rt::lambertian checkered(std::make_shared<rt::checker_texture>(1, color(0.875, 0.875, 0.875),
                                                                   color(0.25, 0.375, 0.125)));
    for (const auto& [p, want] : {std::pair(point3(0.5, 0.5, 0.5), color(0.875, 0.875, 0.875)),
                                  std::pair(point3(1.5, 0.5, 0.5), color(0.25, 0.375, 0.125))}) {
        color attenuation;
        rt::ray scattered;
        s.start_pixel_sample(0, 4, 0);
        REQUIRE(checkered.scatter(rt::ray(p + vec3(0, 0, 1), vec3(0, 0, -1)),
                                  hit_at(p, vec3(0, 0, 1), true), s, attenuation, scattered));
        CHECK(exactly(attenuation, want));
    }
    CHECK_THROWS_AS(rt::lambertian(std::shared_ptr<rt::texture>()), rt::user_error);
}
