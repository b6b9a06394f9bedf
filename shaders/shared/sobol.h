// sobol.h — the two-dimensional Sobol sequence and hash-based Owen scrambling, the building
// blocks of the default sampler (sampler.h). Integer-only, so the CPU and the GPU agree bit for
// bit.
#ifndef VKPT_SOBOL_H
#define VKPT_SOBOL_H

#include "host_device.h"

#ifdef __cplusplus
namespace vkpt::gpu {
using glm::bitfieldReverse; // GLSL built-ins that host_device.h does not already name
using glm::findMSB;
#endif

// The sequence's direction numbers are Joe and Kuo's ("Constructing Sobol sequences with better
// two-dimensional projections", SIAM J. Sci. Comput. 30(5), 2008; the table new-joe-kuo-6.21201).
// Dimension 0 is van der Corput's (direction k is 2^(31-k): the bit-reversed index). Dimension 1
// is the table's first row: degree s = 1 (primitive polynomial x + 1), a = 0, m_1 = 1, so
// Bratley and Fox's recurrence m_k = 2·m_(k-1) XOR m_(k-1) gives v_k = v_(k-1) XOR (v_(k-1) >> 1)
// from v_0 = 2^31 (the rows of Pascal's triangle mod 2). These two dimensions form a
// (0,2)-sequence: every aligned run of 2^m points is a (0,m,2)-net, one point in each of the
// 2^m elementary intervals of every shape. Every further dimension of the sampler reuses this
// pair with its own scrambles and shuffles (sampler.h), so no larger table is needed.
#define SOBOL_BITS 32u

// Dimension 1's value of `index` without the loop over its bits: direction j has the
// (bit-reversed) bit i set exactly when C(j, i) is odd, that is (Lucas's theorem) when the bits
// of i are a subset of the bits of j. So the reversed value's bit i is the parity of the index's
// bits j ⊇ i, a superset sum over the five bits of a position, one shift per bit
// (tests/unit/sobol_test.cpp checks it against the directions of the recurrence above).
VKPT_FN uint sobolSecondDimensionReversed(uint index) {
    index ^= (index >> 1u) & 0x55555555u;
    index ^= (index >> 2u) & 0x33333333u;
    index ^= (index >> 4u) & 0x0f0f0f0fu;
    index ^= (index >> 8u) & 0x00ff00ffu;
    index ^= (index >> 16u) & 0x0000ffffu;
    return index;
}

// Point `index` of the sequence as two 32-bit binary fractions.
VKPT_FN uvec2 sobolPoint(uint index) {
    return uvec2(bitfieldReverse(index), bitfieldReverse(sobolSecondDimensionReversed(index)));
}

// One hash for keys and seeds: pcg (Jarzynski and Olano, "Hash Functions for GPU Rendering",
// JCGT 9(3), 2020), a permutation of 32-bit words.
VKPT_FN uint pcgHash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// Laine and Karras's bit-permuting hash with Burley's constants ("Practical Hash-based Owen
// Scrambling", JCGT 9(4), 2020, section 3): adding a seed and XOR-ing with products by even
// constants changes bit k only as a function of bits 0..k, so the map is a bijection in which
// each bit is flipped by a function of the bits below it.
VKPT_FN uint laineKarrasPermutation(uint x, uint seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// Owen scrambling of a binary fraction given bit-reversed (Burley, section 3): each digit of the
// fraction is flipped as a function of the digits above it. Returns the scrambled fraction.
VKPT_FN uint owenScrambleReversed(uint reversed, uint seed) {
    return bitfieldReverse(laineKarrasPermutation(reversed, seed));
}

// Owen scrambling of a binary fraction (Burley, section 3): between two bit reversals, each
// digit of the fraction is flipped as a function of the digits above it, which permutes the
// points inside every elementary interval and so keeps every (0,m,2)-net a net. Applied to an
// index instead of a fraction it is Burley's nested uniform shuffle (section 4): bit k flipped by
// the bits above k, which reorders every aligned run of 2^m indices within itself.
VKPT_FN uint nestedUniformScramble(uint x, uint seed) {
    return bitfieldReverse(laineKarrasPermutation(bitfieldReverse(x), seed));
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_SOBOL_H
