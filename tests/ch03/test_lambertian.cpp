// Tests for lambertian.h (chapter 03): the ideal diffuse reflector scatters into the hemisphere of
// the normal with density cos(theta) / pi, weighted by exactly its albedo, draws 2 sampler
// dimensions, and refuses albedos that would create energy. The sampler's own distribution is
// tested by chi-square in test_sampling; here we test what the material does with it.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <utility>

#include "ch03/material_helpers.h"
#include "rt/core/error.h"
#include "rt/core/rng.h"
#include "rt/materials/lambertian.h"
#include "rt/samplers/independent_sampler.h"
#include "statistics.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::point3, rt::real, rt::vec3;

using rt_test::exactly, rt_test::hit_at, rt_test::random_unit;

}  // namespace

TEST_CASE("lambertian: scattered directions lie in the hemisphere of the normal", "[ch03]") {
    rt::lambertian mat(color(0.5, 0.5, 0.5));
    rt::pcg32 rng(3, 4);
    rt::independent_sampler s(17);
    // The poles and the axes are where an orthonormal basis is most easily built wrong.
    vec3 normals[8] = {vec3(0, 0, 1), vec3(0, 0, -1), vec3(1, 0, 0), vec3(0, -1, 0)};
    for (int i = 4; i < 8; ++i) normals[i] = random_unit(rng);

    int sample = 0;
    for (const vec3& n : normals) {
        int below = 0, wrong_origin = 0;
        for (int k = 0; k < 5000; ++k, ++sample) {
            auto rec = hit_at(point3(1, 2, 3), n, k % 2 == 0);
            rt::ray r_in(point3(0, 0, 0), -n);
            s.start_pixel_sample(sample, 0, 0);
            const auto drawn = mat.scatter(r_in, rec, s);
            REQUIRE(drawn);
            const rt::ray& scattered = drawn->scattered;
            // The density cos/pi vanishes at the horizon, so every sample is strictly above it.
            if (!(dot(scattered.direction(), n) > 0)) ++below;
            // Spawned on the normal's side, by spawn_reflected_ray.
            if (!exactly(scattered.origin(), rec.p + rec.p_error * n)) ++wrong_origin;
        }
        INFO("normal " << n << ": " << below << " of 5000 below the horizon, " << wrong_origin
                       << " not spawned off the surface");
        CHECK(below == 0);
        CHECK(wrong_origin == 0);
    }
}

TEST_CASE("lambertian: the mean cosine to the normal is 2/3, as for density cos(theta) / pi",
          "[ch03]") {
    // E[cos] = integral of cos^2 / pi over the hemisphere = 2/3, with variance
    // E[cos^2] - 4/9 = 1/2 - 4/9 = 1/18: 1e5 samples give a standard error of 7.5e-4, while a
    // uniform hemisphere (E[cos] = 1/2) would sit 220 standard errors away.
    rt::lambertian mat(color(0.5, 0.5, 0.5));
    const vec3 n = rt::unit_vector(vec3(0.3, -0.8, 0.52));
    rt::independent_sampler s(5);
    rt_test::running_mean cosines;
    int absorbed = 0;
    for (int k = 0; k < 100000; ++k) {
        s.start_pixel_sample(k, 1, 0);
        const auto sample =
            mat.scatter(rt::ray(point3(0, 0, 0), -n), hit_at(point3(0, 0, 0), n, true), s);
        if (!sample) {
            ++absorbed;
            continue;
        }
        cosines.add(double(dot(rt::unit_vector(sample->scattered.direction()), n)));
    }
    CHECK(absorbed == 0);
    auto check = rt_test::mean_within_tolerance(cosines.estimate(), 2.0 / 3.0, 5);
    INFO(check.summary);
    CHECK(check.passed);
}

TEST_CASE("lambertian: the weight is exactly the albedo", "[ch03]") {
    rt::independent_sampler s(9);
    for (const color& albedo : {color(0.6, 0.6, 0.6), color(0.1, 0.2, 0.5), color(0, 1, 0.3)}) {
        rt::lambertian mat(albedo);
        for (int k = 0; k < 100; ++k) {
            s.start_pixel_sample(k, 2, 0);
            const auto sample = mat.scatter(rt::ray(point3(0, 0, 1), vec3(0, 0, -1)),
                                            hit_at(point3(0, 0, 0), vec3(0, 0, 1), true), s);
            REQUIRE(sample);
            INFO("albedo " << albedo << ", weight " << sample->weight);
            REQUIRE(exactly(sample->weight, albedo));
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

TEST_CASE("lambertian: scatter draws exactly 2 sampler dimensions, as scatter_diffuse does",
          "[ch03][draw-order]") {
    // The material's part of the sampler's layout (sampler.h): what the next bounce draws must
    // be the dimension after these 2. And the direction is scatter_diffuse's, bit for bit.
    rt::lambertian mat(color(real(0.3), real(0.6), real(0.9)));
    rt::pcg32 rng(8, 1);
    int drew_wrong = 0, differ = 0;
    for (int k = 0; k < 1000; ++k) {
        const vec3 n = random_unit(rng);
        auto rec     = hit_at(point3(-1, 0, 2), n, true);
        const rt::ray r_in(point3(-1, 0, 2) + n, -n);
        rt::independent_sampler s(21), copy(21);
        s.start_pixel_sample(k, 0, 0);
        copy.start_pixel_sample(k, 0, 0);
        const auto sample = mat.scatter(r_in, rec, s);
        REQUIRE(sample);
        const rt::ray diffuse = rt::scatter_diffuse(r_in, rec, copy, color(1, 1, 1)).scattered;
        if (s.next_1d() != rt_test::next_after_draws(21, k, 0, 0, 2)) ++drew_wrong;
        if (!exactly(sample->scattered.origin(), diffuse.origin()) ||
            !exactly(sample->scattered.direction(), diffuse.direction()))
            ++differ;
    }
    CHECK(drew_wrong == 0);
    CHECK(differ == 0);
}
