// counters.glsl — appending to queues and adding to statistics in queueCounters with one
// atomic per subgroup, and 64-bit statistics counters kept as (low, high) words, because Vulkan
// 1.2 does not guarantee 64-bit atomics. Needs queueCounters declared (and lib/frame.glsl's
// subgroup extensions).
//
// An atomic per invocation costs lavapipe a serialised read-modify-write per lane (docs/gpu.md
// measured it as the largest part of a small kernel's time); a GPU likewise funnels every
// atomic on one address through one unit. Aggregating over the subgroup (ballot or add, one
// atomic by the elected invocation, its result broadcast) divides that by the subgroup size.
// Call these where every invocation of the subgroup that is still running takes part.
#ifndef VKPT_COUNTERS_GLSL
#define VKPT_COUNTERS_GLSL

// Adds `amount` to the counter whose low word is queueCounters[index]; a wrap of the low word
// (the old value plus amount overflows) carries into the high word.
void addToCounter64(uint index, uint amount) {
    if (amount == 0u) return;
    uint before = atomicAdd(queueCounters[index], amount);
    if (before + amount < before) atomicAdd(queueCounters[index + 1u], 1u);
}

// Adds each invocation's `amount` to the 64-bit counter at `index`, one atomic per subgroup.
void addToCounter64InSubgroup(uint index, uint amount) {
    uint total = subgroupAdd(amount);
    if (subgroupElect()) addToCounter64(index, total);
}

// Reserves an entry of the queue counted by queueCounters[counter] for every invocation whose
// `append` is true and returns its index (meaningless where `append` is false). The order of
// entries follows the invocations', so it is the same for a given subgroup whatever the timing.
uint appendToQueue(uint counter, bool append) {
    uvec4 ballot = subgroupBallot(append);
    uint total = subgroupBallotBitCount(ballot);
    uint base = 0u;
    if (subgroupElect() && total > 0u) base = atomicAdd(queueCounters[counter], total);
    return subgroupBroadcastFirst(base) + subgroupBallotExclusiveBitCount(ballot);
}

#endif // VKPT_COUNTERS_GLSL
