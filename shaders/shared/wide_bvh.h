// wide_bvh.h — the stackless walk of the 8-wide compressed BVH (host_device.h, WideBvhNode),
// compiled by the kernels (lib/traverse.glsl) and by the CPU tests and benchmarks
// (host/bvh/wide_traverse.cpp), so that both run this very code.
//
// A visit fetches one node and tests its eight child boxes against (tMin, best t). The hit
// leaf children's primitives are tested right away, in visiting order; the hit internal
// children become the node's pending mask, bit p standing for slot p XOR octant, so that the
// lowest bit is the next child to visit. Descending pushes what is left of the mask onto a bit
// stack (8 bits a level, 32 levels in two uvec4 registers: no stack in memory); when a node's
// mask runs out, the walk climbs to its parent, whose node index the node records, and pops
// the parent's mask. Near-first order comes from the octant alone, so nothing is sorted and no
// distance is stored (Ylitie et al. 2017 keep (child base, mask) pairs on a stack in memory
// instead; the parent link and the bit stack are the trail of Áfra and Szirmay-Kalos,
// "Stackless Multi-BVH Traversal for CPU, MIC and GPU Ray Tracing", CGF 33(1), 2014).
//
// Two levels (bvhHasInstances): the top-level tree's leaf primitives are instances. Meeting one,
// the walk keeps where it stood in the top level (its node, masks and bit stack: registers, as
// before), moves the ray into the instance's mesh space (instance.h) and walks the mesh's tree
// from its root; at that root's end it takes the top level up again where it left it. The best
// crossing's t is the same in every space, so it bounds both levels.
//
// The includer supplies, before including this file:
//   uvec4 bvhNodeTexel(uint texel VKPT_BVH_PARAM)        texel of bvhNodes (5 per node)
//   Triangle bvhPrimitive(uint index VKPT_BVH_PARAM)     primitive in BVH order
//   Instance bvhInstance(uint index VKPT_BVH_PARAM)      instance, for two-level walks
//   bool bvhHasSpheres(VKPT_BVH_PARAM_ONLY), bool bvhHasAlphaMask(VKPT_BVH_PARAM_ONLY),
//   bool bvhHasInstances(VKPT_BVH_PARAM_ONLY)
// (the C++ side defines them below over a WideBvhView).
#ifndef VKPT_WIDE_BVH_H
#define VKPT_WIDE_BVH_H

#include "host_device.h"
#include "instance.h"
#include "intersect.h"
#include "sphere.h"

#ifdef __cplusplus
#include <cstring>

namespace vkpt::gpu {

// What a walk reads, on the CPU: the nodes and the primitives in BVH order, and for a two-level
// tree the instances.
struct WideBvhView {
    const WideBvhNode* nodes;
    const Triangle* primitives;
    bool spheres;   // some primitive may be a sphere
    bool alphaMask; // alpha-masked primitives need the includer's test (PendingCrossing)
    const Instance* instances = nullptr; // non-null: node 0 is the top level of a two-level tree
};

#define VKPT_BVH_PARAM , const WideBvhView& bvh
#define VKPT_BVH_PARAM_ONLY const WideBvhView& bvh
#define VKPT_BVH_ARG , bvh
#define VKPT_BVH_ARG_ONLY bvh

// The node array as the device sees it, 16-byte texels (memcpy: no aliasing of the structs).
VKPT_FN uvec4 bvhNodeTexel(uint texel VKPT_BVH_PARAM) {
    uvec4 value;
    std::memcpy(&value, reinterpret_cast<const unsigned char*>(bvh.nodes) + 16u * texel,
                sizeof value);
    return value;
}
VKPT_FN Triangle bvhPrimitive(uint index VKPT_BVH_PARAM) {
    return bvh.primitives[index];
}
VKPT_FN bool bvhHasSpheres(VKPT_BVH_PARAM_ONLY) {
    return bvh.spheres;
}
VKPT_FN bool bvhHasAlphaMask(VKPT_BVH_PARAM_ONLY) {
    return bvh.alphaMask;
}
VKPT_FN bool bvhHasInstances(VKPT_BVH_PARAM_ONLY) {
    return bvh.instances != nullptr;
}
VKPT_FN Instance bvhInstance(uint index VKPT_BVH_PARAM) {
    return bvh.instances[index];
}
#else
#define VKPT_BVH_PARAM
#define VKPT_BVH_PARAM_ONLY
#define VKPT_BVH_ARG
#define VKPT_BVH_ARG_ONLY
#endif

// ---------------------------------------------------------------------------------------------
// The node's words.

// The first texel, all a climb back to a node needs: childBase, parent, slotsAndExponents,
// primitiveBase.
#define WIDE_HEADER_CHILD_BASE(h) (h).x
#define WIDE_HEADER_PARENT(h) (h).y
#define WIDE_HEADER_PRIMITIVE_BASE(h) (h).w
VKPT_FN uint wideInternalSlots(uvec4 header) {
    return header.z & 0xffu;
}

// The grid spacing per axis: 2^e, built from the biased exponent bits.
VKPT_FN vec3 wideGridScale(uvec4 header) {
    return vec3(uintBitsToFloat(((header.z >> 8u) & 0xffu) << 23u),
                uintBitsToFloat(((header.z >> 16u) & 0xffu) << 23u),
                uintBitsToFloat((header.z >> 24u) << 23u));
}

// Byte `slot` of a pair of words holding one quantised bound of the eight children.
VKPT_FN float wideQuantisedByte(uint first, uint second, uint slot) {
    uint word = slot < 4u ? first : second;
    return float((word >> ((slot & 3u) * 8u)) & 0xffu);
}

// The primitive count of slot's leaf, 0 for an internal or empty slot.
VKPT_FN uint wideLeafCount(uint leafCounts, uint slot) {
    return (leafCounts >> (4u * slot)) & 15u;
}

// Where slot's primitives start after primitiveBase: the sum of the counts of lower slots
// (nibbles summed into bytes, then the bytes by one multiplication; at most 7·15 = 105).
VKPT_FN uint wideLeafOffset(uint leafCounts, uint slot) {
    uint below = slot == 0u ? 0u : leafCounts & ((1u << (4u * slot)) - 1u);
    uint bytes = (below & 0x0f0f0f0fu) + ((below >> 4u) & 0x0f0f0f0fu);
    return (bytes * 0x01010101u) >> 24u;
}

// The node index of slot's internal child.
VKPT_FN uint wideChildIndex(uvec4 header, uint slot) {
    uint lower = wideInternalSlots(header) & ((1u << slot) - 1u);
    return WIDE_HEADER_CHILD_BASE(header) + uint(bitCount(lower));
}

// Moves bit s of an 8-bit slot mask to bit s XOR octant: XOR by a bit of the octant swaps
// single bits, pairs or nibbles.
VKPT_FN uint orderSlotBits(uint mask, uint octant) {
    if ((octant & 1u) != 0u) mask = ((mask & 0x55u) << 1u) | ((mask >> 1u) & 0x55u);
    if ((octant & 2u) != 0u) mask = ((mask & 0x33u) << 2u) | ((mask >> 2u) & 0x33u);
    if ((octant & 4u) != 0u) mask = ((mask & 0x0fu) << 4u) | ((mask >> 4u) & 0x0fu);
    return mask;
}

// The ray's octant: bit k set when direction component k is negative (or −0).
VKPT_FN uint rayOctant(vec3 direction) {
    return (floatBitsToUint(direction.x) >> 31u) | ((floatBitsToUint(direction.y) >> 31u) << 1u) |
           ((floatBitsToUint(direction.z) >> 31u) << 2u);
}

// ---------------------------------------------------------------------------------------------
// The bit stack: a mask of 8 bits per level, the top level in the low byte of words.x.
struct WideBitStack {
    uvec4 words;    // levels 0–15 from the top
    uvec4 overflow; // levels 16–31
};

VKPT_FN void pushMask(VKPT_INOUT(WideBitStack) stack, uint mask) {
    uvec4 carryOverflow = uvec4(stack.words.w >> 24u, stack.overflow.x >> 24u,
                                stack.overflow.y >> 24u, stack.overflow.z >> 24u);
    uvec4 carryWords =
        uvec4(mask, stack.words.x >> 24u, stack.words.y >> 24u, stack.words.z >> 24u);
    stack.overflow = (stack.overflow << 8u) | carryOverflow;
    stack.words = (stack.words << 8u) | carryWords;
}

VKPT_FN uint popMask(VKPT_INOUT(WideBitStack) stack) {
    uint mask = stack.words.x & 0xffu;
    stack.words = (stack.words >> 8u) |
                  (uvec4(stack.words.y, stack.words.z, stack.words.w, stack.overflow.x) << 24u);
    stack.overflow = (stack.overflow >> 8u) |
                     (uvec4(stack.overflow.y, stack.overflow.z, stack.overflow.w, 0u) << 24u);
    return mask;
}

// ---------------------------------------------------------------------------------------------
// The walk.

// A crossing that needs the alpha test before the walk may take it; primitive NO_PRIMITIVE:
// none. The walk stands in its instance (WideWalk::instance).
struct PendingCrossing {
    TriangleHit hit;
    uint primitive;
};

// Where the top level of a two-level walk stood when it entered an instance: what climbing and
// the next leaf need (the node's header and leafCounts are fetched again on the way back).
struct TopLevelPlace {
    WideBitStack stack;
    uint depth;
    uint node;
    uint pending;
    uint leaves;
    uint next;
    uint end;
};

// The instance the walk stands in; NO_INSTANCE at the top level, and always in a build without
// two-level walks.
#if VKPT_INSTANCES
#define WALK_INSTANCE(walk) (walk).instance
#else
#define WALK_INSTANCE(walk) NO_INSTANCE
#endif

// depth of a finished walk: the node loop runs while depth <= WIDE_BVH_MAX_DEPTH, so a walk
// that a driver's loop limit ends early (continueWideWalk) keeps a real depth and reports
// itself.
#define WIDE_WALK_DONE 0xffffffffu

struct WideWalk {
    vec3 origin; // in the space of the tree being walked: the world's, or an instance's mesh's
    float tMin;
    vec3 direction;
    uint octant;
    vec3 invDirection;
    bool stopAtFirst;
    ShearedRay sheared; // the watertight test's shear, once per walk (and per instance)
    // The best crossing so far; its t bounds every test. primitive NO_PRIMITIVE: none yet.
    float t;
    float u;
    float v;
    uint primitive;
    uint hitInstance; // the instance of the best crossing; NO_INSTANCE in a single-level walk
#if VKPT_INSTANCES
    // Two-level walks: the world ray, the instance being walked (NO_INSTANCE at the top level)
    // and where the top level stood.
    vec3 worldOrigin;
    vec3 worldDirection;
    uint instance;
    TopLevelPlace top;
#endif
    // Where the walk stands.
    WideBitStack stack;
    uint depth;      // levels pushed; WIDE_WALK_DONE once finished
    uint node;       // the node whose children `pending` and `leaves` refer to
    uvec4 header;    // its first texel
    uint leafCounts; // its leafCounts word
    uint pending;    // its internal children still to visit (bit p: slot p ^ octant)
    uint leaves;     // its leaf children still to test after the current one (same order)
    uint next;       // the next primitive of the current leaf
    uint end;        // one past its last
    // Where the ray enters each child's box of `node`, slots 0–3 and 4–7, while the walk is at
    // the node it visited last (false once it climbs): children entered beyond a crossing
    // found since are passed over.
    vec4 entryLow;
    vec4 entryHigh;
    bool entriesCurrent;
    // Work done, for statistics.
    uint nodesVisited;
    uint primitiveTests;
};

// The slots (in visiting order) whose boxes the ray enters beyond the best crossing so far,
// with intersectBox's margin (a box entered at that very t may hold a crossing that ties).
VKPT_FN uint childrenBeyondBest(WideWalk walk) {
    if (walk.primitive == NO_PRIMITIVE || !walk.entriesCurrent) return 0u;
    float limit = walk.t * 1.0000004f;
    uvec4 low = uvec4(greaterThan(walk.entryLow, vec4(limit)));
    uvec4 high = uvec4(greaterThan(walk.entryHigh, vec4(limit)));
    uint slots = low.x | (low.y << 1u) | (low.z << 2u) | (low.w << 3u) | (high.x << 4u) |
                 (high.y << 5u) | (high.z << 6u) | (high.w << 7u);
    return orderSlotBits(slots, walk.octant);
}

// Moves to the next leaf of `leaves` that the ray enters before the best crossing, or to an
// empty range when none is left.
VKPT_FN void takeNextLeaf(VKPT_INOUT(WideWalk) walk) {
    walk.leaves &= ~childrenBeyondBest(walk);
    if (walk.leaves == 0u) {
        walk.next = walk.end;
        return;
    }
    uint slot = uint(findLSB(walk.leaves)) ^ walk.octant;
    walk.leaves &= walk.leaves - 1u;
    walk.next = WIDE_HEADER_PRIMITIVE_BASE(walk.header) + wideLeafOffset(walk.leafCounts, slot);
    walk.end = walk.next + wideLeafCount(walk.leafCounts, slot);
}

// A node's quantised bounds as the ray meets them: per axis the byte pair of the plane it
// enters by (near) and of the one it leaves by (far), picked once per node from the ray's
// octant. The slab test then needs no min and max per axis and slot, which on lavapipe cost a
// NaN test each besides (docs/bvh.md): for a direction component of either sign, the plane
// picked as near gives exactly the smaller of intersectBox's two distances.
struct NearFarBounds {
    uvec2 nearX;
    uvec2 nearY;
    uvec2 nearZ;
    uvec2 farX;
    uvec2 farY;
    uvec2 farZ;
};

VKPT_FN NearFarBounds nearFarBounds(uvec4 q0, uvec4 q1, uvec4 q2, uint octant) {
    uvec2 loX = uvec2(q0.x, q0.y), loY = uvec2(q0.z, q0.w), loZ = uvec2(q1.x, q1.y);
    uvec2 hiX = uvec2(q1.z, q1.w), hiY = uvec2(q2.x, q2.y), hiZ = uvec2(q2.z, q2.w);
    bool negativeX = (octant & 1u) != 0u;
    bool negativeY = (octant & 2u) != 0u;
    bool negativeZ = (octant & 4u) != 0u;
    NearFarBounds b;
    b.nearX = negativeX ? hiX : loX;
    b.farX = negativeX ? loX : hiX;
    b.nearY = negativeY ? hiY : loY;
    b.farY = negativeY ? loY : hiY;
    b.nearZ = negativeZ ? hiZ : loZ;
    b.farZ = negativeZ ? loZ : hiZ;
    return b;
}

// The larger and smaller of two distances that are never NaN, as a compare and a select.
VKPT_FN float largerOf(float a, float b) {
    return a > b ? a : b;
}
VKPT_FN float smallerOf(float a, float b) {
    return a < b ? a : b;
}

// Where the ray enters child `slot`'s box within (tMin, best t), VKPT_FAR when it does not:
// intersectBox's slab test (Ize's widened exit, slabFar for rays parallel to a slab) on the
// decoded box. q·2^e is exact (8 bits times a power of two), so the one rounding of a decoded
// bound is the sum's, which the builder checked gives a box around the child's. An empty slot
// (lo = 255, hi = 0 on every axis) has its near planes beyond its far ones: no hit.
VKPT_FN float enterChild(WideWalk walk, vec3 scale, vec3 origin, NearFarBounds b, uint slot) {
    vec3 near = vec3(wideQuantisedByte(b.nearX.x, b.nearX.y, slot),
                     wideQuantisedByte(b.nearY.x, b.nearY.y, slot),
                     wideQuantisedByte(b.nearZ.x, b.nearZ.y, slot));
    vec3 far = vec3(wideQuantisedByte(b.farX.x, b.farX.y, slot),
                    wideQuantisedByte(b.farY.x, b.farY.y, slot),
                    wideQuantisedByte(b.farZ.x, b.farZ.y, slot));
    vec3 tNear = (origin + near * scale - walk.origin) * walk.invDirection;
    vec3 tFar = (origin + far * scale - walk.origin) * walk.invDirection;
    float enter = largerOf(largerOf(tNear.x, tNear.y), largerOf(tNear.z, walk.tMin));
    float exit = smallerOf(smallerOf(slabFar(tFar.x, walk.invDirection.x),
                                     slabFar(tFar.y, walk.invDirection.y)),
                           smallerOf(slabFar(tFar.z, walk.invDirection.z), walk.t)) *
                 1.0000004f;
    return enter <= exit ? enter : VKPT_FAR;
}

// The slots among 0–3 (or 4–7, with `first` 4) whose boxes the ray enters.
VKPT_FN uint enteredSlots(vec4 entries, uint first) {
    uvec4 entered = uvec4(lessThan(entries, vec4(VKPT_FAR)));
    return (entered.x | (entered.y << 1u) | (entered.z << 2u) | (entered.w << 3u)) << first;
}

// Fetches node `index` and tests its children: hit internal children become `pending`, hit
// leaves `leaves` (both in visiting order), and the first of those leaves is the current one.
VKPT_FN void visitNode(VKPT_INOUT(WideWalk) walk, uint index VKPT_BVH_PARAM) {
    uint texel = WIDE_BVH_TEXELS * index;
    uvec4 header = bvhNodeTexel(texel VKPT_BVH_ARG);
    uvec4 frame = bvhNodeTexel(texel + 1u VKPT_BVH_ARG);
    uvec4 q0 = bvhNodeTexel(texel + 2u VKPT_BVH_ARG);
    uvec4 q1 = bvhNodeTexel(texel + 3u VKPT_BVH_ARG);
    uvec4 q2 = bvhNodeTexel(texel + 4u VKPT_BVH_ARG);
    vec3 scale = wideGridScale(header);
    vec3 origin = uintBitsToFloat(uvec3(frame.x, frame.y, frame.z));
    NearFarBounds bounds = nearFarBounds(q0, q1, q2, walk.octant);
    // Written out: eight box tests in straight-line code, no loop for lavapipe to mask.
    walk.entryLow = vec4(
        enterChild(walk, scale, origin, bounds, 0u), enterChild(walk, scale, origin, bounds, 1u),
        enterChild(walk, scale, origin, bounds, 2u), enterChild(walk, scale, origin, bounds, 3u));
    walk.entryHigh = vec4(
        enterChild(walk, scale, origin, bounds, 4u), enterChild(walk, scale, origin, bounds, 5u),
        enterChild(walk, scale, origin, bounds, 6u), enterChild(walk, scale, origin, bounds, 7u));
    walk.entriesCurrent = true;
    uint hits = enteredSlots(walk.entryLow, 0u) | enteredSlots(walk.entryHigh, 4u);
    uint internal = wideInternalSlots(header);
    walk.node = index;
    walk.header = header;
    walk.leafCounts = frame.w;
    walk.pending = orderSlotBits(hits & internal, walk.octant);
    walk.leaves = orderSlotBits(hits & ~internal, walk.octant);
    ++walk.nodesVisited;
    takeNextLeaf(walk);
}

// Points the walk's ray (origin, direction and what is derived from them) at a space.
VKPT_FN void aimWalk(VKPT_INOUT(WideWalk) walk, vec3 origin, vec3 direction) {
    walk.origin = origin;
    walk.direction = direction;
    walk.octant = rayOctant(direction);
    walk.invDirection = safeInverseDirection(direction);
    walk.sheared = shearRay(direction);
}

// A walk of (tMin, tMax), standing at the root's children; continueWideWalk does the rest.
VKPT_FN WideWalk beginWideWalk(vec3 origin, vec3 direction, float tMin, float tMax,
                               bool stopAtFirst VKPT_BVH_PARAM) {
    WideWalk walk;
    aimWalk(walk, origin, direction);
    walk.tMin = tMin;
    walk.stopAtFirst = stopAtFirst;
    walk.t = tMax;
    walk.u = 0.0f;
    walk.v = 0.0f;
    walk.primitive = NO_PRIMITIVE;
    walk.hitInstance = NO_INSTANCE;
#if VKPT_INSTANCES
    walk.worldOrigin = origin;
    walk.worldDirection = direction;
    walk.instance = NO_INSTANCE;
    walk.top.stack.words = uvec4(0u);
    walk.top.stack.overflow = uvec4(0u);
    walk.top.depth = 0u;
    walk.top.node = 0u;
    walk.top.pending = 0u;
    walk.top.leaves = 0u;
    walk.top.next = 0u;
    walk.top.end = 0u;
#endif
    walk.stack.words = uvec4(0u);
    walk.stack.overflow = uvec4(0u);
    walk.depth = 0u;
    walk.next = 0u;
    walk.end = 0u;
    walk.entriesCurrent = false;
    walk.nodesVisited = 0u;
    walk.primitiveTests = 0u;
    visitNode(walk, 0u VKPT_BVH_ARG);
    return walk;
}

// Ends the walk where it stands (an any-hit query's first hit).
VKPT_FN void finishWideWalk(VKPT_INOUT(WideWalk) walk) {
    walk.depth = WIDE_WALK_DONE;
    walk.pending = 0u;
    walk.leaves = 0u;
    walk.next = walk.end;
}

// Takes a crossing of the instance the walk stands in as the best so far (the alpha test, if
// any, has passed).
VKPT_FN void takeCrossing(VKPT_INOUT(WideWalk) walk, TriangleHit h, uint primitive) {
    walk.t = h.t;
    walk.u = h.u;
    walk.v = h.v;
    walk.primitive = primitive;
    walk.hitInstance = WALK_INSTANCE(walk);
    if (walk.stopAtFirst) finishWideWalk(walk);
}

#if VKPT_INSTANCES
// From a top-level leaf into instance `index`: keeps the top level's place, moves the ray into
// the mesh's space and visits the mesh's root, whose first leaf becomes the current one.
VKPT_FN void enterInstance(VKPT_INOUT(WideWalk) walk, uint index VKPT_BVH_PARAM) {
    Instance x = bvhInstance(index VKPT_BVH_ARG);
    walk.top.stack = walk.stack;
    walk.top.depth = walk.depth;
    walk.top.node = walk.node;
    walk.top.pending = walk.pending;
    walk.top.leaves = walk.leaves;
    walk.top.next = walk.next;
    walk.top.end = walk.end;
    walk.instance = index;
    aimWalk(walk, instanceRayOrigin(x, walk.worldOrigin),
            instanceRayDirection(x, walk.worldDirection));
    walk.stack.words = uvec4(0u);
    walk.stack.overflow = uvec4(0u);
    walk.depth = 0u;
    visitNode(walk, x.root VKPT_BVH_ARG);
}

// Back from an instance whose tree is done to where the top level stood.
VKPT_FN void leaveInstance(VKPT_INOUT(WideWalk) walk VKPT_BVH_PARAM) {
    walk.instance = NO_INSTANCE;
    aimWalk(walk, walk.worldOrigin, walk.worldDirection);
    walk.stack = walk.top.stack;
    walk.depth = walk.top.depth;
    walk.node = walk.top.node;
    walk.header = bvhNodeTexel(WIDE_BVH_TEXELS * walk.node VKPT_BVH_ARG);
    walk.leafCounts = bvhNodeTexel(WIDE_BVH_TEXELS * walk.node + 1u VKPT_BVH_ARG).w;
    walk.pending = walk.top.pending;
    walk.leaves = walk.top.leaves;
    walk.next = walk.top.next;
    walk.end = walk.top.end;
    walk.entriesCurrent = false; // the entries were the instance's nodes'
}
#endif // VKPT_INSTANCES

// The primitive's crossing within (tMin, best t], or within the ray's (tMin, tMax) before the
// first (crossingPrecedes decides the ties).
VKPT_FN TriangleHit crossBvhPrimitive(WideWalk walk, Triangle primitive VKPT_BVH_PARAM) {
    float tMax = walk.primitive == NO_PRIMITIVE ? walk.t : nextFloatUp(walk.t);
    if (bvhHasSpheres(VKPT_BVH_ARG_ONLY) && isSpherePrimitive(primitive))
        return intersectSphere(walk.origin, walk.direction, primitive.v0, primitive.v1.x, walk.tMin,
                               tMax);
    return intersectTriangleWatertight(walk.origin, walk.sheared, primitive.v0, primitive.v1,
                                       primitive.v2, walk.tMin, tMax);
}

// Tests the current node's remaining leaf primitives; returns a crossing of an alpha-masked
// primitive for the includer to test (the walk stands just past it), else NO_PRIMITIVE. Never
// at the top level of a two-level walk, whose leaves continueWideWalk enters one by one.
VKPT_FN PendingCrossing testLeaves(VKPT_INOUT(WideWalk) walk VKPT_BVH_PARAM) {
    PendingCrossing pending;
    pending.primitive = NO_PRIMITIVE;
    while (walk.next < walk.end) {
        uint index = walk.next;
        ++walk.next;
        if (walk.next == walk.end) takeNextLeaf(walk);
        ++walk.primitiveTests;
        Triangle primitive = bvhPrimitive(index VKPT_BVH_ARG);
        TriangleHit h = crossBvhPrimitive(walk, primitive VKPT_BVH_ARG);
        if (!h.hit || !instancedCrossingPrecedes(h.t, WALK_INSTANCE(walk), index, walk.t,
                                                 walk.hitInstance, walk.primitive))
            continue;
        // Marked at load time (PRIMITIVE_ALPHA_MASKED): no material read per crossing.
        if (bvhHasAlphaMask(VKPT_BVH_ARG_ONLY) && isAlphaMaskedPrimitive(primitive)) {
            pending.hit = h;
            pending.primitive = index;
            return pending;
        }
        takeCrossing(walk, h, index);
    }
    return pending;
}

// Climbs from a node whose children are all done to the first ancestor with children left,
// or to the root.
VKPT_FN void climbToPendingAncestor(VKPT_INOUT(WideWalk) walk VKPT_BVH_PARAM) {
    // Children entered beyond a crossing found in this node's leaves need no visit.
    walk.pending &= ~childrenBeyondBest(walk);
    while (walk.pending == 0u && walk.depth > 0u) {
        walk.entriesCurrent = false;
        walk.node = WIDE_HEADER_PARENT(walk.header);
        walk.header = bvhNodeTexel(WIDE_BVH_TEXELS * walk.node VKPT_BVH_ARG);
        walk.pending = popMask(walk.stack);
        --walk.depth;
    }
}

// Walks on until the walk ends or a crossing needs the alpha test (returned, with the walk
// standing just past it; continue with the same call after deciding).
//
// Mesa 22.3's lavapipe silently leaves loops once an invocation's loops have run 65,535
// condition tests (docs/gpu.md). A walk cut short must not look finished, so the walk is
// marked finished only where it really ends, and each inner loop's cut is detected with a
// test the compiler cannot fold into the loop's own exit condition: the leaf loop ends when
// next >= end, its cut shows as next != end; the climb ends at a pending mask or depth 0, its
// cut as a node without pending children that is not the root (its parent link is not BVH_END).
VKPT_FN PendingCrossing continueWideWalk(VKPT_INOUT(WideWalk) walk VKPT_BVH_PARAM) {
    PendingCrossing pending;
    pending.primitive = NO_PRIMITIVE;
    while (walk.depth <= WIDE_BVH_MAX_DEPTH) {
        // A top-level leaf holds instances: the next one is entered here, in the node loop, so
        // that the leaf loop below stays the single-level one (lavapipe would run the entry's
        // code, masked, at every primitive test; docs/gpu.md).
#if VKPT_INSTANCES
        if (bvhHasInstances(VKPT_BVH_ARG_ONLY) && walk.instance == NO_INSTANCE &&
            walk.next < walk.end) {
            uint index = walk.next;
            ++walk.next;
            if (walk.next == walk.end) takeNextLeaf(walk);
            enterInstance(walk, index VKPT_BVH_ARG);
        }
#endif
        pending = testLeaves(walk VKPT_BVH_ARG);
        if (pending.primitive != NO_PRIMITIVE || walk.depth == WIDE_WALK_DONE) break;
        if (walk.next != walk.end) break; // the leaf loop was cut short
        climbToPendingAncestor(walk VKPT_BVH_ARG);
        if (walk.pending == 0u) {
            // At a root the tree is done; elsewhere the climb was cut short.
            if (WIDE_HEADER_PARENT(walk.header) != BVH_END) break;
#if VKPT_INSTANCES
            if (bvhHasInstances(VKPT_BVH_ARG_ONLY) && walk.instance != NO_INSTANCE) {
                leaveInstance(walk VKPT_BVH_ARG); // an instance's root: on with the top level
                continue;
            }
#endif
            finishWideWalk(walk);
            break;
        }
        uint slot = uint(findLSB(walk.pending)) ^ walk.octant;
        walk.pending &= walk.pending - 1u;
        uint child = wideChildIndex(walk.header, slot);
        pushMask(walk.stack, walk.pending);
        ++walk.depth;
        visitNode(walk, child VKPT_BVH_ARG);
    }
    return pending;
}

// Whether a driver's loop limit ended the walk before its end.
VKPT_FN bool wideWalkTruncated(WideWalk walk) {
    return walk.depth != WIDE_WALK_DONE;
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_WIDE_BVH_H
