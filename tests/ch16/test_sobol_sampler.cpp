// Tests for sobol_sampler.h (chapter 16): Owen-scrambled, per-pixel shuffled Sobol' points keep
// the (0, 2)-sequence property (one point per elementary cell), are uniform, and depend only on
// (pixel, sample index, draw, seed); the layout of sampler.h puts segment k's draws in the same
// place whatever the segments before it drew, and no two places of it give the same numbers.
#include <catch2/catch.hpp>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "rt/samplers/independent_sampler.h"
#include "rt/samplers/sobol_sampler.h"
#include "statistics.h"

namespace {

using rt::real;

// The first `count` points of draw `draw` of pixel (px, py): every sample index, its draw-th 2D
// number (after the camera's and earlier draws, which are skipped by drawing them).
std::vector<rt::sample2> points_of(rt::sampler& s, int px, int py, int count, int draw) {
    std::vector<rt::sample2> points;
    for (int k = 0; k < count; ++k) {
        s.start_pixel_sample(px, py, k);
        for (int d = 0; d < draw; ++d) s.next_2d();
        points.push_back(s.next_2d());
    }
    return points;
}

// Whether every cell of the 2^a x 2^b grid holds exactly one of the 2^(a+b) points.
bool one_point_per_cell(const std::vector<rt::sample2>& points, int a, int b) {
    std::set<std::uint64_t> cells;
    for (const auto& p : points) {
        auto x = std::uint64_t(double(p.u) * double(1u << a));
        auto y = std::uint64_t(double(p.v) * double(1u << b));
        if (!cells.insert((x << 32u) | y).second) return false;
    }
    return cells.size() == points.size();
}

}  // namespace

TEST_CASE("sobol: dimension 0 is the van der Corput sequence, dimension 1 Sobol's second",
          "[ch16]") {
    // Van der Corput: 0, 1/2, 1/4, 3/4, 1/8, ...; Sobol's second dimension: 0, 1/2, 3/4, 1/4, ...
    const std::uint32_t half = 1u << 31u;
    CHECK(rt::sobol_sampler::sobol_dimension_0(0) == 0);
    CHECK(rt::sobol_sampler::sobol_dimension_0(1) == half);
    CHECK(rt::sobol_sampler::sobol_dimension_0(2) == half / 2);
    CHECK(rt::sobol_sampler::sobol_dimension_0(3) == half + half / 2);
    CHECK(rt::sobol_sampler::sobol_dimension_1(0) == 0);
    CHECK(rt::sobol_sampler::sobol_dimension_1(1) == half);
    CHECK(rt::sobol_sampler::sobol_dimension_1(2) == half + half / 2);
    CHECK(rt::sobol_sampler::sobol_dimension_1(3) == half / 2);
}

TEST_CASE("sobol: dimension 1's byte tables give the definition's point for every index",
          "[ch16]") {
    // The definition: direction numbers v_k = v_(k-1) ^ (v_(k-1) >> 1) from 2^31, XORed over the
    // index's set bits. The sampler looks up four tables instead; the shuffled indices use all
    // 32 bits, so check every single bit, every byte value and many random full indices.
    auto by_definition = [](std::uint32_t i) {
        std::uint32_t result = 0, v = 1u << 31u;
        for (; i != 0; i >>= 1u, v ^= v >> 1u)
            if (i & 1u) result ^= v;
        return result;
    };
    for (unsigned bit = 0; bit < 32; ++bit)
        CHECK(rt::sobol_sampler::sobol_dimension_1(1u << bit) == by_definition(1u << bit));
    for (std::uint32_t byte = 0; byte < 256; ++byte)
        for (unsigned shift : {0u, 8u, 16u, 24u})
            REQUIRE(rt::sobol_sampler::sobol_dimension_1(byte << shift) ==
                    by_definition(byte << shift));
    rt::pcg32 rng;
    for (int k = 0; k < 100000; ++k) {
        std::uint32_t i = rng.next_u32();
        REQUIRE(rt::sobol_sampler::sobol_dimension_1(i) == by_definition(i));
    }
}

TEST_CASE("sobol: the unscrambled first 2^m points are a (0, m, 2)-net", "[ch16]") {
    for (int m = 1; m <= 10; ++m) {
        std::vector<rt::sample2> points;
        for (std::uint32_t i = 0; i < (1u << m); ++i)
            points.push_back({real(rt::sobol_sampler::sobol_dimension_0(i) * 0x1p-32),
                              real(rt::sobol_sampler::sobol_dimension_1(i) * 0x1p-32)});
        for (int a = 0; a <= m; ++a) {
            INFO("m = " << m << ", cells 2^" << a << " x 2^" << m - a);
            CHECK(one_point_per_cell(points, a, m - a));
        }
    }
}

TEST_CASE("sobol: scrambled and shuffled, every pixel's first 2^m samples are still a net",
          "[ch16]") {
    // The shuffle maps aligned blocks of indices onto aligned blocks, and the scramble keeps
    // elementary cells: so for every pixel, every draw and every cell shape, one point per cell.
    rt::sobol_sampler s(7);
    for (int pixel = 0; pixel < 6; ++pixel) {
        for (int draw = 0; draw < 3; ++draw) {
            for (int m : {2, 4, 6, 8}) {
                auto points = points_of(s, 13 * pixel, 5 + pixel, 1 << m, draw);
                for (int a = 0; a <= m; ++a) {
                    INFO("pixel " << pixel << ", draw " << draw << ", cells 2^" << a << " x 2^"
                                  << m - a);
                    CHECK(one_point_per_cell(points, a, m - a));
                }
            }
        }
    }
}

TEST_CASE("sobol: independent samples are not a net, so the net test can fail", "[ch16]") {
    rt::independent_sampler s(7);
    auto points   = points_of(s, 3, 4, 1 << 6, 0);
    int good_grid = 0;
    for (int a = 0; a <= 6; ++a) good_grid += one_point_per_cell(points, a, 6 - a);
    CHECK(good_grid < 7);
}

TEST_CASE("sobol: each pixel's first sample is uniform over the square (chi-square)", "[ch16]") {
    // Across pixels the shuffle and scramble keys differ, so the points are independent uniform.
    rt::sobol_sampler s(3);
    const int n = 16, samples = 64 * n * n;
    std::vector<double> observed(n * n, 0), expected(n * n, double(samples) / (n * n));
    for (int i = 0; i < samples; ++i) {
        s.start_pixel_sample(i % 512, i / 512, 0);
        rt::sample2 p = s.next_2d();
        REQUIRE(p.u >= 0);
        REQUIRE(p.u < 1);
        REQUIRE(p.v >= 0);
        REQUIRE(p.v < 1);
        observed[std::size_t(int(p.u * n) * n + int(p.v * n))] += 1;
    }
    auto result = rt_test::chi_square_test(observed, expected, 0.01);
    INFO(result.summary);
    CHECK(result.passed);
}

TEST_CASE("sobol: 1D draws of one pixel are stratified, and uniform across pixels", "[ch16]") {
    rt::sobol_sampler s(11);
    // 256 samples of one pixel: exactly one in each of 256 equal intervals.
    std::set<int> strata;
    for (int k = 0; k < 256; ++k) {
        s.start_pixel_sample(9, 9, k);
        strata.insert(int(s.next_1d() * 256));
    }
    CHECK(strata.size() == 256);
}

TEST_CASE("sobol: a sample depends only on (pixel, index, draw, seed)", "[ch16]") {
    rt::sobol_sampler a(5), b(5), other_seed(6);
    // b visits other pixels and samples first: a crop or another thread's order.
    b.start_pixel_sample(100, 7, 3);
    b.next_2d();
    a.start_pixel_sample(2, 3, 17);
    b.start_pixel_sample(2, 3, 17);
    other_seed.start_pixel_sample(2, 3, 17);
    rt::sample2 pa = a.next_2d(), pb = b.next_2d(), po = other_seed.next_2d();
    CHECK(pa.u == pb.u);
    CHECK(pa.v == pb.v);
    CHECK((pa.u != po.u || pa.v != po.v));
    CHECK(a.next_1d() == b.next_1d());
}

TEST_CASE("sobol: segment k's draws do not depend on what earlier segments drew", "[ch16]") {
    // Glass draws 1 number, a diffuse wall 2, metal 3: the layout puts the next segment's draws
    // in the same place anyway.
    rt::sobol_sampler a(1), b(1);
    a.start_pixel_sample(4, 4, 9);
    b.start_pixel_sample(4, 4, 9);
    a.next_2d();  // the camera's jitter
    b.next_2d();
    a.start_segment(0);
    b.start_segment(0);
    a.next_1d();  // glass
    b.next_2d();  // metal
    b.next_1d();
    a.start_segment(1);
    b.start_segment(1);
    rt::sample2 pa = a.next_2d(), pb = b.next_2d();
    CHECK(pa.u == pb.u);
    CHECK(pa.v == pb.v);
}

TEST_CASE("sobol: no two draws of a path's layout give the same numbers", "[ch16]") {
    // Each place of the layout (sampler.h: the camera's draws, then draws_per_segment for each
    // segment) is keyed by its own index, so its numbers are independent of every other's. Two
    // places that shared a key would return the same point in every sample: the number that
    // picks a light would also aim the bounce after it, and no sample count removes that bias.
    // So over many pixel samples no two places may agree but by chance; for independent
    // numbers of 24 bits or more an equal pair is a one in 2^24 event, so agreeing in a tenth
    // of the samples is no accident.
    using rt::sampler;
    constexpr int segments = 4;
    constexpr int places   = sampler::camera_draws + segments * sampler::draws_per_segment;
    auto place_name        = [](int place) {
        if (place < sampler::camera_draws) return "camera draw " + std::to_string(place);
        const int k = place - sampler::camera_draws;
        return "segment " + std::to_string(k / sampler::draws_per_segment) + " draw " +
               std::to_string(k % sampler::draws_per_segment);
    };
    rt::sobol_sampler s(21);
    const int samples = 256;
    std::vector<int> equal(places * places, 0);
    for (int k = 0; k < samples; ++k) {
        s.start_pixel_sample(k % 16, k / 16, k % 7);
        std::vector<rt::sample2> drawn;
        for (int d = 0; d < sampler::camera_draws; ++d) drawn.push_back(s.next_2d());
        for (int segment = 0; segment < segments; ++segment) {
            s.start_segment(segment);
            for (int d = 0; d < sampler::draws_per_segment; ++d) drawn.push_back(s.next_2d());
        }
        REQUIRE(drawn.size() == std::size_t(places));
        for (int a = 0; a < places; ++a)
            for (int b = 0; b < a; ++b)
                equal[std::size_t(a * places + b)] +=
                    drawn[std::size_t(a)].u == drawn[std::size_t(b)].u &&
                    drawn[std::size_t(a)].v == drawn[std::size_t(b)].v;
    }
    std::string shared;
    int shared_pairs = 0;
    for (int a = 0; a < places; ++a) {
        for (int b = 0; b < a; ++b) {
            const int count = equal[std::size_t(a * places + b)];
            if (count * 10 <= samples) continue;
            if (++shared_pairs <= 3)
                shared += place_name(a) + " repeats " + place_name(b) + " in " +
                          std::to_string(count) + " of " + std::to_string(samples) + " samples; ";
        }
    }
    INFO(shared_pairs << " pairs of places share their numbers: " << shared);
    CHECK(shared_pairs == 0);
}

TEST_CASE("sobol: the independent sampler ignores the layout, so earlier images stay the same",
          "[ch16]") {
    rt::independent_sampler a(1), b(1);
    a.start_pixel_sample(4, 4, 9);
    b.start_pixel_sample(4, 4, 9);
    a.next_2d();
    b.next_2d();
    b.start_segment(3);
    CHECK(a.next_1d() == b.next_1d());
    CHECK(std::string(a.name()) == "independent");
    CHECK(std::string(rt::sobol_sampler(1).name()) == "sobol");
}
