// sampler.h — the numbers a sample draws: every value a pure function of (seed, pixel, sample
// index, bounce, dimension) and of the render's sampler setup. The default is a scrambled Sobol
// sequence with the pixels in Morton order (blue-noise error across pixels); the independent
// numbers of rng.h are the comparison (--sampler independent). docs/integrator.md, "Random
// numbers", allocates the dimensions.
#ifndef VKPT_SAMPLER_H
#define VKPT_SAMPLER_H

#include "host_device.h"
#include "rng.h"
#include "sobol.h"

#ifdef __cplusplus
#include <array>

namespace vkpt::gpu {
#endif

#define SAMPLER_INDEPENDENT 0u
#define SAMPLER_SOBOL 1u

// The setup word (FrameParams.samplerSetup on the device): bits 0-7 the kind; for Sobol, bits 8-15
// the block exponent b (a pixel owns 2^b consecutive indices of the sequence per block) and
// bits 16-23 the Morton exponent L (pixel coordinates keep L bits each). 2L + b <= 32, so an
// index fits one 32-bit word.
#define SAMPLER_MAX_MORTON_BITS 16u
#define SAMPLER_MAX_BLOCK_BITS 31u

VKPT_FN uint samplerKind(uint setup) {
    return setup & 0xffu;
}

VKPT_FN uint samplerBlockBits(uint setup) {
    return (setup >> 8u) & 0xffu;
}

VKPT_FN uint samplerMortonBits(uint setup) {
    return (setup >> 16u) & 0xffu;
}

// ceil(log2(n)) for n >= 1.
VKPT_FN uint ceilLog2(uint n) {
    return n <= 1u ? 0u : uint(findMSB(n - 1u)) + 1u;
}

// L covers the image's larger side; b = ceil(log2 ceil(spp / 2)) lets one pixel's samples of one
// half (sobolPairBits) of one run be a single block, so that at a power-of-two spp each 2×2 quad
// of pixels holds, in each half, an aligned run of 4·2^b points — a (0, b+2, 2)-net — which is what
// makes the error blue noise (Ahmed and Wonka, "Screen-space blue-noise diffusion of Monte Carlo
// sampling error via hierarchical ordering of pixels", SIGGRAPH Asia 2020). b shrinks when the
// image leaves fewer bits; sample indices past the block use further blocks, each scrambled afresh
// (sobolPairBits).
VKPT_FN uint makeSamplerSetup(uint kind, uint width, uint height, uint samplesPerPixel) {
    if (kind != SAMPLER_SOBOL) return kind;
    uint mortonBits = min(ceilLog2(max(width, height)), SAMPLER_MAX_MORTON_BITS);
    // Each half of the samples (sobolPairBits) is a sequence of its own, of ceil(spp / 2).
    uint perHalf = (samplesPerPixel >> 1u) + (samplesPerPixel & 1u);
    uint blockBits =
        min(min(ceilLog2(max(perHalf, 1u)), SAMPLER_MAX_BLOCK_BITS), SOBOL_BITS - 2u * mortonBits);
    return kind | (blockBits << 8u) | (mortonBits << 16u);
}

// The low 16 bits of v moved to the even bit positions.
VKPT_FN uint spreadBits(uint v) {
    v &= 0x0000ffffu;
    v = (v | (v << 8u)) & 0x00ff00ffu;
    v = (v | (v << 4u)) & 0x0f0f0f0fu;
    v = (v | (v << 2u)) & 0x33333333u;
    v = (v | (v << 1u)) & 0x55555555u;
    return v;
}

// Bits of x and y (each below 2^16) interleaved, x in the even bits.
VKPT_FN uint mortonCode(uint x, uint y) {
    return spreadBits(x) | (spreadBits(y) << 1u);
}

// Entry `digit` of the permutation of {0, 1, 2, 3} that `choice` selects: a Fisher–Yates
// shuffle of four 2-bit fields, drawing its swaps from choice mod 4, mod 3 and mod 2, so the 24
// permutations are (nearly) equally likely over uniform choices. Those three draws depend on
// choice mod 24 alone (4 · 3 · 2 = 24), so the shuffle is tabulated: the 24 permutations in the
// order the draws make them, a byte each (field i: where digit i goes), four to a word. The
// table replaces the three divisions and swaps of every Morton level of every draw (the tests
// hold the sequence's values, which the table does not change).
VKPT_FN uint permuteBase4Digit(uint digit, uint choice) {
    uint r = choice % 24u;
    uint word = r < 12u ? (r < 4u ? 0xc98d4b39u : (r < 8u ? 0xd293721eu : 0xe1b1632du))
                        : (r < 16u ? 0xc6874e36u : (r < 20u ? 0xd89c781bu : 0xe4b46c27u));
    uint fields = (word >> (8u * (r & 3u))) & 0xffu;
    return (fields >> (2u * digit)) & 3u;
}

// Ahmed and Wonka's hierarchical ordering: each base-4 digit of the Morton code, from the top,
// goes through a random permutation chosen by the node above it (the digits before it, with a
// leading 1 so that nodes of different depths differ). The four children of every node still get
// the four quarters of its run of indices, in an order that varies from node to node (and from
// dimension to dimension, through `key`), so neighbouring pixels share no fixed pattern.
VKPT_FN uint shuffleMortonDigits(uint code, uint bits, uint key) {
    uint shuffled = 0u;
    for (uint level = 0u; level < bits; ++level) {
        uint shift = 2u * (bits - 1u - level);
        uint node = ((code >> shift) >> 2u) | (1u << (2u * level));
        uint digit = (code >> shift) & 3u;
        shuffled |= permuteBase4Digit(digit, pcgHash(node ^ key)) << shift;
    }
    return shuffled;
}

#ifdef __cplusplus
// The CPU's shuffleMortonDigits, remembered. The shuffled code depends on the pixel, the pair,
// the block and the half alone, so every sample of a pixel in one block and half asks for the
// same ones; vkpt-ref draws a pixel's samples in turn on one thread, and remembering them (a
// hash per Morton level, every draw) makes its Cornell box render 12 % faster, bit for bit. One
// table per thread, direct-mapped by a mix of code and key; a hit returns the very value the walk
// gives. (The device keeps computing it: there the whole sampler costs vkpt about 4 %,
// docs/benchmarks.md.)
inline uint shuffleMortonDigitsRemembered(uint code, uint bits, uint key) {
    struct Entry {
        uint code;
        uint bits;
        uint key;
        uint shuffled;
    };
    constexpr uint kSlotBits = 10u;
    // bits = 0xffffffff marks an empty slot: no image has that many Morton bits.
    thread_local std::array<Entry, 1u << kSlotBits> table = [] {
        std::array<Entry, 1u << kSlotBits> empty{};
        for (Entry& entry : empty)
            entry.bits = 0xffffffffu;
        return empty;
    }();
    Entry& entry = table[((code * 0x9e3779b1u) ^ key) >> (32u - kSlotBits)];
    if (entry.code != code || entry.bits != bits || entry.key != key)
        entry = Entry{code, bits, key, shuffleMortonDigits(code, bits, key)};
    return entry.shuffled;
}
#define VKPT_SHUFFLED_MORTON(code, bits, key) shuffleMortonDigitsRemembered(code, bits, key)
#else
#define VKPT_SHUFFLED_MORTON(code, bits, key) shuffleMortonDigits(code, bits, key)
#endif

// The half of a pixel's samples that a sample belongs to: the parity of its index, which a
// sample keeps in every task split, merge and resume (docs/integrator.md, "Two halves").
VKPT_FN uint sampleHalf(uint sampleIndex) {
    return sampleIndex & 1u;
}

// One scrambled 2-D Sobol point for a sample of a pixel. The two halves of the samples (even and
// odd indices, sampleHalf) draw from two independently scrambled and shuffled sequences, each
// indexed by sampleIndex / 2: the halves' means are then independent estimates, so that their
// difference measures the error of the whole mean without assuming independent samples (within
// one sequence, a sample and its successor are anti-correlated partners, which would make the
// difference overstate the error). `pair` names the pair (sobolPairKey); within a half, the
// sequence index is (shuffled Morton code of the pixel) · 2^b + (sample index within its
// block, nested-uniform shuffled by all bits above it). A pixel's first 2^k samples of a half's
// block (k <= b) are then an aligned run of indices: one point in each elementary interval of area
// 2^-k. Indices past the block (sampleIndex / 2 >= 2^b, as in --resume to a larger --spp, the
// extremes' 2^20 spp, or large images that leave b small) belong to block (sampleIndex / 2) >> b,
// whose scrambles and shuffles are keyed afresh: each block is an independent randomised net,
// every point stays uniform, so estimates stay unbiased, and the per-pixel error keeps
// falling as the average of independent blocks.
VKPT_FN uvec2 sobolPairBits(uint setup, uint width, uint seed, uint pixel, uint sampleIndex,
                            uint pair) {
    uint mortonBits = samplerMortonBits(setup);
    uint blockBits = samplerBlockBits(setup); // at most 31: the shifts below are defined
    uint withinMask = (1u << blockBits) - 1u;
    uint whichHalf = sampleHalf(sampleIndex);
    sampleIndex >>= 1u;
    uint key =
        pcgHash(seed ^ pcgHash(pair ^ pcgHash(((sampleIndex >> blockBits) << 1u) | whichHalf)));
    uint coordinateMask = (1u << mortonBits) - 1u;
    uint code = mortonCode((pixel % width) & coordinateMask, (pixel / width) & coordinateMask);
    uint original = (code << blockBits) | (sampleIndex & withinMask);
    uint index = (VKPT_SHUFFLED_MORTON(code, mortonBits, key) << blockBits) |
                 (nestedUniformScramble(original, pcgHash(key + 1u)) & withinMask);
    // sobolPoint(index) scrambled, without reversing each coordinate twice.
    return uvec2(owenScrambleReversed(index, pcgHash(key + 2u)),
                 owenScrambleReversed(sobolSecondDimensionReversed(index), pcgHash(key + 3u)));
}

// The pairs of one (bounce, dimension): which 0 gives .xy, which 1 gives .zw.
VKPT_FN uint sobolPairKey(uint bounce, uint dimension, uint which) {
    return (bounce << 9u) | ((dimension & RNG_MAX_DIMENSION) << 1u) | which;
}

// Four numbers in [0, 1) (multiples of 2^-24, as rng.h's) for one (bounce, dimension) of a
// sample. Sobol: .xy and .zw are two 2-D pairs, each stratified over the pixel's samples;
// independent: rng.h's randomFloats.
VKPT_FN vec4 sampleFloats(uint setup, uint width, uint seed, uint pixel, uint sampleIndex,
                          uint bounce, uint dimension) {
    if (samplerKind(setup) != SAMPLER_SOBOL)
        return randomFloats(seed, pixel, sampleIndex, bounce, dimension);
    uvec2 a =
        sobolPairBits(setup, width, seed, pixel, sampleIndex, sobolPairKey(bounce, dimension, 0u));
    uvec2 b =
        sobolPairBits(setup, width, seed, pixel, sampleIndex, sobolPairKey(bounce, dimension, 1u));
    return vec4(bitsToUnitFloat(a.x), bitsToUnitFloat(a.y), bitsToUnitFloat(b.x),
                bitsToUnitFloat(b.y));
}

// A light sample's numbers in the order lights.h reads them (u.x the emitter, u.yz the point or
// direction): the point gets the stratified pair .xy, the emitter choice .z.
VKPT_FN vec4 lightSampleOrder(vec4 u) {
    return vec4(u.z, u.x, u.y, u.w);
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_SAMPLER_H
