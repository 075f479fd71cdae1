#include "sobol_sampler.h"

#include <limits>

namespace rt {

namespace {

std::uint32_t reverse_bits(std::uint32_t x) {
    x = ((x >> 1u) & 0x55555555u) | ((x & 0x55555555u) << 1u);
    x = ((x >> 2u) & 0x33333333u) | ((x & 0x33333333u) << 2u);
    x = ((x >> 4u) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4u);
    x = ((x >> 8u) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8u);
    return (x >> 16u) | (x << 16u);
}

// 32 scrambled bits as a number in [0, 1), kept below 1 as pcg32::uniform() does.
real to_unit(std::uint32_t bits) {
    constexpr real one_minus_epsilon = real(1) - std::numeric_limits<real>::epsilon() / 2;
    real u                           = real(bits) * real(0x1p-32);
    return u < one_minus_epsilon ? u : one_minus_epsilon;
}

}  // namespace

sobol_sampler::sobol_sampler(std::uint64_t render_seed)
    : sampler(render_seed), seed_key(mix_bits(render_seed ^ 0x50b01u)) {}

void sobol_sampler::start_pixel_sample(int px, int py, int sample_index) {
    auto pixel = (std::uint64_t(std::uint32_t(px)) << 32u) | std::uint32_t(py);
    pixel_key  = hash_values(pixel, seed_key, 0x5eed);
    index      = std::uint32_t(sample_index);
    draw       = 0;
}

std::uint32_t sobol_sampler::sobol_dimension_0(std::uint32_t i) {
    return reverse_bits(i);
}

std::uint32_t sobol_sampler::sobol_dimension_1(std::uint32_t i) {
    // Sobol's second dimension (primitive polynomial x + 1, every m_k = 1): direction number
    // v_k = v_(k-1) ^ (v_(k-1) >> 1) from v_0 = 2^31; the point XORs those of i's set bits.
    std::uint32_t result = 0, v = 1u << 31u;
    for (; i != 0; i >>= 1u, v ^= v >> 1u)
        if (i & 1u) result ^= v;
    return result;
}

std::uint32_t sobol_sampler::owen_scramble(std::uint32_t x, std::uint32_t key) {
    // Burley's hash-based Owen scramble: reversed, a Laine-Karras style permutation makes each bit
    // depend only on the bits below it (the more significant ones of x), which is what an Owen
    // scramble is: every digit flipped by a random function of the digits before it.
    x = reverse_bits(x);
    x += key;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return reverse_bits(x);
}

std::uint64_t sobol_sampler::draw_key() {
    return hash_values(pixel_key, std::uint64_t(draw++), 0xd1ce);
}

real sobol_sampler::next_1d() {
    std::uint64_t key      = draw_key();
    std::uint32_t shuffled = owen_scramble(index, std::uint32_t(key));
    return to_unit(owen_scramble(sobol_dimension_0(shuffled), std::uint32_t(key >> 32u)));
}

sample2 sobol_sampler::next_2d() {
    std::uint64_t key      = draw_key();
    std::uint64_t key2     = mix_bits(key);
    std::uint32_t shuffled = owen_scramble(index, std::uint32_t(key));
    return {to_unit(owen_scramble(sobol_dimension_0(shuffled), std::uint32_t(key >> 32u))),
            to_unit(owen_scramble(sobol_dimension_1(shuffled), std::uint32_t(key2)))};
}

}  // namespace rt
