// counters.glsl — 64-bit statistics counters kept as (low, high) words of queueCounters,
// because Vulkan 1.2 does not guarantee 64-bit atomics. Needs queueCounters declared.
#ifndef VKPT_COUNTERS_GLSL
#define VKPT_COUNTERS_GLSL

// Adds `amount` to the counter whose low word is queueCounters[index]; a wrap of the low word
// (the old value plus amount overflows) carries into the high word.
void addToCounter64(uint index, uint amount) {
    if (amount == 0u) return;
    uint before = atomicAdd(queueCounters[index], amount);
    if (before + amount < before) atomicAdd(queueCounters[index + 1u], 1u);
}

#endif // VKPT_COUNTERS_GLSL
