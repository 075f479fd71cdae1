// The warps of rt/samplers/sampling.h that chapter 03 brings, each held to its pdf
// (ch03/sampling_checks.h): the uniform disk (which chapter 06's lens also samples), the uniform
// sphere, and the cosine-weighted hemisphere built on the disk. Chapter 03.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "ch03/sampling_checks.h"
#include "rt/core/rng.h"
#include "rt/samplers/sampling.h"

using namespace rt_test::sampling_checks;

namespace {

// Every pdf here is symmetric about z, so each binning splits the azimuth into nphi equal parts
// and its integral is a factor dphi.

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
