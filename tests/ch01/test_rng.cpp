// pcg32 and the independent sampler (rt/core/rng.h, rt/samplers/independent_sampler.h):
// reproducible streams, jump-ahead, and a stream per pixel sample that does not depend on what was
// drawn before. Chapter 01.
#include <catch2/catch.hpp>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "rt/core/rng.h"
#include "rt/samplers/independent_sampler.h"
#include "statistics.h"

using rt::pcg32;
using rt::real;

namespace {

constexpr std::uint64_t multiplier = 0x5851f42d4c957f2dULL;  // PCG32's LCG multiplier

// The inverse of an odd number modulo 2^64 by Newton's iteration x' = x (2 - a x): each step
// doubles the correct low bits, and x = a is already right to 3 bits, so 5 steps give 96 > 64.
constexpr std::uint64_t inverse_mod_2_64(std::uint64_t a) {
    std::uint64_t x = a;
    for (int i = 0; i < 5; ++i) x *= 2 - a * x;
    return x;
}

// A generator whose next next_u32() reads `state` (the LCG state before the step): set_sequence
// steps twice, state = (inc + seed) * multiplier + inc, so solve that for the seed.
pcg32 generator_at_state(std::uint64_t state, std::uint64_t sequence) {
    const std::uint64_t inc  = (sequence << 1u) | 1u;
    const std::uint64_t seed = (state - inc) * inverse_mod_2_64(multiplier) - inc;
    return pcg32(sequence, seed);
}

bool same_outputs(pcg32 a, pcg32 b, int count) {
    for (int i = 0; i < count; ++i) {
        if (a.next_u32() != b.next_u32()) return false;
    }
    return true;
}

}  // namespace

TEST_CASE("rng: pcg32 reproduces the reference generator", "[rng][ch01]") {
    // O'Neill's pcg32-demo, pcg32_srandom_r(&rng, 42, 54): initstate 42, sequence 54.
    pcg32 rng(54, 42);
    for (std::uint32_t expected :
         {0xa15c02b7u, 0x7b47f409u, 0xba1d3330u, 0x83d2f293u, 0xbfa4784bu, 0xcbed606eu}) {
        CHECK(rng.next_u32() == expected);
    }
    // The same (sequence, seed) gives the same stream, however often it is built.
    CHECK(same_outputs(pcg32(3, 99), pcg32(3, 99), 1000));
    CHECK(same_outputs(pcg32(), pcg32(), 1000));
}

TEST_CASE("rng: advance(n) equals n calls of next_u32", "[rng][ch01]") {
    for (std::uint64_t n :
         {0ull, 1ull, 2ull, 3ull, 7ull, 64ull, 1000ull, 65536ull, 3 * 65536ull + 5, 1ull << 22}) {
        CAPTURE(n);
        pcg32 stepped(17, 5), jumped(17, 5);
        for (std::uint64_t i = 0; i < n; ++i) stepped.next_u32();
        jumped.advance(n);
        CHECK(same_outputs(stepped, jumped, 8));
    }
}

TEST_CASE("rng: advance composes and the period is 2^64", "[rng][ch01]") {
    // Jumps too long to step through are checked by algebra: a jump of a then b is one of a + b,
    // and 2^64 steps (the LCG's full period) come back to the start.
    const std::uint64_t a = (1ull << 40) + 123, b = (1ull << 50) + 7;
    pcg32 two_jumps(9, 1), one_jump(9, 1);
    two_jumps.advance(a);
    two_jumps.advance(b);
    one_jump.advance(a + b);
    CHECK(same_outputs(two_jumps, one_jump, 8));

    pcg32 around(9, 1);
    around.advance(~0ull);  // 2^64 - 1 steps ...
    around.next_u32();      // ... and one more
    CHECK(same_outputs(around, pcg32(9, 1), 8));

    pcg32 halves(9, 1);
    halves.advance(1ull << 63);
    CHECK_FALSE(same_outputs(halves, pcg32(9, 1), 8));
    halves.advance(1ull << 63);
    CHECK(same_outputs(halves, pcg32(9, 1), 8));
}

TEST_CASE("rng: a stride's jump raised to a power is the jump of the product", "[rng][ch01]") {
    // The sampler starts pixel sample s at s * 65536 steps by raising the 65536-step jump to the
    // power s: the same state as jumping s * 65536 steps at once, for every stream, and as
    // stepping where that is short enough to step.
    rt::pcg32 picks(23, 4);
    for (int i = 0; i < 200; ++i) {
        const std::uint64_t stride = picks.next_u32() % 100000 + 1;
        const std::uint64_t times  = i < 100 ? std::uint64_t(i) : picks.next_u32();
        const std::uint64_t stream = (std::uint64_t(picks.next_u32()) << 32u) | picks.next_u32();
        CAPTURE(stride, times, stream);
        pcg32 powered(stream, 7), direct(stream, 7);
        powered.apply(pcg32::repeated(pcg32::jump_of(stride), times));
        direct.advance(stride * times);
        CHECK(same_outputs(powered, direct, 4));
    }
    pcg32 stepped(5, 6), powered(5, 6);
    for (int i = 0; i < 3 * 65536; ++i) stepped.next_u32();
    powered.apply(pcg32::repeated(rt::independent_sampler::sample_stride, 3));
    CHECK(same_outputs(stepped, powered, 8));
}

TEST_CASE("rng: jump_of is Brown's jump-ahead, the pixel samples' positions unchanged",
          "[rng][ch01]") {
    // The definition every image so far was rendered with: advance() as Brown's loop over the
    // bits of delta, with the stream's increment inside. The jump must give its state bit for
    // bit, or every golden image would change.
    auto brown = [](std::uint64_t state, std::uint64_t inc, std::uint64_t delta) {
        std::uint64_t acc_mult = 1, acc_plus = 0;
        std::uint64_t cur_mult = 0x5851f42d4c957f2dULL, cur_plus = inc;
        while (delta > 0) {
            if (delta & 1u) {
                acc_mult *= cur_mult;
                acc_plus = acc_plus * cur_mult + cur_plus;
            }
            cur_plus = (cur_mult + 1) * cur_plus;
            cur_mult *= cur_mult;
            delta >>= 1u;
        }
        return acc_mult * state + acc_plus;
    };
    rt::pcg32 picks(29, 8);
    for (int i = 0; i < 1000; ++i) {
        const std::uint64_t state = (std::uint64_t(picks.next_u32()) << 32u) | picks.next_u32();
        const std::uint64_t inc = (std::uint64_t(picks.next_u32()) << 32u) | picks.next_u32() | 1u;
        const std::uint64_t delta =
            i < 500 ? std::uint64_t(i) * 65536
                    : (std::uint64_t(picks.next_u32()) << 32u) | picks.next_u32();
        const pcg32::jump j = pcg32::jump_of(delta);
        CAPTURE(state, inc, delta);
        CHECK(j.mult * state + j.plus * inc == brown(state, inc, delta));
        const pcg32::jump s =
            pcg32::repeated(rt::independent_sampler::sample_stride, std::uint64_t(i));
        CHECK(s.mult * state + s.plus * inc == brown(state, inc, std::uint64_t(i) * 65536));
    }
}

TEST_CASE("rng: different sequences and seeds give different streams", "[rng][ch01]") {
    // Two unrelated streams agree at one position with probability 2^-32: over 1000 positions
    // a single coincidence is already unlikely (2.3e-7), so allow at most one.
    auto coincidences = [](pcg32 x, pcg32 y) {
        int same = 0;
        for (int i = 0; i < 1000; ++i) same += x.next_u32() == y.next_u32();
        return same;
    };
    CHECK(coincidences(pcg32(1, 42), pcg32(2, 42)) <= 1);
    CHECK(coincidences(pcg32(1, 42), pcg32(1, 43)) <= 1);
    CHECK(coincidences(pcg32(0, 0), pcg32(1, 0)) <= 1);
    // Not tested, because it is false: sequences that differ only in their top bits give
    // near-identical streams (s and s + 2^62 agree on every other output; s and s + 2^63 are
    // the same stream, as the increment is 2s + 1 mod 2^64). That is why the sampler passes
    // (pixel, seed) through a hash before choosing the sequence.
}

TEST_CASE("rng: uniform() stays at or above 0 and below 1, even for the largest output",
          "[rng][ch01]") {
    // Build the state whose output is 0xffffffff: the output is bits 27..58 of s ^ (s >> 18),
    // rotated by s >> 59, so with bits 41..58 set and the rest clear every output bit is 1.
    const std::uint64_t all_ones_state = 0x07fffe0000000000ULL;
    pcg32 top                          = generator_at_state(all_ones_state, 5);
    pcg32 copy                         = top;
    REQUIRE(copy.next_u32() == 0xffffffffu);
    // (2^32 - 1) 2^-32 rounds to exactly 1 in float; the guard must keep it below.
    const real largest = top.uniform();
    CHECK(largest < 1);
    // ... but no further than the largest float below 1 (the guard of a float build).
    CHECK(largest >= real(1) - real(0x1p-24));

    pcg32 bottom = generator_at_state(0, 5);
    CHECK(bottom.uniform() == 0);  // state 0 outputs 0, which maps to exactly 0

    pcg32 rng(11, 13);
    real smallest = 1, biggest = 0;
    for (int i = 0; i < 1000000; ++i) {
        const real u = rng.uniform();
        if (u < smallest) smallest = u;
        if (u > biggest) biggest = u;
    }
    CHECK(smallest >= 0);
    CHECK(biggest < 1);
    // A million draws leave gaps of about 1e-6 at the ends; 1e-4 cannot be missed by chance
    // (probability e^-100) but catches a scale that stops short, e.g. 2^-33 instead of 2^-32.
    CHECK(smallest < real(1e-4));
    CHECK(biggest > real(1 - 1e-4));
}

TEST_CASE("rng: uniform() passes a chi-square test over 100 bins", "[rng][ch01]") {
    constexpr int bins = 100, samples = 1000000;
    std::vector<double> observed(bins, 0), expected(bins, double(samples) / bins);
    pcg32 rng(2024, 1);
    for (int i = 0; i < samples; ++i) observed[std::size_t(rng.uniform() * bins)] += 1;
    auto result = rt_test::chi_square_test(observed, expected, 0.01);
    INFO(result.summary);
    CHECK(result.passed);
}

namespace {

std::vector<real> draw(rt::sampler& s, int px, int py, int sample_index, int count) {
    s.start_pixel_sample(px, py, sample_index);
    std::vector<real> values;
    for (int i = 0; i < count; ++i) values.push_back(s.next_1d());
    return values;
}

}  // namespace

TEST_CASE("sampler: the same pixel sample and seed give the same numbers", "[sampler][ch01]") {
    rt::independent_sampler a(7), b(7);
    CHECK(draw(a, 3, 4, 5, 16) == draw(b, 3, 4, 5, 16));
    // next_2d is next_1d twice, u first.
    a.start_pixel_sample(3, 4, 5);
    const rt::sample2 pair          = a.next_2d();
    const std::vector<real> singles = draw(b, 3, 4, 5, 2);
    CHECK(pair.u == singles[0]);
    CHECK(pair.v == singles[1]);
}

TEST_CASE("sampler: a pixel sample's stream does not depend on what was drawn before",
          "[sampler][ch01]") {
    // This is what makes the image independent of the thread schedule and of cropping.
    rt::independent_sampler fresh(42);
    const std::vector<real> reference = draw(fresh, 10, 20, 3, 32);

    rt::independent_sampler used(42);
    draw(used, 11, 20, 3, 100);
    draw(used, 10, 20, 2, 7);
    draw(used, 10, 20, 4, 1);
    CHECK(draw(used, 10, 20, 3, 32) == reference);
    // Restarting mid-stream rewinds to the same start.
    used.start_pixel_sample(10, 20, 3);
    used.next_1d();
    CHECK(draw(used, 10, 20, 3, 32) == reference);
}

TEST_CASE("sampler: sample k + 1 starts where sample k's 65536 dimensions end", "[sampler][ch01]") {
    rt::independent_sampler s(5);
    const std::vector<real> first =
        draw(s, 1, 2, 0, int(rt::independent_sampler::dimensions_per_sample) + 8);
    const std::vector<real> next = draw(s, 1, 2, 1, 8);
    CHECK(std::vector<real>(first.end() - 8, first.end()) == next);
}

TEST_CASE("sampler: different pixels, samples and seeds give different numbers",
          "[sampler][ch01]") {
    // The first two numbers of 8192 streams: two unrelated pairs coincide with probability 2^-64
    // (2^-48 with float's 24-bit uniforms), and there are 2^25 pairs of streams, so a repeat has
    // probability below 2^-23 unless two of them are the same stream by mistake.
    std::set<std::pair<real, real>> seen;
    int streams = 0;
    for (std::uint64_t seed : {0ull, 1ull}) {
        rt::independent_sampler s(seed);
        for (int py = 0; py < 32; ++py) {
            for (int px = 0; px < 32; ++px) {
                for (int k = 0; k < 4; ++k) {
                    const std::vector<real> v = draw(s, px, py, k, 2);
                    seen.insert({v[0], v[1]});
                    ++streams;
                }
            }
        }
    }
    CHECK(int(seen.size()) == streams);
    // Swapping the coordinates is a different pixel.
    rt::independent_sampler s(0);
    CHECK(draw(s, 3, 5, 0, 4) != draw(s, 5, 3, 0, 4));
}

TEST_CASE("sampler: first numbers are uniform across pixels and across seeds", "[sampler][ch01]") {
    // Neighbouring pixels and consecutive seeds must not give correlated starts, or an image
    // would show the pixel grid in its noise. 65536 first draws into 64 bins: 1024 expected each.
    constexpr int bins = 64, streams = 256 * 256;
    const std::vector<double> expected(bins, double(streams) / bins);

    std::vector<double> by_pixel(bins, 0);
    rt::independent_sampler s(0);
    for (int py = 0; py < 256; ++py) {
        for (int px = 0; px < 256; ++px) {
            s.start_pixel_sample(px, py, 0);
            by_pixel[std::size_t(s.next_1d() * bins)] += 1;
        }
    }
    auto pixels = rt_test::chi_square_test(by_pixel, expected, 0.01);
    INFO("across pixels: " << pixels.summary);
    CHECK(pixels.passed);

    std::vector<double> by_seed(bins, 0);
    for (int seed = 0; seed < streams; ++seed) {
        rt::independent_sampler per_seed((std::uint64_t(seed)));
        per_seed.start_pixel_sample(0, 0, 0);
        by_seed[std::size_t(per_seed.next_1d() * bins)] += 1;
    }
    auto seeds = rt_test::chi_square_test(by_seed, expected, 0.01);
    INFO("across seeds: " << seeds.summary);
    CHECK(seeds.passed);
}
