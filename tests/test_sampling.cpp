// The warps of common/sampling.h, each held to its pdf: every sample lies in its domain, a
// chi-square test of 1e6 samples against expected counts integrated from the pdf over each bin,
// and the pdf functions integrated numerically over the same bins (they must sum to 1).
// Chapter 03 (sphere, cosine hemisphere and the disk it is built on), 04 (ball), 06 (disk, lens).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "common/rng.h"
#include "common/sampling.h"
#include "statistics.h"

using rt::real;
using rt::sample2;
using rt::vec3;

namespace {

constexpr double pi     = 3.14159265358979323846;
constexpr double two_pi = 2 * pi;
constexpr real eps      = std::numeric_limits<real>::epsilon();
constexpr double alpha  = 0.01;

// Bins of [0, 1); a coordinate that rounds to 1 (or a hair beyond) goes into the last bin, and a
// NaN into the first, since the domain checks, not the histogram, police the boundary.
std::size_t cell(double t, int n) {
    if (!(t > 0)) return 0;
    if (t >= 1) return std::size_t(n - 1);
    return std::size_t(t * n);
}

// Azimuth of (x, y) as a fraction of a turn, in [0, 1).
double azimuth01(const vec3& p) {
    double phi = std::atan2(double(p.y()), double(p.x())) / two_pi;
    return phi < 0 ? phi + 1 : phi;
}

// Composite Simpson rule with m (even) steps: error (b - a) h^4 max|f''''| / 180, which for the
// smooth integrands below (r, r^2, sin, sin cos over one bin) is below 1e-9 of the bin's integral.
template <class F>
double simpson(F f, double a, double b, int m = 64) {
    double h = (b - a) / m, sum = f(a) + f(b);
    for (int k = 1; k < m; ++k) sum += (k % 2 ? 4 : 2) * f(a + k * h);
    return sum * h / 3;
}

// Every pdf here is symmetric about z, so each binning splits the azimuth into nphi equal parts
// and its integral is a factor dphi. probability() is the closed-form integral of the pdf formula
// over a bin; integrate_pdf() integrates the pdf *function* numerically over the same bin in the
// natural coordinates (r, theta), so the two meet only if the function is the density.

// Disk: r^2 x phi, so that equal-area bins get equal counts. dA = r dr dphi.
struct disk_bins {
    static constexpr int nr = 10, nphi = 20;
    static constexpr double dphi = two_pi / nphi;
    int count() const { return nr * nphi; }
    std::size_t index(const vec3& p) const {
        double r2 = double(p.x()) * p.x() + double(p.y()) * p.y();
        return cell(r2, nr) * nphi + cell(azimuth01(p), nphi);
    }
    double probability(std::size_t bin) const {
        double r2_0 = double(bin / nphi) / nr, r2_1 = double(bin / nphi + 1) / nr;
        return double(rt::uniform_disk_pdf()) * (r2_1 - r2_0) / 2 * dphi;
    }
    double integrate_pdf(std::size_t bin) const {
        double r0 = std::sqrt(double(bin / nphi) / nr), r1 = std::sqrt(double(bin / nphi + 1) / nr);
        return simpson([](double r) { return double(rt::uniform_disk_pdf()) * r; }, r0, r1) * dphi;
    }
};

// Sphere: z x phi (Archimedes: equal z slabs have equal areas). dw = sin(theta) dtheta dphi.
struct sphere_bins {
    static constexpr int nz = 20, nphi = 20;
    static constexpr double dphi = two_pi / nphi;
    int count() const { return nz * nphi; }
    std::size_t index(const vec3& d) const {
        return cell((double(d.z()) + 1) / 2, nz) * nphi + cell(azimuth01(d), nphi);
    }
    static double z_edge(std::size_t i) { return -1 + 2 * double(i) / nz; }
    double probability(std::size_t bin) const {
        return double(rt::uniform_sphere_pdf()) * (z_edge(bin / nphi + 1) - z_edge(bin / nphi)) *
               dphi;
    }
    double integrate_pdf(std::size_t bin) const {
        auto f = [](double theta) { return double(rt::uniform_sphere_pdf()) * std::sin(theta); };
        return simpson(f, std::acos(z_edge(bin / nphi + 1)), std::acos(z_edge(bin / nphi))) * dphi;
    }
};

// Cosine hemisphere: cos(theta) x phi over z >= 0. The pdf is cos(theta) / pi per solid angle,
// so a bin [z0, z1] x dphi holds (z1^2 - z0^2) / 2 * dphi / pi: unequal counts, small near the
// horizon.
struct hemisphere_bins {
    static constexpr int nz = 10, nphi = 20;
    static constexpr double dphi = two_pi / nphi;
    int count() const { return nz * nphi; }
    std::size_t index(const vec3& d) const {
        return cell(double(d.z()), nz) * nphi + cell(azimuth01(d), nphi);
    }
    static double z_edge(std::size_t i) { return double(i) / nz; }
    double probability(std::size_t bin) const {
        double z0 = z_edge(bin / nphi), z1 = z_edge(bin / nphi + 1);
        return (z1 * z1 - z0 * z0) / 2 * dphi / pi;
    }
    double integrate_pdf(std::size_t bin) const {
        auto f = [](double theta) {
            return double(rt::cosine_hemisphere_pdf(real(std::cos(theta)))) * std::sin(theta);
        };
        return simpson(f, std::acos(z_edge(bin / nphi + 1)), std::acos(z_edge(bin / nphi))) * dphi;
    }
};

// Ball: r^3 x cos(theta) x phi (equal volumes). dV = r^2 dr sin(theta) dtheta dphi.
struct ball_bins {
    static constexpr int nr = 8, nz = 8, nphi = 16;
    static constexpr double dphi = two_pi / nphi;
    int count() const { return nr * nz * nphi; }
    std::size_t index(const vec3& p) const {
        double r = double(p.length());
        double z = r > 0 ? double(p.z()) / r : 0;  // the centre itself has no direction
        return (cell(r * r * r, nr) * nz + cell((z + 1) / 2, nz)) * nphi + cell(azimuth01(p), nphi);
    }
    static double r3_edge(std::size_t i) { return double(i) / nr; }
    static double z_edge(std::size_t i) { return -1 + 2 * double(i) / nz; }
    double probability(std::size_t bin) const {
        std::size_t ir = bin / (nz * nphi), iz = (bin / nphi) % nz;
        return double(rt::uniform_ball_pdf()) * (r3_edge(ir + 1) - r3_edge(ir)) / 3 *
               (z_edge(iz + 1) - z_edge(iz)) * dphi;
    }
    double integrate_pdf(std::size_t bin) const {
        std::size_t ir = bin / (nz * nphi), iz = (bin / nphi) % nz;
        // The pdf is constant, so the triple integral is pdf times the bin's volume, integrated
        // here in (r, theta) rather than taken from the closed form above.
        double radial  = simpson([](double r) { return r * r; }, std::cbrt(r3_edge(ir)),
                                std::cbrt(r3_edge(ir + 1)));
        double angular = simpson([](double theta) { return std::sin(theta); },
                                 std::acos(z_edge(iz + 1)), std::acos(z_edge(iz)));
        return double(rt::uniform_ball_pdf()) * radial * angular * dphi;
    }
};

sample2 next_sample2(rt::pcg32& rng) {
    real u = rng.uniform();
    return {u, rng.uniform()};
}

// Bins `samples` warped points and compares them with the binning's expected counts.
template <class Bins, class Warp>
rt_test::chi_square_result chi_square(const Bins& bins, Warp warp, int samples,
                                      std::uint64_t sequence) {
    std::vector<double> observed(std::size_t(bins.count()), 0), expected(observed.size());
    rt::pcg32 rng(sequence, 1);
    for (int i = 0; i < samples; ++i) observed[bins.index(warp(rng))] += 1;
    for (std::size_t b = 0; b < expected.size(); ++b) expected[b] = samples * bins.probability(b);
    return rt_test::chi_square_test(observed, expected, alpha);
}

// The numeric integral of the pdf over each bin matches the closed form the chi-square test
// used, and the bins together hold probability 1. Simpson's error is below 1e-9 of each bin
// (see simpson) and the pdf functions return `real`, so they are exact only to about one
// rounding of 1/pi and one of cos(theta): 1e-8 + 2 eps relative (2.4e-7 in a float build) is
// tight enough to catch any wrong constant or wrong power.
template <class Bins>
void check_pdf_matches_bins(const Bins& bins) {
    const double tolerance = 1e-8 + 2 * double(eps);
    double total           = 0;
    int mismatches         = 0;
    for (std::size_t b = 0; b < std::size_t(bins.count()); ++b) {
        double numeric = bins.integrate_pdf(b), closed = bins.probability(b);
        if (!(std::fabs(numeric - closed) <= tolerance * closed)) {
            UNSCOPED_INFO("bin " << b << ": numeric " << numeric << " vs closed form " << closed);
            ++mismatches;
        }
        total += numeric;
    }
    CHECK(mismatches == 0);
    CHECK(std::fabs(total - 1) <= tolerance);
}

// Corner and edge inputs, where a warp divides by zero or leaves its domain if it ever does:
// 0, the centre and either side of it, and the largest value below 1 (what uniform() returns at
// most in a float build; larger than anything it returns in double).
std::vector<real> edge_inputs() {
    return {0,          real(1e-7),
            real(0.25), std::nextafter(real(0.5), real(0)),
            real(0.5),  std::nextafter(real(0.5), real(1)),
            real(0.75), std::nextafter(real(1), real(0))};
}

// Applies `check` to the warp of every pair of edge inputs and of 1e5 random pairs.
template <class Check>
void for_edge_and_random_samples(Check check) {
    for (real u : edge_inputs()) {
        for (real v : edge_inputs()) check(sample2{u, v});
    }
    rt::pcg32 rng(99, 3);
    for (int i = 0; i < 100000; ++i) check(next_sample2(rng));
}

}  // namespace

TEST_CASE("sampling: uniform disk samples lie in the unit disk", "[sampling][ch03][ch06]") {
    // |p|^2 = r^2 (cos^2 + sin^2) with |r| <= 1: cos and sin are within an ulp, and the squares
    // and the sum add three roundings, so |p|^2 exceeds 1 by at most about 4 eps.
    int outside = 0;
    for_edge_and_random_samples([&](sample2 s) {
        vec3 p = rt::sample_uniform_disk(s);
        if (!(p.z() == 0 && p.length_squared() <= 1 + 4 * eps)) {
            UNSCOPED_INFO("u = " << s.u << ", v = " << s.v << " gives " << p);
            ++outside;
        }
    });
    CHECK(outside == 0);
    // The concentric map sends the centre of the square to the centre of the disk.
    vec3 centre = rt::sample_uniform_disk({real(0.5), real(0.5)});
    CHECK(centre.length() == 0);
}

TEST_CASE("sampling: uniform disk matches its pdf (chi-square)", "[sampling][ch03][ch06]") {
    auto result = chi_square(
        disk_bins{}, [](rt::pcg32& rng) { return rt::sample_uniform_disk(next_sample2(rng)); },
        1000000, 1);
    INFO(result.summary);
    CHECK(result.passed);
}

TEST_CASE("sampling: the disk test rejects r = u, the classic mistake", "[sampling][ch03][ch06]") {
    // Polar coordinates with r uniform crowd the centre (density 1 / (2 pi r)); 1e5 samples put
    // X^2 in the tens of thousands. This shows the test above can fail.
    auto naive = [](rt::pcg32& rng) {
        sample2 s = next_sample2(rng);
        real phi  = 2 * rt::pi * s.v;
        return vec3(s.u * std::cos(phi), s.u * std::sin(phi), 0);
    };
    auto result = chi_square(disk_bins{}, naive, 100000, 2);
    INFO(result.summary);
    CHECK_FALSE(result.passed);
}

TEST_CASE("sampling: uniform disk pdf integrates to one over the bins", "[sampling][ch03][ch06]") {
    CHECK(rt::uniform_disk_pdf() > 0);
    check_pdf_matches_bins(disk_bins{});
}

TEST_CASE("sampling: uniform sphere samples are unit vectors", "[sampling][ch03]") {
    // z = 1 - 2u carries one rounding, 1 - z^2 an absolute error of about eps, and sqrt, cos, sin
    // and the length a few ulps more: | |d| - 1 | stays below 4 eps (9e-16 in double, far inside
    // the 1e-12 a renderer needs).
    int off = 0;
    for_edge_and_random_samples([&](sample2 s) {
        vec3 d = rt::sample_uniform_sphere(s);
        if (!(std::fabs(d.length() - 1) <= 4 * eps)) {
            UNSCOPED_INFO("u = " << s.u << ", v = " << s.v << " gives " << d
                                 << ", |d| - 1 = " << d.length() - 1);
            ++off;
        }
    });
    CHECK(off == 0);
}

TEST_CASE("sampling: uniform sphere matches its pdf (chi-square)", "[sampling][ch03]") {
    auto result = chi_square(
        sphere_bins{}, [](rt::pcg32& rng) { return rt::sample_uniform_sphere(next_sample2(rng)); },
        1000000, 3);
    INFO(result.summary);
    CHECK(result.passed);
}

TEST_CASE("sampling: uniform sphere pdf integrates to one over the bins", "[sampling][ch03]") {
    check_pdf_matches_bins(sphere_bins{});
}

TEST_CASE("sampling: cosine hemisphere samples are unit vectors with z >= 0", "[sampling][ch03]") {
    // The disk point has |p|^2 <= 1 + 4 eps and z = sqrt(max(0, 1 - |p|^2)), so |d|^2 = 1 up to
    // the disk's error plus two roundings: | |d| - 1 | <= 4 eps.
    int off = 0;
    for_edge_and_random_samples([&](sample2 s) {
        vec3 d = rt::sample_cosine_hemisphere(s);
        if (!(d.z() >= 0 && std::fabs(d.length() - 1) <= 4 * eps)) {
            UNSCOPED_INFO("u = " << s.u << ", v = " << s.v << " gives " << d);
            ++off;
        }
    });
    CHECK(off == 0);
}

TEST_CASE("sampling: cosine hemisphere matches its pdf (chi-square)", "[sampling][ch03]") {
    auto result = chi_square(
        hemisphere_bins{},
        [](rt::pcg32& rng) { return rt::sample_cosine_hemisphere(next_sample2(rng)); }, 1000000, 4);
    INFO(result.summary);
    CHECK(result.passed);
}

TEST_CASE("sampling: the cosine test rejects uniform hemisphere directions", "[sampling][ch03]") {
    // Uniform directions (z = u) put 10% of the samples in the lowest z slab, where cos/pi
    // expects 1%: with 1e5 samples X^2 runs to the thousands.
    auto uniform_hemisphere = [](rt::pcg32& rng) {
        vec3 d = rt::sample_uniform_sphere(next_sample2(rng));
        return vec3(d.x(), d.y(), std::fabs(d.z()));
    };
    auto result = chi_square(hemisphere_bins{}, uniform_hemisphere, 100000, 5);
    INFO(result.summary);
    CHECK_FALSE(result.passed);
}

TEST_CASE("sampling: cosine hemisphere pdf integrates to one and is zero below",
          "[sampling][ch03]") {
    check_pdf_matches_bins(hemisphere_bins{});
    CHECK(rt::cosine_hemisphere_pdf(0) == 0);
    CHECK(rt::cosine_hemisphere_pdf(real(-0.5)) == 0);
    CHECK(rt::cosine_hemisphere_pdf(-1) == 0);
    CHECK(std::fabs(double(rt::cosine_hemisphere_pdf(1)) - 1 / pi) <= 2 * double(eps) / pi);
}

TEST_CASE("sampling: uniform ball samples lie in the unit ball", "[sampling][ch03][ch04]") {
    // cbrt(w) <= 1 scales a unit vector (within 4 eps), plus one rounding per component.
    int outside = 0;
    for_edge_and_random_samples([&](sample2 s) {
        for (real w : {real(0), s.u, std::nextafter(real(1), real(0))}) {
            vec3 p = rt::sample_uniform_ball(s, w);
            if (!(p.length() <= 1 + 6 * eps)) {
                UNSCOPED_INFO("u = " << s.u << ", v = " << s.v << ", w = " << w << " gives " << p);
                ++outside;
            }
        }
    });
    CHECK(outside == 0);
}

TEST_CASE("sampling: uniform ball matches its pdf (chi-square)", "[sampling][ch03][ch04]") {
    auto result = chi_square(
        ball_bins{},
        [](rt::pcg32& rng) {
            sample2 s = next_sample2(rng);
            return rt::sample_uniform_ball(s, rng.uniform());
        },
        1000000, 6);
    INFO(result.summary);
    CHECK(result.passed);
}

TEST_CASE("sampling: uniform ball pdf integrates to one over the bins", "[sampling][ch03][ch04]") {
    check_pdf_matches_bins(ball_bins{});
}
