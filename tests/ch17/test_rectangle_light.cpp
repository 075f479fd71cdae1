// Tests for spherical_rectangle.h and rectangle_light.h (chapter 17): a rectangular lamp sampled
// by solid angle. Directions must be uniform over the solid angle the rectangle covers: chi-square
// against pdf() integrated over bins of directions (ch14/direction_checks.h), pdf() = 1 / that
// solid angle, integrating to 1, from near and far, below, beside the lamp in its own plane's
// neighbourhood, and from behind. The solid angle itself against closed forms; far away, where
// it runs out of digits, the light draws by area as quad_light and says so by its density; a
// quad that is no rectangle gets a quad_light. Hard cases: in the plane, on an edge, a hair off a
// corner: no NaN, no infinity. And the estimator keeps its mean: mis with rectangles by solid
// angle against mis by area, on every scene of ch14/estimator_scenes.h (within 5 standard
// errors), and with less noise on a ceiling beside a lamp.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <type_traits>

#include "ch03/sampling_checks.h"
#include "ch14/direction_checks.h"
#include "ch14/estimator_scenes.h"
#include "ch14/quad_checks.h"
#include "rt/geometry/quad.h"
#include "rt/integrators/mis_tracer.h"
#include "rt/lights/quad_light.h"
#include "rt/lights/rectangle_light.h"
#include "rt/lights/spherical_rectangle.h"
#include "rt/materials/diffuse_light.h"

namespace {

using rt::color, rt::point3, rt::real, rt::vec3;
using rt_test::direction_checks::direction_bins;
using rt_test::quad_checks::bins_around, rt_test::quad_checks::center_of;

const color radiance(4, 2, 1);

std::shared_ptr<rt::quad> tilted_rectangle() {
    return rt_test::quad_checks::tilted_quad(radiance);
}

rt_test::direction_checks::direction_test test_from(const rt::light& light,
                                                    const direction_bins& bins, const point3& ref,
                                                    std::uint64_t sequence) {
    return rt_test::direction_checks::test_light(
        light, bins, ref, sequence, 1000 * double(std::numeric_limits<real>::epsilon()));
}

bool finite(const vec3& v) {
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

// light draws from ref as by_area does (chapter 14's quad light): 2000 samples with the same
// numbers give the same directions and densities, bit for bit, and pdf() agrees on them.
void check_draws_as(const rt::light& light, const rt::quad_light& by_area, const point3& ref,
                    std::uint64_t sequence) {
    rt::pcg32 rng(sequence, 3);
    int differ = 0;
    for (int k = 0; k < 2000; ++k) {
        const rt::sample2 u = rt_test::sampling_checks::next_sample2(rng);
        rt::light_sample a, b;
        const bool drawn = light.sample(ref, u, a);
        if (drawn != by_area.sample(ref, u, b)) {
            ++differ;
            continue;
        }
        if (!drawn) continue;
        differ += !(a.wi.x() == b.wi.x() && a.wi.y() == b.wi.y() && a.wi.z() == b.wi.z() &&
                    a.pdf == b.pdf && light.pdf(ref, a.wi) == by_area.pdf(ref, b.wi));
    }
    CHECK(differ == 0);
}

}  // namespace

TEST_CASE(
    "spherical_rectangle: the solid angle of a square seen along its axis, and of a "
    "rectangle from its corner's normal",
    "[ch17]") {
    // Relative tolerances: a few roundings of the angles' sum, against the solid angle; near the
    // half sphere the inner angles come close to pi, where acos loses half the digits.
    const bool in_float = std::is_same_v<real, float>;
    const double close = in_float ? 1e-3 : 1e-9, half_sphere = in_float ? 1e-3 : 1e-5;
    // A square of side 2a centered at distance h: 4 asin(a^2 / (a^2 + h^2)).
    for (real h : {real(0.01), real(0.5), real(1), real(3), real(40)}) {
        const real a = real(0.75);
        rt::spherical_rectangle seen(point3(0, 0, 0), point3(-a, -a, h), vec3(2 * a, 0, 0),
                                     vec3(0, 2 * a, 0));
        const double expected = 4 * std::asin(double(a) * a / (double(a) * a + double(h) * h));
        INFO("h " << h);
        CHECK(seen.solid_angle() == Approx(expected).epsilon(close));
        CHECK(seen.by_solid_angle() == (expected >= rt::spherical_rectangle::min_solid_angle));
    }
    // A w x l rectangle seen from above one of its corners at height h:
    // atan(w l / (h sqrt(h^2 + w^2 + l^2))).
    const real w = 2, l = 3, h = real(0.7);
    rt::spherical_rectangle corner(point3(0, h, 0), point3(0, 0, 0), vec3(0, 0, l), vec3(w, 0, 0));
    const double dh = h;
    CHECK(corner.solid_angle() ==
          Approx(std::atan(w * l / (dh * std::sqrt(dh * dh + w * w + l * l)))).epsilon(close));
    // Nearly touching its middle: nearly the half sphere.
    rt::spherical_rectangle touching(point3(0, 0, real(-1e-6)), point3(-1, -1, 0), vec3(2, 0, 0),
                                     vec3(0, 2, 0));
    CHECK(touching.solid_angle() == Approx(2 * std::numbers::pi).epsilon(half_sphere));
    // In its plane: none.
    rt::spherical_rectangle edge_on(point3(5, 0, 0), point3(-1, -1, 0), vec3(2, 0, 0),
                                    vec3(0, 2, 0));
    CHECK(edge_on.solid_angle() == 0);
    CHECK_FALSE(edge_on.by_solid_angle());
}

TEST_CASE(
    "rectangle_light: near its plane, directions uniform in the solid angle (pdf() = 1 / "
    "solid angle), farther by area as quad_light",
    "[ch17]") {
    auto q = tilted_rectangle();
    rt::rectangle_light light(*q);
    rt::quad_light by_area(*q);
    const vec3 n = rt::unit_vector(cross(q->edge_u(), q->edge_v()));
    // Near (closer to its plane than half its longer edge, 1.25): below and oblique, from
    // behind, and close beside the lamp just off its plane (a ceiling beside its lamp, where
    // drawing by area is worst). Far: below, far away, behind.
    const point3 beside = q->corner() + real(1.02) * q->edge_u() + real(0.5) * q->edge_v();
    const point3 near[] = {point3(0.2, 1.5, 0.1), point3(0.5, 2.8, -0.6), beside - real(0.05) * n};
    const point3 far[]  = {point3(0.3, 0, 0.2), point3(-6, -4, 9), point3(0.5, 3.5, -2)};
    std::uint64_t sequence = 11;
    for (const point3& ref : near) {
        INFO("near: ref " << ref << ", " << dot(ref - q->corner(), n) << " from the plane");
        REQUIRE(light.near(ref));
        rt::spherical_rectangle seen(ref, q->corner(), q->edge_u(), q->edge_v());
        REQUIRE(seen.by_solid_angle());
        rt_test::direction_checks::check_directions(
            test_from(light, bins_around(*q, ref), ref, sequence++));
        CHECK(light.pdf(ref, rt::unit_vector(center_of(*q) - ref)) ==
              Approx(1 / seen.solid_angle()).epsilon(1e-12));
    }
    // Far, chapter 14's quad light draws (whose own chi-square is chapter 14's test): the same
    // directions and densities, bit for bit.
    for (const point3& ref : far) {
        INFO("far: ref " << ref << ", " << dot(ref - q->corner(), n) << " from the plane");
        REQUIRE_FALSE(light.near(ref));
        check_draws_as(light, by_area, ref, sequence++);
    }
}

TEST_CASE("rectangle_light: seen too small to measure, it draws by area, as quad_light does",
          "[ch17]") {
    auto q = tilted_rectangle();
    rt::rectangle_light light(*q);
    rt::quad_light by_area(*q);
    // Near its plane (one unit off it) but 2000 units away along it: about 7e-10 steradians.
    const vec3 n     = rt::unit_vector(cross(q->edge_u(), q->edge_v()));
    const point3 far = center_of(*q) + real(800) * q->edge_u() + n;
    REQUIRE(light.near(far));
    rt::spherical_rectangle seen(far, q->corner(), q->edge_u(), q->edge_v());
    REQUIRE_FALSE(seen.by_solid_angle());
    check_draws_as(light, by_area, far, 3);
}

TEST_CASE("rectangle_light::make: rectangles by solid angle, other quads by area", "[ch17]") {
    auto lamp = std::make_shared<rt::diffuse_light>(radiance);
    rt::quad rectangle(point3(0, 0, 0), vec3(2, 0, 0), vec3(0, 0, 3), lamp);
    rt::quad parallelogram(point3(0, 0, 0), vec3(2, 0, 0), vec3(0.5, 0, 3), lamp);
    CHECK(rt::rectangle_light::is_rectangle(rectangle));
    CHECK_FALSE(rt::rectangle_light::is_rectangle(parallelogram));
    CHECK(dynamic_cast<rt::rectangle_light*>(rt::rectangle_light::make(rectangle).get()));
    auto other = rt::rectangle_light::make(parallelogram);
    CHECK(dynamic_cast<rt::quad_light*>(other.get()));
    CHECK_FALSE(dynamic_cast<rt::rectangle_light*>(other.get()));
}

TEST_CASE(
    "rectangle_light: in the lamp's plane, on its edge, a hair off its corner: no NaN, no "
    "infinity",
    "[ch17]") {
    auto q = tilted_rectangle();
    rt::rectangle_light light(*q);
    const vec3 n        = rt::unit_vector(cross(q->edge_u(), q->edge_v()));
    const point3 refs[] = {q->corner() - real(1) * q->edge_u(),    // in its plane
                           q->corner() + real(0.5) * q->edge_u(),  // on its edge
                           q->corner() + real(1e-9) * n,           // off a corner
                           center_of(*q) + real(1e-12) * n,        // touching
                           q->corner() + q->edge_u() + q->edge_v() - real(1e-7) * n};
    rt::pcg32 rng(9, 1);
    for (const point3& ref : refs) {
        INFO("ref " << ref);
        for (int k = 0; k < 2000; ++k) {
            rt::light_sample out;
            if (!light.sample(ref, rt_test::sampling_checks::next_sample2(rng), out)) continue;
            REQUIRE(finite(out.wi));
            REQUIRE(std::isfinite(out.pdf));
            REQUIRE(out.pdf > 0);
            REQUIRE(light.pdf(ref, out.wi) >= 0);
        }
    }
}

TEST_CASE("rectangle_light: mis keeps its mean with rectangles drawn by solid angle", "[ch17]") {
    using namespace rt_test::estimator_scenes;
    std::uint64_t seed = 900;
    for (const test_scene& sc : all_scenes()) {
        INFO(sc.name);
        const rt::mis_tracer by_area(sc.world, sc.sky);
        const rt::mis_tracer by_solid_angle(
            sc.world, sc.sky, {rt::light_through_media::sampled, rt::rectangle_light::make});
        const run a = estimate(by_area, sc, 40000, seed++);
        const run b = estimate(by_solid_angle, sc, 40000, seed++);
        check_run(b, sc);
        check_same_mean(b, a);
    }
}

TEST_CASE("rectangle_light: the direct light on a ceiling beside a lamp is far less noisy",
          "[ch17]") {
    using namespace rt_test::estimator_scenes;
    // The closed box's ceiling just beside its lamp, 0.05 below it: drawn by area, the lamp's
    // far edge has a density many times its near edge's.
    test_scene sc = closed_box();
    sc.eye        = point3(0, -0.5, 0.5);
    sc.target     = point3(0.6, 1, 0);
    sc.spread     = real(0.05);
    sc.max_depth  = 2;  // the lamp's own light on it, by both of MIS's strategies
    const rt::mis_tracer by_area(sc.world, sc.sky);
    const rt::mis_tracer by_solid_angle(
        sc.world, sc.sky, {rt::light_through_media::sampled, rt::rectangle_light::make});
    const run a = estimate(by_area, sc, 20000, 1201);
    const run b = estimate(by_solid_angle, sc, 20000, 1202);
    check_same_mean(a, b);
    const double area_se  = a.radiance.estimate().standard_error;
    const double solid_se = b.radiance.estimate().standard_error;
    INFO("standard errors: by area " << area_se << ", by solid angle " << solid_se);
    CHECK(solid_se * 1.5 < area_se);
}
