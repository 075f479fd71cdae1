// Tests for constant_medium.h and isotropic.h (chapter 12). A ray crossing a medium of density
// rho for a length d passes without scattering with probability exp(-rho d) (Beer-Lambert), and
// where it does scatter, the distance s travelled inside follows rho exp(-rho s) truncated to
// [0, d]. The medium draws its one random number from the ray's key, so each test sets the keys
// itself, from a pcg32, one per ray, exactly as trace_path draws one per path segment.
//
// Tolerances. A pass fraction over n independent rays is binomial: it lies within 5 standard
// errors sqrt(p (1 - p) / n) of p except with probability ~6e-7. Histograms use Pearson's
// chi-square at alpha = 0.01 (statistics.h). Exact properties (same key, same answer; clipping
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

#include "common/box.h"
#include "common/constant_medium.h"
#include "common/error.h"
#include "common/instance.h"
#include "common/integrator.h"
#include "common/isotropic.h"
#include "common/lambertian.h"
#include "common/rng.h"
#include "common/sampling.h"
#include "common/sphere.h"
#include "statistics.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::point3, rt::real, rt::vec3;

const rt::interval forward(0, rt::infinity);
constexpr real eps = std::numeric_limits<real>::epsilon();

using rt_test::exactly;

std::uint64_t next_key(rt::pcg32& rng) {
    std::uint64_t high = rng.next_u32();
    return (high << 32u) | rng.next_u32();
}

std::shared_ptr<rt::material> any_surface() {
    return std::make_shared<rt::lambertian>(color(0.5, 0.5, 0.5));
}

// The slab 0 <= z <= 2, 100 wide in x and y (wide enough that no ray here leaves by a side).
constexpr real density = real(0.7), thickness = 2;
std::shared_ptr<rt::hittable> slab_boundary() {
    return rt::box(point3(-50, -50, 0), point3(50, 50, thickness), any_surface());
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

struct crossing {
    long long rays = 0, passed = 0;
    std::vector<double> distances;  // |direction| * (t - t_start) of the hits: the path inside
};

// Sends n copies of r, each with a fresh key, at `medium`, restricted to ray_t; distances are
// measured from t_start along the ray.
crossing cross(const rt::hittable& medium, rt::ray r, rt::interval ray_t, real t_start, int n,
               std::uint64_t stream) {
    crossing c;
    rt::pcg32 keys(stream, 0);
    const real speed = r.direction().length();
    for (int k = 0; k < n; ++k) {
        r.set_random_key(next_key(keys));
        rt::hit_record rec;
        ++c.rays;
        if (medium.hit(r, ray_t, rec))
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
        // path starts at t = 0, constant_medium.h): key for key the same answer as (0, inf).
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
    rt::ray r(point3(0, 0, -1), vec3(0, 0, 1));  // inside the medium for t in [1, 3]
    rt::pcg32 keys(4, 0);
    int before = 0, after = 0, inconsistent = 0, clipped_hits = 0;
    long long clipped_passed = 0, late_passed = 0;
    std::vector<double> late_distances;
    const int n = 100000;
    for (int k = 0; k < n; ++k) {
        r.set_random_key(next_key(keys));
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

TEST_CASE("constant_medium: the same key gives the same answer, and a hit record is complete",
          "[ch12]") {
    auto medium = slab();
    auto twin   = slab();  // built the same way: the same id, so the same choices
    rt::pcg32 keys(5, 0);
    int differ = 0, hits = 0;
    for (int k = 0; k < 10000; ++k) {
        rt::ray r(point3(0.5, 0.5, -1), vec3(0.25, -0.5, 1), 0.375);
        r.set_random_key(next_key(keys));
        rt::hit_record a, b, c;
        bool ha = medium->hit(r, forward, a);
        bool hb = medium->hit(r, forward, b);
        bool hc = twin->hit(r, forward, c);
        if (ha != hb || ha != hc || (ha && (a.t != b.t || a.t != c.t))) ++differ;
        if (!ha) continue;
        ++hits;
        // The record of a scattering event: on the ray, inside the slab, with the phase
        // function as its material and no offset for new rays (there is no surface to leave).
        CHECK(exactly(a.p, r.at(a.t)));
        CHECK(a.p.z() >= 0);
        CHECK(a.p.z() <= thickness);
        CHECK(a.mat != nullptr);
        CHECK(a.p_error == 0);
    }
    CHECK(differ == 0);
    CHECK(hits > 1000);
}

TEST_CASE("constant_medium: different media make independent choices for the same key", "[ch12]") {
    // If two media drew the same random number for a key, their choices would be correlated:
    // for equal chords both would pass together with probability p instead of p^2. Independent
    // media pass together with probability p_a p_b; the count is binomial (5 standard errors).
    auto boundary = [](const point3& a, const point3& b) { return rt::box(a, b, any_surface()); };
    const point3 lo(-50, -50, 0), hi(50, 50, thickness);
    struct pair_case {
        const char* what;
        std::shared_ptr<rt::hittable> a, b;
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
        rt::ray r(point3(0, 0, -1), vec3(0, 0, 1));
        rt::pcg32 keys(6, 0);
        const int n    = 100000;
        long long both = 0;
        for (int k = 0; k < n; ++k) {
            r.set_random_key(next_key(keys));
            rt::hit_record rec;
            bool pass_a = !a.hit(r, forward, rec);
            bool pass_b = !b.hit(r, forward, rec);
            both += pass_a && pass_b;
        }
        check_fraction(
            both, n,
            std::exp(-double(c.rho_a) * thickness) * std::exp(-double(c.rho_b) * thickness));
    }
}

TEST_CASE("constant_medium: one medium placed twice (two translates) attenuates like two media",
          "[ch12]") {
    // A slab of thickness 1 and density 0.7, black (albedo 0), in a background of 1: a path
    // returns 1 exactly when it passes without scattering. Through two copies the chance is
    // exp(-0.7 * 2); if both copies reused one random number it would be exp(-0.7).
    auto thin = std::make_shared<rt::constant_medium>(
        rt::box(point3(-1, -1, 0), point3(1, 1, 1), any_surface()), density, color(0, 0, 0));
    rt::scene placed, separate;
    placed.world.add(std::make_shared<rt::translate>(thin, vec3(0, 0, 2)));
    placed.world.add(std::make_shared<rt::translate>(thin, vec3(0, 0, 4)));
    for (real z : {real(2), real(4)})
        separate.world.add(std::make_shared<rt::constant_medium>(
            rt::box(point3(-1, -1, z), point3(1, 1, z + 1), any_surface()), density,
            color(0, 0, 0)));
    for (rt::scene* sc : {&placed, &separate}) {
        INFO((sc == &placed ? "one medium, two translates" : "two media"));
        sc->sky = rt::background::uniform(color(1, 1, 1));
        rt::sampler s(9);
        const int n      = 100000;
        long long passed = 0;
        for (int k = 0; k < n; ++k) {
            s.start_pixel_sample(0, 0, k);
            passed += rt::trace_path(*sc, rt::ray(point3(0, 0, 0), vec3(0, 0, 1)), s, 50).x() == 1;
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
    CHECK_THROWS_WITH(rt::constant_medium(slab_boundary(), -1, color(1, 1, 1)),
                      Catch::Contains("density"));
    CHECK_THROWS_AS(rt::constant_medium(slab_boundary(), 1, color(1.5, 0, 0)), rt::user_error);
    CHECK_THROWS_AS(rt::constant_medium(slab_boundary(), 1, color(nan, 0, 0)), rt::user_error);
    CHECK_THROWS_AS(rt::constant_medium(nullptr, 1, color(1, 1, 1)), rt::user_error);
    CHECK_NOTHROW(rt::constant_medium(slab_boundary(), real(1e-6), color(0, 0, 0)));
}

TEST_CASE("isotropic: scattered directions are uniform on the sphere, weighted by the albedo",
          "[ch12]") {
    const color albedo(0.25, 0.5, 0.75);
    rt::isotropic phase(albedo);
    rt::sampler s(10);
    rt::pcg32 incoming(11, 0);
    // 10 bins of z = cos(theta) (equal areas, by Archimedes) times 20 of the azimuth: under the
    // uniform sphere each bin expects n / 200.
    const int z_bins = 10, phi_bins = 20, n = 100000;
    std::vector<double> observed(z_bins * phi_bins, 0);
    int wrong = 0;
    for (int k = 0; k < n; ++k) {
        s.start_pixel_sample(0, 0, k);
        // Any incoming direction and time: the phase function ignores the direction.
        real u      = incoming.uniform();
        vec3 in_dir = rt::sample_uniform_sphere({u, incoming.uniform()});
        rt::ray r_in(point3(0, 0, 0), 3 * in_dir, 0.625);
        rt::hit_record rec;
        rec.p = point3(1, -2, 3);
        color attenuation;
        rt::ray out;
        if (!phase.scatter(r_in, rec, s, attenuation, out)) {
            ++wrong;
            continue;
        }
        // It starts exactly at the scattering point (a medium has no surface to leave), keeps
        // the time, is unit length to rounding and weighs exactly the albedo.
        const vec3& d = out.direction();
        if (!exactly(out.origin(), rec.p) || out.time() != r_in.time() ||
            !exactly(attenuation, albedo) || std::fabs(d.length() - 1) > 4 * eps)
            ++wrong;
        real z   = std::clamp(d.z(), real(-1), real(1));
        real phi = std::atan2(d.y(), d.x()) + rt::pi;  // in [0, 2 pi]
        int iz   = std::min(int((z + 1) / 2 * z_bins), z_bins - 1);
        int ip   = std::min(int(phi / (2 * rt::pi) * phi_bins), phi_bins - 1);
        observed[std::size_t(iz * phi_bins + ip)] += 1;
    }
    std::vector<double> expected(observed.size(), double(n) / double(observed.size()));
    auto result = rt_test::chi_square_test(observed, expected, 0.01);
    INFO(result.summary);
    CHECK(wrong == 0);
    CHECK(result.passed);

    CHECK_THROWS_AS(rt::isotropic(color(real(1.1), 0, 0)), rt::user_error);
    CHECK_THROWS_AS(rt::isotropic(std::shared_ptr<rt::texture>()), rt::user_error);
}

TEST_CASE("constant_medium: furnace, a white medium sphere returns exactly 1 on every path",
          "[ch12]") {
    // Albedo 1 and no surface: scattering keeps the throughput at 1, and every path ends by
    // leaving the sphere into the background of 1 (max_depth 1000 is never reached: with
    // optical radius 0.5 a path scatters a few times at most). So each path is exactly 1; the
    // mean test below adds nothing but the round-off floor and a readable summary.
    rt::scene sc;
    sc.world.add(std::make_shared<rt::constant_medium>(
        std::make_shared<rt::sphere>(point3(0, 0, 0), 1, any_surface()), 0.5, color(1, 1, 1)));
    sc.sky              = rt::background::uniform(color(1, 1, 1));
    sc.cam.aspect_ratio = 1;
    sc.cam.image_width  = 40;
    sc.cam.vfov         = 32;  // the sphere fills most of the view from distance 4
    sc.cam.lookfrom     = point3(0, 0, 4);
    sc.cam.lookat       = point3(0, 0, 0);
    sc.cam.initialize();

    rt_test::running_mean paths;
    long long not_one = 0, scattered = 0;
    rt::sampler s(12);
    for (int j = 0; j < 40; ++j) {
        for (int i = 0; i < 40; ++i) {
            for (int k = 0; k < 16; ++k) {
                s.start_pixel_sample(i, j, k);
                rt::ray r = sc.cam.get_ray(i, j, s);
                // The first segment's choice, from a copy of the sampler in the same state: so
                // the test knows that many paths really scatter (else 1 would prove nothing).
                rt::sampler peek = s;
                rt::ray first    = r;
                first.set_random_key(peek.next_key());
                rt::hit_record rec;
                scattered += sc.world.hit(first, forward, rec);
                color L = rt::trace_path(sc, r, s, 1000);
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
    // the mean is exp(-1), each path being 0 or 1 (5 standard errors of the mean).
    rt::scene sc;
    sc.world.add(std::make_shared<rt::constant_medium>(
        std::make_shared<rt::sphere>(point3(0, 0, 0), 1, any_surface()), 0.5, color(0, 0, 0)));
    sc.sky = rt::background::uniform(color(1, 1, 1));
    rt::sampler s(13);
    rt_test::running_mean paths;
    long long other = 0;
    for (int k = 0; k < 100000; ++k) {
        s.start_pixel_sample(0, 0, k);
        color L = rt::trace_path(sc, rt::ray(point3(0, 0, -3), vec3(0, 0, 1)), s, 1000);
        other += !exactly(L, color(0, 0, 0)) && !exactly(L, color(1, 1, 1));
        paths.add(double(L.x()));
    }
    CHECK(other == 0);
    auto check = rt_test::mean_within_tolerance(paths.estimate(), std::exp(-1.0), 5);
    INFO(check.summary);
    CHECK(check.passed);
}
