#include "rt/samplers/sobol_sampler.h"

#include <limits>

#include "rt/core/exercise.h"
#include "rt/core/rng.h"

namespace rt {

namespace {

// Bits in reverse order: the bytes by one instruction, then the bits within each byte.
constexpr std::uint32_t reverse_bits(std::uint32_t x) {
    x = __builtin_bswap32(x);
    x = ((x >> 4u) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4u);
    x = ((x >> 2u) & 0x33333333u) | ((x & 0x33333333u) << 2u);
    return ((x >> 1u) & 0x55555555u) | ((x & 0x55555555u) << 1u);
}

// Sobol's second dimension by its definition (primitive polynomial x + 1, every m_k = 1):
// direction number v_k = v_(k-1) ^ (v_(k-1) >> 1) from v_0 = 2^31; the point XORs those of the
// index's set bits. Up to 32 steps with a branch each: used only to build the tables below.
constexpr std::uint32_t dimension_1_by_definition(std::uint32_t i) {
    std::uint32_t result = 0, v = 1u << 31u;
    for (; i != 0; i >>= 1u, v ^= v >> 1u)
        if (i & 1u) result ^= v;
    return result;
}

// The point is linear in the index's bits (XOR of direction numbers), so it is the XOR of the
// points of the index's four bytes: four lookups in tables of 256 instead of 32 steps, since the
// shuffled index uses all 32 bits. `reversed` stores each point's bits reversed, which is what
// the Owen scramble needs (below).
struct dimension_1_tables {
    std::uint32_t by_byte[4][256];

    constexpr explicit dimension_1_tables(bool reversed) : by_byte{} {
        for (unsigned byte = 0; byte < 4; ++byte) {
            for (std::uint32_t value = 0; value < 256; ++value) {
                std::uint32_t point  = dimension_1_by_definition(value << (8u * byte));
                by_byte[byte][value] = reversed ? reverse_bits(point) : point;
            }
        }
    }

    std::uint32_t operator()(std::uint32_t i) const {
        // [exercise dimension_1_tables::operator begin]
        return by_byte[0][i & 0xffu] ^ by_byte[1][(i >> 8u) & 0xffu] ^
               by_byte[2][(i >> 16u) & 0xffu] ^ by_byte[3][i >> 24u];
        // [exercise dimension_1_tables::operator end]
    }
};
constexpr dimension_1_tables dimension_1{false}, dimension_1_reversed{true};

// Laine and Karras's permutation: each bit of the result depends only on the bits of x below it
// (and the key). On reversed bits that is an Owen scramble (see owen_scramble).
constexpr std::uint32_t laine_karras_permutation(std::uint32_t x, std::uint32_t key) {
    x += key;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// The Owen scramble of the number whose bits, reversed, are `reversed` (owen_scramble below,
// for callers that already hold the reversed bits).
constexpr std::uint32_t owen_scramble_of_reversed(std::uint32_t reversed, std::uint32_t key) {
    return reverse_bits(laine_karras_permutation(reversed, key));
}

// 32 scrambled bits as a number in [0, 1), kept below 1 as pcg32::uniform() does.
real to_unit(std::uint32_t bits) {
    constexpr real one_minus_epsilon = real(1) - std::numeric_limits<real>::epsilon() / 2;
    real u                           = real(bits) * real(0x1p-32);
    return u < one_minus_epsilon ? u : one_minus_epsilon;
}

}  // namespace

sobol_sampler::sobol_sampler(std::uint64_t render_seed)
    : seed_key(mix_bits(render_seed ^ 0x50b01u)) {}

void sobol_sampler::start_pixel_sample(int px, int py, int sample_index) {
    auto pixel     = (std::uint64_t(std::uint32_t(px)) << 32u) | std::uint32_t(py);
    pixel_key      = hash_values(pixel, seed_key, 0x5eed);
    index_reversed = reverse_bits(std::uint32_t(sample_index));
    draw           = 0;
}

std::uint32_t sobol_sampler::sobol_dimension_0(std::uint32_t i) {
    return reverse_bits(i);
}

std::uint32_t sobol_sampler::sobol_dimension_1(std::uint32_t i) {
    return dimension_1(i);
}

std::uint32_t sobol_sampler::owen_scramble(std::uint32_t x, std::uint32_t key) {
    // Burley's hash-based Owen scramble: reversed, the Laine-Karras permutation makes each bit
    // depend only on the bits below it (the more significant ones of x), which is what an Owen
    // scramble is: every digit flipped by a random function of the digits before it.
    return owen_scramble_of_reversed(reverse_bits(x), key);
}

std::uint64_t sobol_sampler::draw_key() {
    return hash_values(pixel_key, std::uint64_t(draw++), 0xd1ce);
}

// The draws compute owen_scramble(sobol_dimension_d(owen_scramble(index, k0)), k_d) with fewer
// bit reversals, the same bits: the shuffle's first reversal of the index is done once per
// sample (start_pixel_sample); dimension 0 is itself a reversal, which cancels the scramble's
// first one; and dimension 1 comes from tables already reversed. tests/ch16 checks the identity
// against the plain composition.
std::uint32_t sobol_sampler::shuffled_index(std::uint32_t key) const {
    return owen_scramble_of_reversed(index_reversed, key);
}

real sobol_sampler::next_1d() {
    // [exercise sobol_sampler::next_1d begin]
    std::uint64_t key      = draw_key();
    std::uint32_t shuffled = shuffled_index(std::uint32_t(key));
    return to_unit(owen_scramble_of_reversed(shuffled, std::uint32_t(key >> 32u)));
    // [exercise sobol_sampler::next_1d end]
}

sample2 sobol_sampler::next_2d() {
    // [exercise sobol_sampler::next_2d begin]
    std::uint64_t key      = draw_key();
    std::uint64_t key2     = mix_bits(key);
    std::uint32_t shuffled = shuffled_index(std::uint32_t(key));
    return {
        to_unit(owen_scramble_of_reversed(shuffled, std::uint32_t(key >> 32u))),
        to_unit(owen_scramble_of_reversed(dimension_1_reversed(shuffled), std::uint32_t(key2)))};
    // [exercise sobol_sampler::next_2d end]
}

}  // namespace rt
