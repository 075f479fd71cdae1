// Tests for constant_medium.h (chapter 12). A ray crossing a medium of density rho for a length d
// passes without scattering with probability exp(-rho d) (Beer-Lambert), and where it does
// scatter, the distance s travelled inside follows rho exp(-rho s) truncated to [0, d].
//
// The medium draws its one random number by hashing the ray (its origin, direction and time)
// with its own id: the same ray always gets the same answer, and independent samples need
// different rays. So where the old tests shot one ray with many keys, these shoot many rays that
// differ only by a random sideways shift of the origin too small to change the path inside (the
// slab is 100 wide; the sphere's chord changes by less than 1e-7), one per sample, as a renderer's
// paths differ. The hash itself is tested too: uniform over random rays and over rays whose
// origins differ in the last bit, and independent between media and between placements.
//
// Tolerances. A pass fraction over n independent rays is binomial: it lies within 5 standard
// errors sqrt(p (1 - p) / n) of p except with probability ~6e-7. Histograms use Pearson's
// chi-square at alpha = 0.01 (statistics.h). Exact properties (same ray, same answer; clipping
// by ray_t; no hit when the boundary is missed) are checked on every ray.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "ch03/material_helpers.h"
#include "ch12/ray_recorder.h"
#include "rt/camera/thin_lens_camera.h"
#include "rt/core/error.h"
#include "rt/core/rng.h"
#include "rt/geometry/box.h"
#include "rt/geometry/instance.h"
#include "rt/geometry/sphere.h"
#include "rt/integrators/path_tracer.h"
#include "rt/media/constant_medium.h"
#include "rt/render/film.h"
#include "rt/samplers/independent_sampler.h"
#include "rt/scene/hittable_list.h"
#include "statistics.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::point3, rt::real, rt::vec3;

const rt::interval forward(0, rt::infinity);

using rt_test::any_material, rt_test::exactly, rt_test::random_in_cube, rt_test::random_unit,
    rt_test::uniform;

// The slab 0 <= z <= 2, 100 wide in x and y (wide enough that no ray here leaves by a side).
constexpr real density = real(0.7), thickness = 2;
std::shared_ptr<rt::bvh> slab_boundary() {
    return rt::box(point3(-50, -50, 0), point3(50, 50, thickness), any_material());
}
std::shared_ptr<rt::constant_medium> slab(real rho = density) {
    return std::make_shared<rt::constant_medium>(slab_boundary(), rho, color(0.5, 0.5, 0.5));
}

// Is the observed fraction within 5 binomial standard errors of p?
void check_fraction(long long count, long long n, double p) {
    double fraction = double(count) / double(n);
    double se       = std::sqrt(p * (1 - p) / double(n));
    INFO("fraction " << fraction << " of " << n << ", expected " << p << " +- " << se
                     << " (binomial standard error); off by " << std::fabs(fraction - p) / se
                     << " standard errors");
    CHECK(std::fabs(fraction - p) <= 5 * se);
}

// The k-th of a family of rays like r: its origin moved sideways (in x and y) by up to
// `spread` at random. Parallel to r, with the same time: the same path through the slab.
rt::ray shifted(const rt::ray& r, rt::pcg32& rng, real spread) {
    const real dx = uniform(rng, -spread, spread);
    const real dy = uniform(rng, -spread, spread);
    return r.continued(r.origin() + vec3(dx, dy, 0), r.direction());
}

struct crossing {
    long long rays = 0, passed = 0;
    std::vector<double> distances;  // |direction| * (t - t_start) of the hits: the path inside
};

// Sends n rays like r (shifted sideways, one random number each) at `medium`, restricted to
// ray_t; distances are measured from t_start along the ray.
crossing cross(const rt::hittable& medium, const rt::ray& r, rt::interval ray_t, real t_start,
               int n, std::uint64_t stream, real spread = real(0.5)) {
    crossing c;
    rt::pcg32 rng(stream, 0);
    const real speed = r.direction().length();
    for (int k = 0; k < n; ++k) {
        rt::hit_record rec;
        ++c.rays;
        if (medium.hit(shifted(r, rng, spread), ray_t, rec))
            c.distances.push_back(double(speed * (rec.t - t_start)));
        else
            ++c.passed;
    }
    return c;
}

// Chi-square of the distances against rho exp(-rho s) on [0, d], renormalized to the hits.
void check_truncated_exponential(const std::vector<double>& distances, double rho, double d) {
    const int bins = 20;
    std::vector<double> observed(bins, 0), expected(bins, 0);
    int outside = 0;
    for (double s : distances) {
        int bin = int(s / d * bins);
        if (s < 0 || s > d)
            ++outside;
        else
            observed[std::size_t(std::min(bin, bins - 1))] += 1;
    }
    const double all = 1 - std::exp(-rho * d);
    for (int i = 0; i < bins; ++i) {
        double s0 = d * i / bins, s1 = d * (i + 1) / bins;
        expected[std::size_t(i)] =
            double(distances.size()) * (std::exp(-rho * s0) - std::exp(-rho * s1)) / all;
    }
    auto result = rt_test::chi_square_test(observed, expected, 0.01);
    INFO(result.summary);
    CHECK(outside == 0);
    CHECK(result.passed);
}

// Chi-square of numbers against the uniform distribution on (0, 1], in `bins` equal bins.
rt_test::chi_square_result uniformity(const std::vector<real>& numbers, int bins) {
    std::vector<double> observed(std::size_t(bins), 0);
    for (real u : numbers) {
        const int bin = std::min(int(double(u) * bins), bins - 1);
        observed[std::size_t(std::max(bin, 0))] += 1;
    }
    const std::vector<double> expected(std::size_t(bins), double(numbers.size()) / bins);
    return rt_test::chi_square_test(observed, expected, 0.01);
}

// Chi-square of pairs (a, b) against the uniform distribution on the unit square, in
// bins x bins cells: a dependence between the two numbers (equal, or one following from the
// other) crowds some cells and empties others.
rt_test::chi_square_result joint_uniformity(const std::vector<real>& a, const std::vector<real>& b,
                                            int bins) {
    REQUIRE(a.size() == b.size());
    std::vector<double> observed(std::size_t(bins * bins), 0);
    auto bin_of = [bins](real u) { return std::min(std::max(int(double(u) * bins), 0), bins - 1); };
    for (std::size_t i = 0; i < a.size(); ++i)
        observed[std::size_t(bin_of(a[i]) * bins + bin_of(b[i]))] += 1;
    const std::vector<double> expected(observed.size(), double(a.size()) / double(observed.size()));
    return rt_test::chi_square_test(observed, expected, 0.01);
}

// Records the rays it is asked about and passes them on to the object it wraps, so that a test
// sees the ray a placement hands its object.
using rt_test::ray_recorder;

}  // namespace

TEST_CASE("constant_medium: the fraction of rays through a slab is exp(-density * thickness)",
          "[ch12]") {
    auto medium = slab();
    // Straight through (d = 2), and at 36.87 degrees (cos 0.8, so d = 2 / 0.8 = 2.5); the
    // directions are not unit, so the medium must measure distance in space, not in t.
    struct config {
        vec3 direction;
        real path;
    };
    for (const config& c : {config{vec3(0, 0, 2.5), thickness}, config{vec3(1.5, 0, 2), 2.5}}) {
        INFO("direction " << c.direction);
        rt::ray r(point3(0.25, -0.125, -1), c.direction);
        // The ray enters at z = 0, at t = 1 / direction.z.
        auto run = cross(*medium, r, forward, 1 / c.direction.z(), 100000, 1);
        check_fraction(run.passed, run.rays, std::exp(-density * c.path));
        check_truncated_exponential(run.distances, density, double(c.path));
    }
}

TEST_CASE("constant_medium: a ray starting inside sees only the medium ahead of it", "[ch12]") {
    auto medium = slab();
    // From z = 0.5: 1.5 left going up, 0.5 going down. Distances are from the origin (t = 0).
    struct config {
        vec3 direction;
        real remaining;
    };
    for (const config& c : {config{vec3(0, 0, 1), 1.5}, config{vec3(0, 0, -3), 0.5}}) {
        INFO("direction " << c.direction);
        auto run = cross(*medium, rt::ray(point3(1, 2, 0.5), c.direction), forward, 0, 100000, 2);
        check_fraction(run.passed, run.rays, std::exp(-density * c.remaining));
        check_truncated_exponential(run.distances, density, double(c.remaining));
        // The medium behind the origin never counts, even when ray_t reaches back there (the
        // path starts at t = 0, constant_medium.h): ray for ray the same answer as (0, inf).
        const auto behind_too = cross(*medium, rt::ray(point3(1, 2, 0.5), c.direction),
                                      rt::interval::universe(), 0, 100000, 2);
        CHECK(behind_too.passed == run.passed);
        CHECK(behind_too.distances == run.distances);
    }
}

TEST_CASE("constant_medium: a ray that misses the boundary, or leaves it behind, never scatters",
          "[ch12]") {
    auto medium            = slab();
    const rt::ray misses[] = {
        rt::ray(point3(200, 0, 1), vec3(0, 1, 0)),    // beside the slab, parallel to it
        rt::ray(point3(0, 0, -1), vec3(0, 0, -1)),    // below it, going down
        rt::ray(point3(0, 0, 3), vec3(0.125, 0, 1)),  // above it, going up
        rt::ray(point3(0, 0, 5), vec3(100, 0, -1)),   // passing beyond its edge
    };
    for (const rt::ray& r : misses) {
        INFO("ray " << r.origin() << " -> " << r.direction());
        auto run = cross(*medium, r, forward, 0, 10000, 3);
        CHECK(run.passed == run.rays);
    }
}

TEST_CASE("constant_medium: ray_t clips the medium: no hit outside it, hits only inside it",
          "[ch12]") {
    auto medium = slab();
    const rt::ray straight(point3(0, 0, -1), vec3(0, 0, 1));  // inside for t in [1, 3]
    rt::pcg32 rng(4, 0);
    int before = 0, after = 0, inconsistent = 0, clipped_hits = 0;
    long long clipped_passed = 0, late_passed = 0;
    std::vector<double> late_distances;
    const int n = 100000;
    for (int k = 0; k < n; ++k) {
        const rt::ray r = shifted(straight, rng, real(0.5));
        rt::hit_record full, rec;
        bool hit = medium->hit(r, forward, full);
        // Ending before the entry, or starting after the exit: nothing to cross.
        before += medium->hit(r, rt::interval(0, real(0.99)), rec);
        after += medium->hit(r, rt::interval(real(3.01), rt::infinity), rec);
        // Ending at t = 2 (half the slab): the same choice as unclipped, cut off at t = 2. A
        // shorter ray does not change where a longer one would scatter.
        bool clipped = medium->hit(r, rt::interval(0, 2), rec);
        if (clipped != (hit && full.t < 2) || (clipped && rec.t != full.t)) ++inconsistent;
        clipped_hits += clipped;
        clipped_passed += !clipped;
        // Starting at t = 1.5: the medium starts there, so this is a fresh 1.5 of medium.
        if (medium->hit(r, rt::interval(1.5, rt::infinity), rec))
            late_distances.push_back(double(rec.t - 1.5));
        else
            ++late_passed;
    }
    CHECK(before == 0);
    CHECK(after == 0);
    CHECK(inconsistent == 0);
    CHECK(clipped_hits > 0);
    check_fraction(clipped_passed, n, std::exp(-density * 1.0));
    check_fraction(late_passed, n, std::exp(-density * 1.5));
    check_truncated_exponential(late_distances, density, 1.5);
}

TEST_CASE("constant_medium: the same ray gives the same answer, and a hit record is complete",
          "[ch12]") {
    auto medium = slab();
    auto twin   = slab();  // built the same way: the same id, so the same choices
    rt::pcg32 rng(5, 0);
    const rt::ray base(point3(0.5, 0.5, -1), vec3(0.25, -0.5, 1), 0.375);
    int differ = 0, hits = 0, elsewhere = 0;
    for (int k = 0; k < 10000; ++k) {
        const rt::ray r = shifted(base, rng, real(0.5));
        rt::hit_record a, b, c;
        bool ha = medium->hit(r, forward, a);
        bool hb = medium->hit(r, forward, b);
        bool hc = twin->hit(r, forward, c);
        if (ha != hb || ha != hc || (ha && (a.t != b.t || a.t != c.t))) ++differ;
        if (!ha) continue;
        ++hits;
        // The distance is -ln(xi) / density with xi = random_for(r), measured in space from the
        // entry at t = 1 (z = 0): the medium's number decides, and nothing else.
        const real distance = (-1 / density) * std::log(medium->random_for(r));
        if (a.t != 1 + distance / r.direction().length()) ++elsewhere;
        // The record of a scattering event: on the ray, inside the slab, with the phase
        // function as its material and no offset for new rays (there is no surface to leave).
        // It names the medium, which has no surface coordinates.
        CHECK(exactly(a.p, r.at(a.t)));
        CHECK(a.p.z() >= 0);
        CHECK(a.p.z() <= thickness);
        CHECK(a.mat != nullptr);
        CHECK(a.p_error == 0);
        CHECK(a.object == medium.get());
        CHECK(a.uv().u == 0);
        CHECK(a.uv().v == 0);
    }
    CHECK(differ == 0);
    CHECK(elsewhere == 0);
    CHECK(hits > 1000);
}

TEST_CASE(
    "constant_medium: its random number is uniform between 0 and 1 over random rays, and over "
    "rays one ulp apart",
    "[ch12]") {
    // The number replaces a sampler dimension, so it must be as uniform as one: 100 bins,
    // 200,000 rays of random origins, directions (of random lengths) and times. Then the rays of
    // a path that differ least: origins whose x coordinates are consecutive doubles (or
    // floats), all else equal, and the same for consecutive times, whose hashes differ in one
    // input bit; their numbers must be uniform too, and each independent of the next.
    auto medium = slab();
    rt::pcg32 rng(14, 0);
    const int n = 200000;
    std::vector<real> random_rays, next_ulp, next_time;
    bool in_range = true;
    for (int k = 0; k < n; ++k) {
        const point3 o = random_in_cube(rng, 10);
        const vec3 d   = uniform(rng, real(0.1), 10) * random_unit(rng);
        const real u   = medium->random_for(rt::ray(o, d, rng.uniform()));
        in_range       = in_range && u > 0 && u <= 1;
        random_rays.push_back(u);
    }
    real x = real(0.25), time = real(0.5);
    const vec3 d(0.125, -0.5, 1);
    for (int k = 0; k < n; ++k) {
        next_ulp.push_back(medium->random_for(rt::ray(point3(x, 0.5, -1), d)));
        next_time.push_back(medium->random_for(rt::ray(point3(0.25, 0.5, -1), d, time)));
        x    = std::nextafter(x, rt::infinity);
        time = std::nextafter(time, rt::infinity);
    }
    for (const auto* numbers : {&random_rays, &next_ulp, &next_time}) {
        for (real u : *numbers) in_range = in_range && u > 0 && u <= 1;
        const auto result = uniformity(*numbers, 100);
        INFO(result.summary);
        CHECK(result.passed);
    }
    CHECK(in_range);
    // Each number against the next one's, for the neighbouring rays.
    for (const auto* numbers : {&next_ulp, &next_time}) {
        const std::vector<real> a(numbers->begin(), numbers->end() - 1),
            b(numbers->begin() + 1, numbers->end());
        const auto result = joint_uniformity(a, b, 10);
        INFO(result.summary);
        CHECK(result.passed);
    }
}

TEST_CASE("constant_medium: different media make independent choices for the same ray", "[ch12]") {
    // If two media drew the same random number for a ray, their choices would be correlated:
    // for equal chords both would pass together with probability p instead of p^2. Independent
    // media pass together with probability p_a p_b; the count is binomial (5 standard errors).
    // And their two numbers, over many rays, fill the unit square evenly (chi-square).
    auto boundary = [](const point3& a, const point3& b) { return rt::box(a, b, any_material()); };
    const point3 lo(-50, -50, 0), hi(50, 50, thickness);
    struct pair_case {
        const char* what;
        std::shared_ptr<rt::bvh> a, b;
        real rho_a, rho_b;
    };
    const pair_case cases[] = {
        {"same box, other density", boundary(lo, hi), boundary(lo, hi), density, real(0.9)},
        {"same density, box moved in x", boundary(lo, hi),
         boundary(lo + vec3(1, 0, 0), hi + vec3(1, 0, 0)), density, density},
        {"same density, box wider in x", boundary(lo, hi), boundary(lo, hi + vec3(1, 0, 0)),
         density, density},
        {"same density, box deeper in y", boundary(lo, hi), boundary(lo, hi + vec3(0, 1, 0)),
         density, density},
        {"same density, box lower in y only", boundary(lo, hi), boundary(lo - vec3(0, 1, 0), hi),
         density, density},
    };
    for (const pair_case& c : cases) {
        INFO(c.what);
        rt::constant_medium a(c.a, c.rho_a, color(1, 1, 1)), b(c.b, c.rho_b, color(1, 1, 1));
        const rt::ray straight(point3(0, 0, -1), vec3(0, 0, 1));
        rt::pcg32 rng(6, 0);
        const int n    = 100000;
        long long both = 0;
        std::vector<real> numbers_a, numbers_b;
        for (int k = 0; k < n; ++k) {
            const rt::ray r = shifted(straight, rng, real(0.5));
            rt::hit_record rec;
            bool pass_a = !a.hit(r, forward, rec);
            bool pass_b = !b.hit(r, forward, rec);
            both += pass_a && pass_b;
            numbers_a.push_back(a.random_for(r));
            numbers_b.push_back(b.random_for(r));
        }
        check_fraction(
            both, n,
            std::exp(-double(c.rho_a) * thickness) * std::exp(-double(c.rho_b) * thickness));
        const auto joint = joint_uniformity(numbers_a, numbers_b, 10);
        INFO(joint.summary);
        CHECK(joint.passed);
    }
}

TEST_CASE("constant_medium: two placements of one medium draw independent numbers", "[ch12]") {
    // One medium, placed twice by translations, twice by rotations, and by a translation and a
    // rotation: each placement hands the medium the world ray in its own frame (an instance
    // tests no box first), which a recorder between them keeps. The medium's numbers for the
    // two rays one world ray becomes must fill the unit square evenly (chi-square), over random
    // world rays: the placements choose independently, though the medium (and its id) is one.
    auto medium = std::make_shared<rt::constant_medium>(
        rt::box(point3(-1, -1, -1), point3(1, 1, 1), any_material()), density, color(1, 1, 1));
    auto recorder = std::make_shared<ray_recorder>(medium);
    using rt::axis;
    struct placement_pair {
        const char* what;
        std::shared_ptr<rt::bounded_hittable> a, b;
    };
    const placement_pair pairs[] = {
        {"two translations", std::make_shared<rt::translate>(recorder, vec3(0, 0, 2)),
         std::make_shared<rt::translate>(recorder, vec3(0, 0, 4))},
        {"translations apart in x", std::make_shared<rt::translate>(recorder, vec3(3, 0, 0)),
         std::make_shared<rt::translate>(recorder, vec3(-3, 0, 0))},
        {"two rotations", std::make_shared<rt::rotate>(recorder, axis::y, 30),
         std::make_shared<rt::rotate>(recorder, axis::y, -30)},
        {"a translation and a rotation", std::make_shared<rt::translate>(recorder, vec3(0, 1, 0)),
         std::make_shared<rt::rotate>(recorder, axis::x, 90)},
    };
    for (const placement_pair& p : pairs) {
        INFO(p.what);
        rt::pcg32 rng(15, 0);
        const int n = 100000;
        std::vector<real> numbers_a, numbers_b;
        int missing = 0;
        for (int k = 0; k < n; ++k) {
            const rt::ray r(random_in_cube(rng, 5), random_unit(rng), rng.uniform());
            rt::hit_record rec;
            recorder->rays.clear();
            p.a->hit(r, forward, rec);
            p.b->hit(r, forward, rec);
            if (recorder->rays.size() != 2) {
                ++missing;
                continue;
            }
            numbers_a.push_back(medium->random_for(recorder->rays[0]));
            numbers_b.push_back(medium->random_for(recorder->rays[1]));
        }
        INFO(missing << " world rays not handed on once by each placement");
        CHECK(missing == 0);
        const auto joint = joint_uniformity(numbers_a, numbers_b, 10);
        INFO(joint.summary);
        CHECK(joint.passed);
    }
}

TEST_CASE("constant_medium: one medium placed twice (two translates) attenuates like two media",
          "[ch12]") {
    // A slab of thickness 1 and density 0.7, black (albedo 0), in a background of 1: a path
    // returns 1 exactly when it passes without scattering. Through two copies the chance is
    // exp(-0.7 * 2); if both copies drew one random number it would be exp(-0.7).
    auto thin = std::make_shared<rt::constant_medium>(
        rt::box(point3(-1, -1, 0), point3(1, 1, 1), any_material()), density, color(0, 0, 0));
    auto placed   = std::make_shared<rt::hittable_list>(),
         separate = std::make_shared<rt::hittable_list>();
    placed->add(std::make_shared<rt::translate>(thin, vec3(0, 0, 2)));
    placed->add(std::make_shared<rt::translate>(thin, vec3(0, 0, 4)));
    for (real z : {real(2), real(4)})
        separate->add(std::make_shared<rt::constant_medium>(
            rt::box(point3(-1, -1, z), point3(1, 1, z + 1), any_material()), density,
            color(0, 0, 0)));
    for (const auto& world : {placed, separate}) {
        INFO((world == placed ? "one medium, two translates" : "two media"));
        const rt::path_tracer tracer(world, rt::background::uniform(color(1, 1, 1)));
        rt::independent_sampler s(9);
        rt::pcg32 rng(7, 0);
        const int n      = 100000;
        long long passed = 0;
        for (int k = 0; k < n; ++k) {
            s.start_pixel_sample(0, 0, k);
            // Parallel rays from random points of the square |x|, |y| < 0.5: the same path
            // through both slabs, a different ray each.
            const rt::ray r = shifted(rt::ray(point3(0, 0, 0), vec3(0, 0, 1)), rng, real(0.5));
            passed += tracer.radiance(r, s, 50).x() == 1;
        }
        check_fraction(passed, n, std::exp(-density * 2.0));
    }
}

TEST_CASE("constant_medium: density <= 0, NaN or infinite, a bad albedo or no boundary throws",
          "[ch12]") {
    const real nan = std::numeric_limits<real>::quiet_NaN();
    for (real bad : {real(0), real(-0.0), real(-1), nan, rt::infinity}) {
        INFO("density " << bad);
        CHECK_THROWS_AS(rt::constant_medium(slab_boundary(), bad, color(1, 1, 1)), rt::user_error);
    }
    CHECK_THROWS_WITH(rt::constant_medium(slab_boundary(), 0, color(1, 1, 1)),
                      Catch::Contains("medium density must be positive and finite, got 0"));
    CHECK_THROWS_AS(rt::constant_medium(slab_boundary(), 1, color(1.5, 0, 0)), rt::user_error);
    CHECK_THROWS_AS(rt::constant_medium(slab_boundary(), 1, color(nan, 0, 0)), rt::user_error);
    CHECK_THROWS_AS(rt::constant_medium(std::shared_ptr<rt::sphere>(), 1, color(1, 1, 1)),
                    rt::user_error);
    CHECK_NOTHROW(rt::constant_medium(slab_boundary(), real(1e-6), color(0, 0, 0)));
}

TEST_CASE("constant_medium: furnace, a white medium sphere returns exactly 1 on every path",
          "[ch12]") {
    // Albedo 1 and no surface: scattering keeps the throughput at 1, and every path ends by
    // leaving the sphere into the background of 1 (max_depth 1000 is never reached: with
    // optical radius 0.5 a path scatters a few times at most). So each path is exactly 1; the
    // mean test below adds nothing but the round-off floor and a readable summary.
    auto world = std::make_shared<rt::hittable_list>();
    world->add(std::make_shared<rt::constant_medium>(
        std::make_shared<rt::sphere>(point3(0, 0, 0), 1, any_material()), 0.5, color(1, 1, 1)));
    const rt::path_tracer tracer(world, rt::background::uniform(color(1, 1, 1)));
    rt::thin_lens_camera cam;
    cam.aspect_ratio = 1;
    cam.vfov         = 32;  // the sphere fills most of the view from distance 4
    cam.lookfrom     = point3(0, 0, 4);
    cam.lookat       = point3(0, 0, 0);
    cam.initialize(rt::film::for_aspect(40, 1));

    rt_test::running_mean paths;
    long long not_one = 0, scattered = 0;
    rt::independent_sampler s(12);
    for (int j = 0; j < 40; ++j) {
        for (int i = 0; i < 40; ++i) {
            for (int k = 0; k < 16; ++k) {
                s.start_pixel_sample(i, j, k);
                rt::ray r = cam.get_ray(i, j, s);
                // The first segment's choice depends on the camera ray alone: asking the world
                // tells the test whether this path scatters (else 1 would prove nothing).
                rt::hit_record rec;
                scattered += world->hit(r, forward, rec);
                color L = tracer.radiance(r, s, 1000);
                not_one += !exactly(L, color(1, 1, 1));
                paths.add(double(L.y()));
            }
        }
    }
    INFO(scattered << " of " << paths.count() << " paths scattered at least once");
    CHECK(not_one == 0);
    // A ray through the center scatters with chance 1 - exp(-1) = 0.63; over the view, at
    // least a fifth of all paths must scatter for this test to mean anything.
    CHECK(scattered > paths.count() / 5);
    auto check = rt_test::mean_within_tolerance(paths.estimate(), 1.0, 5);
    INFO(check.summary);
    CHECK(check.passed);
}

TEST_CASE("constant_medium: black smoke transmits exp(-density * chord) through its center",
          "[ch12]") {
    // Albedo 0: a path that scatters carries nothing afterwards, one that passes sees the
    // background 1. Through the center of a radius-1 sphere of density 0.5 the chord is 2, so
    // the mean is exp(-1), each path being 0 or 1 (5 standard errors of the mean). The rays
    // start up to 1e-4 beside the axis: their chords are shorter by at most 2e-8, which moves
    // exp(-1) by 1e-8, far below the standard error of 1.5e-3.
    auto world = std::make_shared<rt::hittable_list>();
    world->add(std::make_shared<rt::constant_medium>(
        std::make_shared<rt::sphere>(point3(0, 0, 0), 1, any_material()), 0.5, color(0, 0, 0)));
    const rt::path_tracer tracer(world, rt::background::uniform(color(1, 1, 1)));
    rt::independent_sampler s(13);
    rt::pcg32 rng(8, 0);
    rt_test::running_mean paths;
    long long other = 0;
    for (int k = 0; k < 100000; ++k) {
        s.start_pixel_sample(0, 0, k);
        const rt::ray r = shifted(rt::ray(point3(0, 0, -3), vec3(0, 0, 1)), rng, real(1e-4));
        color L         = tracer.radiance(r, s, 1000);
        other += !exactly(L, color(0, 0, 0)) && !exactly(L, color(1, 1, 1));
        paths.add(double(L.x()));
    }
    CHECK(other == 0);
    auto check = rt_test::mean_within_tolerance(paths.estimate(), std::exp(-1.0), 5);
    INFO(check.summary);
    CHECK(check.passed);
}
