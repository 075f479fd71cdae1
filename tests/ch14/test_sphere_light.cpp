// Tests for sphere_light.h (chapter 14): seen from outside, a sphere light draws directions
// uniformly in the cone it fills, pdf = 1 / (2 pi (1 - cos theta_max)) with
// sin^2 theta_max = r^2 / d^2; from inside, a uniform point of its surface, converted to solid
// angle. Checked by chi-square against pdf() integrated over bins of directions
// (ch14/direction_checks.h), near (the cone is 56 degrees wide), far (under a degree) and from
// inside, by the pdf integrating to 1, and by every drawn sample reporting pdf() of its own
// direction. one_minus_cos_max is checked against the plain formula where that one is accurate.
// Hard cases: a tiny sphere extremely far away, ref a hair outside the surface or on it.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>

#include "ch03/sampling_checks.h"
#include "ch14/direction_checks.h"
#include "ch14/light_checks.h"
#include "rt/geometry/sphere.h"
#include "rt/lights/sphere_light.h"
#include "rt/materials/diffuse_light.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::point3, rt::real, rt::vec3;
using rt_test::direction_checks::direction_bins;

const color radiance(3, 2, 5);

std::shared_ptr<rt::sphere> light_sphere(const point3& center, real radius) {
    return std::make_shared<rt::sphere>(center, radius,
                                        std::make_shared<rt::diffuse_light>(radiance));
}

rt_test::direction_checks::direction_test test_from(const rt::sphere_light& light,
                                                    const direction_bins& bins, const point3& ref,
                                                    std::uint64_t sequence) {
    return rt_test::direction_checks::test_light(
        light, bins, ref, sequence, 1000 * double(std::numeric_limits<real>::epsilon()));
}

bool finite(const vec3& v) {
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

}  // namespace

TEST_CASE("sphere_light: from outside, directions are uniform in the cone the sphere fills",
          "[ch14]") {
    const point3 center(1, 2, -3);
    const real radius = real(0.75);
    auto s            = light_sphere(center, radius);
    rt::sphere_light light(*s);
    // Distances 1.2 r (theta_max = 56 degrees) and 60 r (under a degree): the bins reach 1.25
    // times the cone's 1 - cos theta_max, so a direction outside the cone would fall where
    // pdf() is 0 and fail the test outright.
    const vec3 away        = rt::unit_vector(vec3(0.3, -0.9, 0.2));
    std::uint64_t sequence = 11;
    for (real distance : {real(1.2) * radius, real(60) * radius}) {
        const point3 ref  = center + distance * away;
        const double s2   = double(radius * radius) / double(distance * distance);
        const double cone = s2 / (1 + std::sqrt(1 - s2));  // 1 - cos theta_max
        const direction_bins bins(center - ref, 1.25 * cone, 10, 16);
        INFO("distance " << distance << " = " << distance / radius << " radii");
        rt_test::direction_checks::check_directions(test_from(light, bins, ref, sequence++));
        // The density inside the cone, in closed form.
        CHECK(double(light.pdf(ref, rt::unit_vector(center - ref))) ==
              Approx(1 / (2 * rt_test::sampling_checks::pi * cone)).epsilon(1e-5));
    }
}

TEST_CASE("sphere_light: from inside, directions follow the area density in solid angle",
          "[ch14]") {
    // From inside every direction meets the sphere once, with density d^2 / (|cos| 4 pi r^2):
    // larger towards the far side. Bins over the whole sphere of directions, about the axis
    // from ref to the center.
    const point3 center(-2, 0.5, 1);
    const real radius = 2;
    auto s            = light_sphere(center, radius);
    rt::sphere_light light(*s);
    std::uint64_t sequence = 21;
    for (const point3& ref : {center + vec3(0.9, 0.8, -0.4), center + vec3(0, 0, 1.9)}) {
        INFO("ref " << ref);
        const direction_bins bins(center - ref, 2, 10, 16);
        rt_test::direction_checks::check_directions(test_from(light, bins, ref, sequence++));
    }
    // At the center the density is uniform, 1 / (4 pi).
    CHECK(double(light.pdf(center, vec3(0, 0, 1))) ==
          Approx(1 / (4 * rt_test::sampling_checks::pi)).epsilon(1e-5));
}

TEST_CASE("sphere_light: a sample carries the light's radiance and lies on the near side",
          "[ch14]") {
    const point3 center(0, 3, 0);
    auto s = light_sphere(center, 1);
    rt::sphere_light light(*s);
    rt::pcg32 rng(6, 1);
    int wrong = 0;
    const point3 ref(0.5, 0, 0.25);
    for (int k = 0; k < 5000; ++k) {
        rt::light_sample out;
        REQUIRE(light.sample(ref, rt_test::sampling_checks::next_sample2(rng), out));
        const vec3 outward = out.on_light.p - center;
        const bool ok      = rt_test::exactly(out.radiance, radiance) && !out.at_infinity &&
                        std::fabs(out.wi.length() - 1) < 1e-5 &&
                        std::fabs(outward.length() - 1) < 1e-5 &&
                        // The near side: its outward normal faces ref.
                        dot(outward, out.wi) <= 0 && dot(out.on_light.normal, out.wi) <= 0 &&
                        dot(out.wi, out.on_light.p - ref) > 0;
        wrong += !ok;
    }
    CHECK(wrong == 0);
    // Directions away from the sphere have no density.
    CHECK(light.pdf(ref, vec3(0, -1, 0)) == 0);
    CHECK(light.pdf(ref, vec3(1, 0, 0)) == 0);
}

TEST_CASE("sphere_light: 1 - cos theta_max without cancellation", "[ch14]") {
    // Against 1 - sqrt(1 - s) where that is accurate (s not small), and against its series
    // s/2 + s^2/8 where s is small and the plain formula would return 0.
    for (double s : {0.9, 0.5, 0.25, 0.01}) {
        CHECK(double(rt::sphere_light::one_minus_cos_max(real(s))) ==
              Approx(1 - std::sqrt(1 - s)).epsilon(1e-6));
    }
    for (double s : {1e-12, 1e-20, 1e-30}) {
        CHECK(double(rt::sphere_light::one_minus_cos_max(real(s))) ==
              Approx(s / 2 + s * s / 8).epsilon(1e-6));
    }
    CHECK(rt::sphere_light::one_minus_cos_max(1) == 1);
}

TEST_CASE("sphere_light: far, tiny, touching: no NaN, and a pdf that is finite or 0",
          "[ch14][hardcase]") {
    // Extremes where 1 - cos theta_max underflows or the cone becomes a hemisphere: a speck
    // 1e-6 across seen from 1e6 away (sin^2 theta_max = 1e-24, and smaller in float), ref a
    // hair outside the surface, exactly on it (as rounded), a hair inside, and at the center.
    struct setup {
        point3 center;
        real radius;
        point3 ref;
    };
    const vec3 dir      = rt::unit_vector(vec3(0.6, -0.48, 0.64));
    const real eps      = std::numeric_limits<real>::epsilon();
    const setup cases[] = {
        {point3(0, 0, 0), real(1e-6), point3(1e6, 2e5, -3e5)},
        {point3(1e3, 0, 0), real(1e-3), point3(-1e6, 1e6, 0)},
        // sin^2 theta_max = 1e-44: a denormal in float, where 1 / (2 pi (1 - cos)) overflows.
        {point3(0, 0, 0), real(1e-20), point3(100, 0, 0)},
        {point3(0, 0, 0), 1, point3(0, 0, 0) + (1 + 4 * eps) * dir},
        {point3(0, 0, 0), 1, point3(0, 0, 0) + dir},
        {point3(0, 0, 0), 1, point3(0, 0, 0) + (1 - 4 * eps) * dir},
        {point3(2, -1, 3), real(0.5), point3(2, -1, 3) + real(0.5) * vec3(0, 1, 0)},
        {point3(2, -1, 3), real(0.5), point3(2, -1, 3) + real(0.5) * vec3(1, 0, 0)},
        {point3(5, 5, 5), 2, point3(5, 5, 5)},
    };
    rt::pcg32 rng(4, 9);
    int bad_samples = 0, bad_pdfs = 0, refused = 0;
    for (const setup& c : cases) {
        auto s = light_sphere(c.center, c.radius);
        rt::sphere_light light(*s);
        auto check_pdf = [&](const vec3& wi) {
            const real p = light.pdf(c.ref, wi);
            if (std::isnan(p) || !std::isfinite(p) || p < 0) {
                UNSCOPED_INFO("sphere " << c.center << " r " << c.radius << ", ref " << c.ref
                                        << ", wi " << wi << ": pdf " << p);
                ++bad_pdfs;
            }
        };
        rt_test::sampling_checks::for_edge_and_random_samples([&](rt::sample2 u) {
            rt::light_sample out;
            if (!light.sample(c.ref, u, out)) {
                ++refused;
                return;
            }
            const bool ok = finite(out.wi) && std::isfinite(out.pdf) && out.pdf > 0 &&
                            finite(out.radiance) && finite(out.on_light.p) &&
                            finite(out.on_light.normal);
            if (!ok) {
                UNSCOPED_INFO("sphere " << c.center << " r " << c.radius << ", ref " << c.ref
                                        << ", u " << u.u << " " << u.v << ": wi " << out.wi
                                        << ", pdf " << out.pdf);
                ++bad_samples;
            }
            check_pdf(out.wi);
        });
        for (int k = 0; k < 2000; ++k) check_pdf(rt_test::random_unit(rng));
        if ((c.center - c.ref).length_squared() > 0) check_pdf(rt::unit_vector(c.center - c.ref));
    }
    INFO(refused << " samples refused");
    CHECK(bad_samples == 0);
    CHECK(bad_pdfs == 0);
}
