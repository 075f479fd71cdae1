// The warp of rt/samplers/sampling.h that chapter 04 brings for fuzzy metal, held to its pdf
// (ch03/sampling_checks.h): the uniform ball. Chapter 04.
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

}  // namespace

TEST_CASE("sampling: uniform ball samples lie in the unit ball", "[sampling][ch04]") {
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

TEST_CASE("sampling: uniform ball matches its pdf (chi-square)", "[sampling][ch04]") {
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

TEST_CASE("sampling: uniform ball pdf integrates to one over the bins", "[sampling][ch04]") {
    check_pdf_matches_bins(ball_bins{});
}
