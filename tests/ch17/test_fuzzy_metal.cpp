// Tests for metal's density (chapter 17: metal::spread_is_evaluable, spread_eval, spread_pdf; here
// pdf() and eval() name those two) and for MIS that
// weighs fuzzy metal with it (mis_choices::weigh_fuzzy_metal). scatter() aims at a point uniform
// in the ball of radius fuzz about the unit mirror direction m and absorbs what points below the
// surface, so pdf() must be the density of those directions, integrating to the share of draws
// kept, not to 1, where the ball dips below the surface (a grazing ray). Checked by chi-square
// of drawn directions against pdf() integrated over bins about m (ch14/direction_checks.h), the
// integral against the share kept, the weight against eval / pdf, pdf() against the chord
// integral (t+^3 - t-^3) / 3 / ball volume computed apart from it, and against 2 c^3 / pi for
// fuzz 1 at normal incidence. Hard cases: a fuzz of 1e-5 and at min_evaluable_fuzz, finite; a
// mirror, no density. And MIS keeps the path tracer's mean on fuzzy metal, with a lamp that only
// a ray below the surface could reach, and is far less noisy where a small lamp is mirrored.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "ch03/material_helpers.h"
#include "ch14/direction_checks.h"
#include "ch14/estimator_scenes.h"
#include "rt/integrators/mis_tracer.h"
#include "rt/integrators/path_tracer.h"
#include "rt/materials/metal.h"
#include "rt/materials/optics.h"
#include "rt/samplers/independent_sampler.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::point3, rt::real, rt::vec3;
using rt_test::direction_checks::ddot, rt_test::direction_checks::dunit;
using rt_test::direction_checks::direction_bins, rt_test::direction_checks::dvec;
using rt_test::direction_checks::to_double;
using rt_test::estimator_scenes::check_run, rt_test::estimator_scenes::check_same_mean;
using rt_test::estimator_scenes::estimate, rt_test::estimator_scenes::run;
using rt_test::estimator_scenes::test_scene;

constexpr double pi  = rt_test::sampling_checks::pi;
const real eps       = std::numeric_limits<real>::epsilon();
const color albedo   = color(0.9, 0.6, 0.3);
const real fuzzes[4] = {1, real(0.5), real(0.1), real(0.01)};

// Every material under test is made here and used through the interface, as an integrator does.
std::shared_ptr<rt::material> fuzzy_metal(real fuzz) {
    return std::make_shared<rt::metal>(albedo, fuzz);
}

struct incidence {
    std::string name;
    rt::hit_record rec;
    rt::ray r_in;
};

// A ray arriving at p at `degrees` from the unit normal n (which faces it), from one unit away.
incidence arriving(std::string name, const point3& p, const vec3& n, bool front_face,
                   double degrees, const vec3& towards) {
    const double theta = degrees * pi / 180;
    const vec3 tangent = rt::unit_vector(cross(n, towards));
    const vec3 d       = real(-std::cos(theta)) * n + real(std::sin(theta)) * tangent;
    return {std::move(name), rt_test::hit_at(p, n, front_face), rt::ray(p - d, d)};
}

// Normals on the axes and off them, both faces; from straight on to grazing, where the mirror
// direction is 5 and then half a degree above the surface and much of the ball lies below it.
std::vector<incidence> incidences() {
    return {
        arriving("straight on, +z normal", point3(0.1, -0.45, 0.37), vec3(0, 0, 1), true, 0,
                 vec3(1, 0, 0)),
        arriving("45 degrees, -y normal, back face", point3(0.2, -0.25, 0.37), vec3(0, -1, 0),
                 false, 45, vec3(0, 0, 1)),
        arriving("60 degrees, a normal off the axes", point3(0.3, -0.05, 0.37),
                 rt::unit_vector(vec3(0.3, -0.8, 0.52)), true, 60, vec3(0, 0, 1)),
        arriving("grazing, 85 degrees, back face", point3(-0.3, 0.15, 0.37),
                 rt::unit_vector(vec3(-0.9, 0.1, -0.2)), false, 85, vec3(0, 1, 0)),
        arriving("grazing, 89.5 degrees, -z normal", point3(0.4, 0.35, 0.37), vec3(0, 0, -1), true,
                 89.5, vec3(1, 1, 0)),
    };
}

// The unit mirror direction, in double, from the ray and normal as scatter() gets them.
dvec mirror_of(const incidence& h) {
    const dvec d = dunit(to_double(h.r_in.direction())), n = to_double(h.rec.normal);
    const double dn = ddot(d, n);
    return dunit({d[0] - 2 * dn * n[0], d[1] - 2 * dn * n[1], d[2] - 2 * dn * n[2]});
}
vec3 to_vec3(const dvec& v) {
    return vec3(real(v[0]), real(v[1]), real(v[2]));
}

// 1 - cos of the half-angle asin(fuzz) of the cone the ball subtends, without cancellation.
double cone_x(double fuzz) {
    return fuzz * fuzz / (1 + std::sqrt(1 - fuzz * fuzz));
}

// Whether the ball lies wholly above the surface: its center m is at least fuzz above it. At 60
// degrees with fuzz 0.5 it touches the surface, where rounding may put it a hair either way.
bool ball_above(const incidence& h, double fuzz) {
    return ddot(mirror_of(h), to_double(h.rec.normal)) >= fuzz - 1e-6;
}

bool close(const color& a, const color& b) {
    for (int i = 0; i < 3; ++i) {
        if (!(std::fabs(a[i] - b[i]) <= 16 * eps * std::fabs(b[i]))) return false;
    }
    return true;
}

bool finite(const color& c) {
    return std::isfinite(c.x()) && std::isfinite(c.y()) && std::isfinite(c.z());
}

// A point uniform in the unit ball.
vec3 in_unit_ball(rt::pcg32& rng) {
    return std::cbrt(rng.uniform()) * rt_test::random_unit(rng);
}

}  // namespace

TEST_CASE(
    "metal: drawn directions follow pdf(), which integrates to the share of draws not absorbed",
    "[ch17]") {
    // 50,000 draws: the share kept is known to 0.0022 (one standard deviation), and a bin of 500
    // expected draws to 4.5 %; a density twice too large, or one that counts the part of the
    // ball below the surface, misses the share by far more.
    const int n            = 50000;
    std::uint64_t sequence = 1730;
    for (real fuzz : fuzzes) {
        const auto mat = fuzzy_metal(fuzz);
        for (const incidence& h : incidences()) {
            INFO("fuzz " << fuzz << ", " << h.name);
            REQUIRE(mat->spread_is_evaluable());
            // Beyond the cone by a fifth: a direction drawn outside it, where pdf() is 0, fails.
            const direction_bins bins(to_vec3(mirror_of(h)), 1.2 * cone_x(fuzz), 10, 12);
            rt::independent_sampler s(sequence);
            int k     = 0;
            auto draw = [&](rt::pcg32&, vec3& wi, real& pdf) {
                s.start_pixel_sample(k++, 0, 0);
                const auto sample = mat->scatter(h.r_in, h.rec, s);
                if (!sample) return false;
                wi  = rt::unit_vector(sample->scattered.direction());
                pdf = mat->spread_pdf(h.r_in, h.rec, wi);
                return true;
            };
            auto pdf = [&](const vec3& wi) { return mat->spread_pdf(h.r_in, h.rec, wi); };
            const auto t =
                rt_test::direction_checks::test_directions(bins, draw, pdf, n, sequence++, 0);
            const double kept = double(t.drawn) / n;
            INFO(t.summary << "; share kept " << kept);
            CHECK(t.chi_square.passed);
            if (ball_above(h, fuzz)) {
                CHECK(t.refused == 0);
                CHECK(std::fabs(t.total - 1) <= 1e-3);
            } else {
                // 5 standard deviations of the binomial share, and the integration's error.
                const double tolerance = 5 * std::sqrt(kept * (1 - kept) / n) + 1e-3;
                CHECK(t.refused > 0);
                CHECK(std::fabs(t.total - kept) <= tolerance);
            }
        }
    }
}

TEST_CASE("metal: the weight of a drawn direction is eval / pdf, and its pdf is not 0", "[ch17]") {
    rt::independent_sampler s(1701);
    int n = 0, no_density = 0, wrong = 0;
    for (real fuzz : {real(1), real(0.5), real(0.1), real(0.01), real(0.001)}) {
        const auto mat = fuzzy_metal(fuzz);
        for (const incidence& h : incidences()) {
            for (int k = 0; k < 2000; ++k, ++n) {
                s.start_pixel_sample(n, 0, 0);
                const auto sample = mat->scatter(h.r_in, h.rec, s);
                if (!sample) continue;
                const vec3 wi = rt::unit_vector(sample->scattered.direction());
                const real p  = mat->spread_pdf(h.r_in, h.rec, wi);
                if (!(p > 0) || !std::isfinite(p)) {
                    if (no_density < 3)
                        UNSCOPED_INFO("fuzz " << fuzz << ", " << h.name << ", wi " << wi << ": pdf "
                                              << p);
                    ++no_density;
                    continue;
                }
                const color weight = mat->spread_eval(h.r_in, h.rec, wi) / p;
                if (!close(sample->weight, weight)) {
                    if (wrong < 3)
                        UNSCOPED_INFO("fuzz " << fuzz << ", " << h.name << ", wi " << wi
                                              << ": weight " << sample->weight << ", eval / pdf "
                                              << weight);
                    ++wrong;
                }
            }
        }
    }
    CHECK(no_density == 0);  // scatter() drew a direction pdf() says it never draws
    CHECK(wrong == 0);
}

TEST_CASE(
    "metal: pdf() is the chord integral inside the cone above the surface, 0 below it and "
    "outside the cone, and eval is albedo times pdf",
    "[ch17]") {
    // The reference, in double: t w is in the ball where t^2 - 2 c t + 1 - fuzz^2 <= 0, from
    // t- to t+ = c -+ h, h^2 = c^2 - 1 + fuzz^2 (taken as fuzz^2 - |w x m|^2: c^2 - 1 loses the
    // digits of a narrow cone), and the density is the integral of t^2 dt over that chord
    // divided by the ball's volume. Away from the cone's edge (h^2 >= fuzz^2 / 4) pdf() may
    // differ from it by the roundings of w x m in rt::real (|w x m|^2 off by a few eps times
    // fuzz, against h^2): relative 64 eps (1 + 1 / fuzz).
    rt::pcg32 rng(1702, 1);
    long long compared = 0, below = 0, outside = 0, wrong = 0;
    for (real fuzz : {real(1), real(0.5), real(0.1), real(0.01), real(0.001)}) {
        const auto mat = fuzzy_metal(fuzz);
        const double f = fuzz, tolerance = 64 * double(eps) * (1 + 1 / f);
        for (const incidence& h : incidences()) {
            const dvec m = mirror_of(h), n = to_double(h.rec.normal);
            for (int k = 0; k < 4000; ++k) {
                // Half towards the ball and a little beyond it, half anywhere on the sphere.
                const vec3 wi =
                    k % 2 == 0 ? rt::unit_vector(to_vec3(m) + real(1.3) * fuzz * in_unit_ball(rng))
                               : rt_test::random_unit(rng);
                const dvec w       = dunit(to_double(wi));
                const double c     = ddot(w, m);
                const dvec x       = {w[1] * m[2] - w[2] * m[1], w[2] * m[0] - w[0] * m[2],
                                      w[0] * m[1] - w[1] * m[0]};
                const double h2    = f * f - ddot(x, x);
                const double above = ddot(w, n);
                const real p       = mat->spread_pdf(h.r_in, h.rec, wi);
                const color e      = mat->spread_eval(h.r_in, h.rec, wi);
                bool ok = std::isfinite(p) && p >= 0 && close(e, p * albedo) && finite(e);
                if (above < -1e-6 || h2 < -0.02 * f * f || c < 0) {
                    // Below the surface, or outside the cone (or the cone opposite it, c < 0).
                    ok = ok && p == 0 && rt_test::exactly(e, color(0, 0, 0));
                    if (above < -1e-6)
                        ++below;
                    else
                        ++outside;
                } else if (above > 1e-6 && h2 >= f * f / 4) {
                    const double t1 = c + std::sqrt(h2), t0 = c - std::sqrt(h2);
                    const double expected =
                        (t1 * t1 * t1 - t0 * t0 * t0) / 3 / (4 * pi * f * f * f / 3);
                    ok = ok && std::fabs(double(p) - expected) <= tolerance * expected;
                    ++compared;
                }
                if (!ok) {
                    if (wrong < 3)
                        UNSCOPED_INFO("fuzz " << fuzz << ", " << h.name << ", wi " << wi << ": pdf "
                                              << p << ", eval " << e << "; c " << c << ", h^2 "
                                              << h2 << ", cos to the normal " << above);
                    ++wrong;
                }
            }
        }
    }
    INFO(compared << " compared inside the cone, " << below << " below the surface, " << outside
                  << " outside the cone");
    CHECK(wrong == 0);
    CHECK(compared > 10000);
    CHECK(below > 10000);
    CHECK(outside > 10000);
}

TEST_CASE("metal: with fuzz 1, straight on, pdf() is 2 c^3 / pi of the cosine c to the normal",
          "[ch17]") {
    // The ball of radius 1 touches the hit: the chord from 0 to 2c gives h = c, and
    // h (3 c^2 + h^2) / (2 pi) = 2 c^3 / pi, which integrates to 1 over the hemisphere.
    const auto mat    = fuzzy_metal(1);
    const incidence h = incidences()[0];
    const vec3 n      = h.rec.normal;
    rt::pcg32 rng(1703, 1);
    int wrong = 0;
    for (int k = 0; k < 20000; ++k) {
        const vec3 wi         = rt_test::random_unit(rng);
        const double c        = double(dot(wi, n));
        const double p        = double(mat->spread_pdf(h.r_in, h.rec, wi));
        const double expected = c > 0 ? 2 * c * c * c / pi : 0;
        // h^2 = 1 - |w x n|^2 loses about eps / c^2 relative to it; far enough from the
        // horizon that this stays small, it must match closely.
        bool ok = p >= 0 && std::isfinite(p);
        if (c < -1e-6) ok = ok && p == 0;
        if (c > 0.05)
            ok = ok && std::fabs(p - expected) <= 32 * double(eps) * (1 + 1 / (c * c)) * expected;
        if (!ok) {
            if (wrong < 3)
                UNSCOPED_INFO("wi " << wi << ": pdf " << p << ", 2 c^3 / pi " << expected);
            ++wrong;
        }
    }
    CHECK(wrong == 0);
    // Straight back along the normal: 2 / pi.
    CHECK(double(mat->spread_pdf(h.r_in, h.rec, n)) == Approx(2 / pi).epsilon(16 * double(eps)));
}

TEST_CASE(
    "metal: a fuzz of 1e-5 and at min_evaluable_fuzz gives finite densities, about "
    "3 / (2 pi fuzz^2) at the mirror direction",
    "[ch17][hardcase]") {
    // Whole ball above the surface here, so no draw may be absorbed; the mirror direction is
    // the chord through the center, t from 1 - fuzz to 1 + fuzz: (3 + fuzz^2) / (2 pi fuzz^2).
    rt::independent_sampler s(1704);
    int n = 0;
    for (real fuzz : {real(1e-5), rt::metal::min_evaluable_fuzz}) {
        const auto mat = fuzzy_metal(fuzz);
        REQUIRE(mat->spread_is_evaluable());
        for (const incidence& h : incidences()) {
            INFO("fuzz " << fuzz << ", " << h.name);
            const vec3 m          = rt::unit_vector(rt::reflect(h.r_in.direction(), h.rec.normal));
            const double f        = fuzz;
            const double expected = (3 + f * f) / (2 * pi * f * f);
            const real p          = mat->spread_pdf(h.r_in, h.rec, m);
            CHECK(double(p) == Approx(expected).epsilon(16 * double(eps)));
            CHECK(finite(mat->spread_eval(h.r_in, h.rec, m)));
            // The power heuristic squares such densities: still a weight in [0, 1].
            for (real other : {real(0), real(1e-3), real(1), p, real(1e12)}) {
                const real w = rt::power_heuristic(p, other), v = rt::power_heuristic(other, p);
                CHECK((w >= 0 && w <= 1 && v >= 0 && v <= 1));
            }
            // Drawn directions: finite densities and weights, none absorbed. In float a fuzz of
            // 1e-6 is a few units in the last place of the mirror direction, so a direction
            // drawn near the cone's edge may round out of it (pdf 0): at most 1 in 100.
            REQUIRE(ball_above(h, f));
            int drawn = 0, absorbed = 0, no_density = 0, not_finite = 0, too_dense = 0;
            for (int k = 0; k < 2000; ++k, ++n) {
                s.start_pixel_sample(n, 0, 0);
                const auto sample = mat->scatter(h.r_in, h.rec, s);
                if (!sample) {
                    ++absorbed;
                    continue;
                }
                ++drawn;
                const vec3 wi  = rt::unit_vector(sample->scattered.direction());
                const real pdf = mat->spread_pdf(h.r_in, h.rec, wi);
                const color e  = mat->spread_eval(h.r_in, h.rec, wi);
                not_finite += !std::isfinite(pdf) || !finite(e) || !finite(sample->weight);
                no_density += !(pdf > 0);
                too_dense += !(pdf <= expected * (1 + 16 * double(eps)));
            }
            CHECK(absorbed == 0);
            CHECK(too_dense == 0);  // nowhere denser than along the mirror direction
            CHECK(not_finite == 0);
            if (std::is_same_v<real, double>) CHECK(no_density == 0);
            CHECK(no_density * 100 <= drawn);
        }
    }
}

TEST_CASE("metal: a mirror, or a fuzz below min_evaluable_fuzz, has no density to weigh",
          "[ch17][hardcase]") {
    const incidence h = incidences()[2];
    const vec3 m      = rt::unit_vector(rt::reflect(h.r_in.direction(), h.rec.normal));
    const real min    = rt::metal::min_evaluable_fuzz;
    CHECK(min == real(1e-6));
    for (real fuzz : {real(0), real(1e-9), real(0.5e-6), std::nextafter(min, real(0))}) {
        INFO("fuzz " << fuzz);
        const auto mat = fuzzy_metal(fuzz);
        CHECK_FALSE(mat->spread_is_evaluable());
        CHECK(mat->spread_pdf(h.r_in, h.rec, m) == 0);
        CHECK(rt_test::exactly(mat->spread_eval(h.r_in, h.rec, m), color(0, 0, 0)));
    }
    for (real fuzz : {min, real(1e-5), real(0.3), real(1)}) {
        INFO("fuzz " << fuzz);
        CHECK(fuzzy_metal(fuzz)->spread_is_evaluable());
    }
}

TEST_CASE(
    "metal: chapters 14-16 still only follow it: a sampled_only lobe, samples without density",
    "[ch17]") {
    rt::independent_sampler s(1705);
    int n = 0;
    for (real fuzz : {real(0), real(1e-5), real(0.3), real(1)}) {
        INFO("fuzz " << fuzz);
        const auto mat = fuzzy_metal(fuzz);
        CHECK(mat->lobe_kind() == rt::lobe::sampled_only);
        for (const incidence& h : incidences()) {
            // Chapter 14's eval and pdf stay 0: the density is only under its own names.
            const vec3 m = rt::unit_vector(rt::reflect(h.r_in.direction(), h.rec.normal));
            CHECK(mat->pdf(h.r_in, h.rec, m) == 0);
            CHECK(rt_test::exactly(mat->eval(h.r_in, h.rec, m), color(0, 0, 0)));
            for (int k = 0; k < 50; ++k) {
                s.start_pixel_sample(n++, 0, 0);
                if (const auto sample = mat->scatter(h.r_in, h.rec, s)) {
                    CHECK(sample->from == rt::lobe::sampled_only);
                    CHECK(sample->pdf == 0);
                }
            }
        }
    }
    // And chapter 17's MIS weighs it only when asked.
    CHECK_FALSE(rt::mis_choices{}.weigh_fuzzy_metal);
}

namespace {

using rt_test::estimator_scenes::lamp, rt_test::estimator_scenes::no_closed_form;

std::shared_ptr<rt::quad> metal_floor(real fuzz, real x0, real x1) {
    return std::make_shared<rt::quad>(point3(x0, 0, -3), vec3(x1 - x0, 0, 0), vec3(0, 0, 6),
                                      fuzzy_metal(fuzz));
}

// A small sphere lamp above a fuzzy metal floor, and the eye where the floor mirrors it: where
// the metal is only followed, the lamp is found only by the rare scattered ray that hits it.
test_scene small_lamp_over_metal(real fuzz) {
    auto world = std::make_shared<rt::hittable_list>();
    world->add(metal_floor(fuzz, -3, 6));
    world->add(std::make_shared<rt::sphere>(point3(0, 1, 0), real(0.15), lamp(20)));
    return {"a small lamp over metal of fuzz " + std::to_string(fuzz),
            world,
            rt::background::uniform(color(0, 0, 0)),
            point3(3, 1, 0),
            point3(1.5, 0, 0),
            real(0.3),
            4,
            no_closed_form};
}

// The eye low over a fuzzy metal floor (6 to 13 degrees up from it, fuzz 0.3: a cone of 17.5
// degrees, much of it below), a lamp ahead, and a second lamp below the floor's plane that only
// a direction under the surface would reach: a shadow ray towards it starts below the floor
// and meets nothing, so a density that is not 0 there would add its light.
test_scene grazing_on_metal() {
    auto world = std::make_shared<rt::hittable_list>();
    world->add(metal_floor(real(0.3), real(-1.5), 6));
    world->add(
        std::make_shared<rt::quad>(point3(-3, 0.1, -0.5), vec3(0, 0.8, 0), vec3(0, 0, 1), lamp(8)));
    world->add(std::make_shared<rt::sphere>(point3(-2.5, -0.4, 0), real(0.2), lamp(10)));
    return {"grazing on metal, a lamp ahead and one below its plane",
            world,
            rt::background::uniform(color(0, 0, 0)),
            point3(4, 0.3, 0),
            point3(0.5, -0.3, 0),
            real(0.2),
            6,
            no_closed_form};
}

rt::mis_choices weighing_metal(bool weigh) {
    rt::mis_choices choices;
    choices.weigh_fuzzy_metal = weigh;
    return choices;
}

}  // namespace

TEST_CASE(
    "metal: mis that weighs fuzzy metal keeps the mean of mis that follows it, and of the path "
    "tracer",
    "[ch17]") {
    std::uint64_t seed             = 1710;
    std::vector<test_scene> scenes = {small_lamp_over_metal(real(0.4)),
                                      small_lamp_over_metal(real(0.02)), grazing_on_metal(),
                                      rt_test::estimator_scenes::glass_over_floor()};
    for (const test_scene& sc : scenes) {
        INFO(sc.name);
        const rt::path_tracer path(sc.world, sc.sky);
        const rt::mis_tracer following(sc.world, sc.sky, weighing_metal(false));
        const rt::mis_tracer weighing(sc.world, sc.sky, weighing_metal(true));
        const run by_path      = estimate(path, sc, 40000, seed++);
        const run by_following = estimate(following, sc, 40000, seed++);
        const run by_weighing  = estimate(weighing, sc, 40000, seed++);
        check_run(by_weighing, sc);
        INFO("standard errors: following " << by_following.radiance.estimate().standard_error
                                           << ", weighing "
                                           << by_weighing.radiance.estimate().standard_error);
        {
            INFO("against mis that follows metal");
            check_same_mean(by_weighing, by_following);
        }
        {
            INFO("against the path tracer");
            check_same_mean(by_weighing, by_path);
        }
    }
}

TEST_CASE("metal: a small lamp mirrored in fuzzy metal is far less noisy when metal is weighed",
          "[ch17]") {
    // The lamp covers a few percent of the fuzz's cone: followed, a path finds it once in tens
    // of tries; weighed, a shadow ray aims at it every time.
    const test_scene sc = small_lamp_over_metal(real(0.4));
    const run following =
        estimate(rt::mis_tracer(sc.world, sc.sky, weighing_metal(false)), sc, 20000, 1720);
    const run weighing =
        estimate(rt::mis_tracer(sc.world, sc.sky, weighing_metal(true)), sc, 20000, 1721);
    check_same_mean(following, weighing);
    const double following_se = following.radiance.estimate().standard_error;
    const double weighing_se  = weighing.radiance.estimate().standard_error;
    INFO("standard errors: following " << following_se << ", weighing " << weighing_se);
    CHECK(weighing_se * 3 < following_se);
}
