/* sobol.h — Owen-scrambled Sobol points, shared by the kernels and the host: a
 * low-discrepancy drop-in for rng_uniform4 (rng.h), with the same arguments.
 *
 * Owns: the 32-bit generator matrices of the first four Sobol dimensions
 * (dimension 0 is van der Corput; 1 to 3 follow the Joe and Kuo direction
 * numbers), the unscrambled point sobol_sample(), and the randomised point
 * sobol_uniform4(), built as in Burley, "Practical Hash-based Owen Scrambling"
 * (JCGT 2020).
 *
 * Promises, for every (seed, pixel, bounce, group):
 * - four numbers in [0, 1), multiples of 2^-24, a pure function of the keys;
 *   the host and a device compute the same bits (integer arithmetic, then one
 *   exact conversion);
 * - every aligned block of 2^m consecutive sample indices (in particular the
 *   first 2^m) gives a (0, m, 2)-net in coordinates (x, y), and each of z and w
 *   alone puts exactly one point in each of 2^m equal intervals. Coordinates z
 *   and w together are stratified as Sobol dimensions 2 and 3 are (t > 0);
 * - different keys give independently scrambled point sets (up to the hash).
 * Sample indices run over all of 0 .. 2^32 - 1.
 *
 * How: the keys hash to one 32-bit key. The sample index is Owen-scrambled
 * with it, which permutes the indices within each aligned block of 2^m, so a
 * prefix of 2^m samples takes an aligned block of 2^m Sobol points, a net in
 * dimensions 0 and 1 (Sobol's first two dimensions are a (0, 2)-sequence).
 * Each coordinate of that point is then Owen-scrambled with its own seed.
 * Owen scrambling flips each bit of a number by a random function of the
 * more significant bits, which maps elementary intervals onto elementary
 * intervals of the same shape and so keeps the net property exactly; the
 * "random function" is a hash, so the scramble costs a few multiplies. The
 * point's four coordinates are computed side by side in uint4 lanes, and on
 * a CPU device its matrix product sixteen columns at a time. */
#ifndef WF_SOBOL_H
#define WF_SOBOL_H

#include "wavefront/compat.h"

/* Tables live in the constant address space on the device; on the host one
 * definition is shared by every translation unit. */
#ifdef __OPENCL_C_VERSION__
#define WF_SOBOL_TABLE __constant uint32_t
#else
#define WF_SOBOL_TABLE inline constexpr uint32_t
#endif

#define WF_SOBOL_DIMENSIONS 4

WF_DEVICE_BEGIN

/* The generator matrices' columns, a row a bit j of the index: the column of
 * each dimension d for that bit, as a binary fraction (bit 31 is 1/2); that
 * is m_{j+1} of Joe and Kuo's recurrence shifted left by 31 - j. Dimension 0
 * is the identity read as a fraction (bit reversal). Polynomials (s, a) and
 * initial m: dimension 1: (1, 0), 1; dimension 2: (2, 1), 1 3; dimension 3:
 * (3, 1), 1 3 1. */
#define WF_SOBOL_COLUMNS(X) \
    X(0x80000000u, 0x80000000u, 0x80000000u, 0x80000000u) X(0x40000000u, 0xc0000000u, 0xc0000000u, 0xc0000000u) \
    X(0x20000000u, 0xa0000000u, 0x60000000u, 0x20000000u) X(0x10000000u, 0xf0000000u, 0x90000000u, 0x50000000u) \
    X(0x08000000u, 0x88000000u, 0xe8000000u, 0xf8000000u) X(0x04000000u, 0xcc000000u, 0x5c000000u, 0x74000000u) \
    X(0x02000000u, 0xaa000000u, 0x8e000000u, 0xa2000000u) X(0x01000000u, 0xff000000u, 0xc5000000u, 0x93000000u) \
    X(0x00800000u, 0x80800000u, 0x68800000u, 0xd8800000u) X(0x00400000u, 0xc0c00000u, 0x9cc00000u, 0x25400000u) \
    X(0x00200000u, 0xa0a00000u, 0xee600000u, 0x59e00000u) X(0x00100000u, 0xf0f00000u, 0x55900000u, 0xe6d00000u) \
    X(0x00080000u, 0x88880000u, 0x80680000u, 0x78080000u) X(0x00040000u, 0xcccc0000u, 0xc09c0000u, 0xb40c0000u) \
    X(0x00020000u, 0xaaaa0000u, 0x60ee0000u, 0x82020000u) X(0x00010000u, 0xffff0000u, 0x90550000u, 0xc3050000u) \
    X(0x00008000u, 0x80008000u, 0xe8808000u, 0x208f8000u) X(0x00004000u, 0xc000c000u, 0x5cc0c000u, 0x51474000u) \
    X(0x00002000u, 0xa000a000u, 0x8e606000u, 0xfbea2000u) X(0x00001000u, 0xf000f000u, 0xc5909000u, 0x75d93000u) \
    X(0x00000800u, 0x88008800u, 0x6868e800u, 0xa0858800u) X(0x00000400u, 0xcc00cc00u, 0x9c9c5c00u, 0x914e5400u) \
    X(0x00000200u, 0xaa00aa00u, 0xeeee8e00u, 0xdbe79e00u) X(0x00000100u, 0xff00ff00u, 0x5555c500u, 0x25db6d00u) \
    X(0x00000080u, 0x80808080u, 0x8000e880u, 0x58800080u) X(0x00000040u, 0xc0c0c0c0u, 0xc0005cc0u, 0xe54000c0u) \
    X(0x00000020u, 0xa0a0a0a0u, 0x60008e60u, 0x79e00020u) X(0x00000010u, 0xf0f0f0f0u, 0x9000c590u, 0xb6d00050u) \
    X(0x00000008u, 0x88888888u, 0xe8006868u, 0x800800f8u) X(0x00000004u, 0xccccccccu, 0x5c009c9cu, 0xc00c0074u) \
    X(0x00000002u, 0xaaaaaaaau, 0x8e00eeeeu, 0x200200a2u) X(0x00000001u, 0xffffffffu, 0xc5005555u, 0x50050093u)

/* Bit reversal's step, swapping the bit groups `mask` selects with their
 * neighbours `shift` above; and a 32-bit constant's bits in reverse order
 * by its steps, as a constant expression (sobol_reverse_bits takes them at
 * run time). */
#define WF_SOBOL_SWAP(x, shift, mask) ((((x) >> (shift)) & (mask)) | (((x) & (mask)) << (shift)))
#define WF_SOBOL_REVERSED(x)                                                                                 \
    WF_SOBOL_SWAP(WF_SOBOL_SWAP(WF_SOBOL_SWAP(WF_SOBOL_SWAP(((x) >> 16) | ((x) << 16), 8u, 0x00ff00ffu), 4u, \
                                              0x0f0f0f0fu),                                                  \
                                2u, 0x33333333u),                                                            \
                  1u, 0x55555555u)
#define WF_SOBOL_ROW(d0, d1, d2, d3) d0, d1, d2, d3,
#define WF_SOBOL_ROW_REVERSED(d0, d1, d2, d3) \
    WF_SOBOL_REVERSED(d0), WF_SOBOL_REVERSED(d1), WF_SOBOL_REVERSED(d2), WF_SOBOL_REVERSED(d3),

/* sobol_matrices[4 j + d]: dimension d's column for bit j. A bit's four
 * columns sit side by side, so that one load takes them for the four
 * coordinates. */
WF_SOBOL_TABLE sobol_matrices[WF_SOBOL_DIMENSIONS * 32] = {WF_SOBOL_COLUMNS(WF_SOBOL_ROW)};

/* The same columns with their bits reversed: what sobol_uniform4 multiplies,
 * since it scrambles bit-reversed numbers (below). */
WF_SOBOL_TABLE sobol_matrices_reversed[WF_SOBOL_DIMENSIONS * 32] = {WF_SOBOL_COLUMNS(WF_SOBOL_ROW_REVERSED)};

/* Coordinate `dimension` (< WF_SOBOL_DIMENSIONS) of Sobol point `index`, as 32
 * fraction bits: the XOR of the matrix columns of the index's set bits. The
 * mask instead of a branch keeps the loop free of divergence. */
WF_INLINE uint32_t sobol_bits(uint32_t index, uint32_t dimension) {
    uint32_t bits = 0u;
    for (uint32_t j = 0u; index != 0u; index >>= 1, ++j)
        bits ^= sobol_matrices[4u * j + dimension] & (0u - (index & 1u));
    return bits;
}

/* The four coordinates' reversed columns for bit j of the index. */
WF_INLINE uint4 sobol_columns_reversed(uint32_t j) {
#ifdef __OPENCL_C_VERSION__
    return vload4(j, sobol_matrices_reversed);
#else
    return make_uint4(sobol_matrices_reversed[4u * j], sobol_matrices_reversed[4u * j + 1u],
                      sobol_matrices_reversed[4u * j + 2u], sobol_matrices_reversed[4u * j + 3u]);
#endif
}

/* The four coordinates of Sobol point reverse(r), a coordinate a lane, each
 * with its bits reversed: the XOR of the reversed columns of the index's set
 * bits, bit j of the index being bit 31 - j of r. */
#if defined(__OPENCL_C_VERSION__) && defined(__AVX__)
/* On an x86 CPU device, sixteen columns a step (four bits of the index, four
 * coordinates each) in one 512-bit vector: eight steps of independent
 * arithmetic where a bit at a time was a loop of 32 dependent ones. */
WF_INLINE uint4 sobol_point_bits_reversed(uint32_t r) {
    const uint16 bit_in_step =
        (uint16)(31u, 31u, 31u, 31u, 30u, 30u, 30u, 30u, 29u, 29u, 29u, 29u, 28u, 28u, 28u, 28u);
    uint16 bits = (uint16)(0u);
    for (uint32_t step = 0u; step < 8u; ++step) {
        const uint16 set = ((uint16)(r << (4u * step)) >> bit_in_step) & (uint16)(1u);
        bits ^= vload16(step, sobol_matrices_reversed) & ((uint16)(0u) - set);
    }
    const uint8 pairs = bits.lo ^ bits.hi;
    return pairs.lo ^ pairs.hi;
}
#else
WF_INLINE uint4 sobol_point_bits_reversed(uint32_t r) {
    uint4 bits = make_uint4(0u, 0u, 0u, 0u);
    for (uint32_t j = 0u; r != 0u; r <<= 1, ++j) {
        const uint32_t mask = 0u - (r >> 31);
        bits ^= sobol_columns_reversed(j) & make_uint4(mask, mask, mask, mask);
    }
    return bits;
}
#endif

/* The top 24 bits scaled into [0, 1), as rng.h does: exact, never 1. */
WF_INLINE float sobol_bits_to_float(uint32_t bits) { return (float)(bits >> 8) * (1.0f / 16777216.0f); }

/* The unscrambled Sobol sequence, for tests and reference. */
WF_INLINE float sobol_sample(uint32_t index, uint32_t dimension) {
    return sobol_bits_to_float(sobol_bits(index, dimension));
}

/* The bit twiddling below is written once for a number, for four in lanes
 * (uint4, a Sobol point's four coordinates) and, in sobol_lanes.inc, for a
 * number a path in the group schedule's lanes: the same operations on each
 * lane, so the same bits. NAME(f) names f for type T; WF_SOBOL_SCALAR(x) is
 * x in every lane. */
#define WF_SOBOL_FUNCTIONS(T, NAME, WF_SOBOL_SCALAR)                                                               \
    /* OpenCL C 1.2 has no bit-reversal built-in: swap halves, then quarters, ... */                                 \
    WF_INLINE T NAME(sobol_reverse_bits)(T x) {                                                                    \
        x = (x >> 16u) | (x << 16u);                                                                                 \
        x = WF_SOBOL_SWAP(x, 8u, WF_SOBOL_SCALAR(0x00ff00ffu));                                                      \
        x = WF_SOBOL_SWAP(x, 4u, WF_SOBOL_SCALAR(0x0f0f0f0fu));                                                      \
        x = WF_SOBOL_SWAP(x, 2u, WF_SOBOL_SCALAR(0x33333333u));                                                      \
        return WF_SOBOL_SWAP(x, 1u, WF_SOBOL_SCALAR(0x55555555u));                                                   \
    }                                                                                                                \
    /* A full-avalanche 32-bit integer hash (xorshift-multiply rounds; constants                                     \
     * from Wellons' hash-prospector search), for combining keys into seeds. */                                      \
    WF_INLINE T NAME(sobol_hash)(T x) {                                                                            \
        x ^= x >> 16u;                                                                                               \
        x *= WF_SOBOL_SCALAR(0x7feb352du);                                                                           \
        x ^= x >> 15u;                                                                                               \
        x *= WF_SOBOL_SCALAR(0x846ca68bu);                                                                           \
        x ^= x >> 16u;                                                                                               \
        return x;                                                                                                    \
    }                                                                                                                \
    /* Owen scrambling of bit-reversed x (Laine and Karras's observation): every                                     \
     * step below is a bijection in which bit k of the result is bit k of the input                                  \
     * XOR a function of the seed and the bits below k: adding, multiplying by an                                    \
     * odd number, and x ^= x * even all carry only upwards. Steps that mix the                                      \
     * input before and after the seed enters give every bit a dependence on all                                     \
     * the lower bits; measured pairwise flip correlations are at the noise level                                    \
     * of 20000 trials, unlike the original four-multiply form. */                                                   \
    WF_INLINE T NAME(sobol_owen_scramble_reversed)(T x, T seed) {                                                  \
        x ^= x * WF_SOBOL_SCALAR(0x9e3779b8u);                                                                       \
        x += seed;                                                                                                   \
        x *= (seed >> 16u) | WF_SOBOL_SCALAR(1u);                                                                    \
        x ^= x * WF_SOBOL_SCALAR(0x6c50b47cu);                                                                       \
        x ^= x * WF_SOBOL_SCALAR(0xb82f1e52u);                                                                       \
        return x;                                                                                                    \
    }

#define WF_SOBOL_ONE(x) (x)
#define WF_SOBOL_FOUR(x) make_uint4((x), (x), (x), (x))
#define WF_SOBOL_NAME_ONE(f) f
#define WF_SOBOL_NAME_FOUR(f) f##4
WF_SOBOL_FUNCTIONS(uint32_t, WF_SOBOL_NAME_ONE, WF_SOBOL_ONE)
WF_SOBOL_FUNCTIONS(uint4, WF_SOBOL_NAME_FOUR, WF_SOBOL_FOUR)
#undef WF_SOBOL_ONE
#undef WF_SOBOL_FOUR
#undef WF_SOBOL_NAME_ONE
#undef WF_SOBOL_NAME_FOUR

/* Owen scrambling of x: each bit flipped by a hash of the seed and the bits
 * above it. */
WF_INLINE uint32_t sobol_owen_scramble(uint32_t x, uint32_t seed) {
    return sobol_reverse_bits(sobol_owen_scramble_reversed(sobol_reverse_bits(x), seed));
}

/* The keys' hash, which scrambles the sample index, and what coordinate d's
 * seed hashes with it; HASH is sobol_hash at the caller's width. */
#define WF_SOBOL_KEY(HASH, seed, pixel, bounce, group) HASH(HASH(HASH(sobol_hash(seed) ^ (pixel)) ^ (bounce)) ^ (group))
#define WF_SOBOL_SALT(d) (0x9e3779b9u * ((d) + 1u))

/* Four numbers in [0, 1) for (pixel, sample, bounce, group): an Owen-scrambled
 * Sobol point, different for every (seed, pixel, bounce, group). The sample
 * index is scrambled with the keys' hash; each coordinate of its point then
 * with a seed of its own drawn from that hash, all four in lanes. Both
 * scrambles work on reversed bits; the scrambled index stays reversed, and
 * the point is taken from it by the reversed columns, which leaves its
 * coordinates reversed for their scramble: the same bits as
 * sobol_owen_scramble(sobol_bits(sobol_owen_scramble(sample, key), d), seed_d),
 * two reversals fewer. */
WF_INLINE float4 sobol_uniform4(uint32_t seed, uint32_t pixel, uint32_t sample, uint32_t bounce, uint32_t group) {
    const uint32_t key = WF_SOBOL_KEY(sobol_hash, seed, pixel, bounce, group);
    const uint32_t reversed_index = sobol_owen_scramble_reversed(sobol_reverse_bits(sample), key);
    const uint4 seeds = sobol_hash4(make_uint4(key, key, key, key) ^
                                    make_uint4(WF_SOBOL_SALT(0u), WF_SOBOL_SALT(1u), WF_SOBOL_SALT(2u), WF_SOBOL_SALT(3u)));
    const uint4 bits =
        sobol_reverse_bits4(sobol_owen_scramble_reversed4(sobol_point_bits_reversed(reversed_index), seeds));
    return make_float4(sobol_bits_to_float(bits.x), sobol_bits_to_float(bits.y), sobol_bits_to_float(bits.z),
                       sobol_bits_to_float(bits.w));
}

WF_DEVICE_END

#endif /* WF_SOBOL_H */
