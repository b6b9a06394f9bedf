// traversal_stats.glsl — the traversal work of a dispatch (BVH nodes visited, primitives
// tested, walks cut short), added to queueCounters once per subgroup rather than per ray
// (lib/counters.glsl). Kernels call countTraversal() from every invocation still running, with
// a zero Traversal where there was no walk. Needs queueCounters and what traverse.glsl needs.
#ifndef VKPT_TRAVERSAL_STATS_GLSL
#define VKPT_TRAVERSAL_STATS_GLSL

#include "lib/counters.glsl"
#include "lib/traverse.glsl"

// The statistics of no walk, for invocations without a ray.
Traversal noTraversal() {
    Traversal none;
    none.hit = HitRecord(VKPT_FAR, 0.0, 0.0, NO_HIT);
    none.instance = NO_INSTANCE;
    none.truncated = false;
    none.nodesVisited = 0u;
    none.triangleTests = 0u;
    return none;
}

void countTraversal(Traversal walk) {
    addToCounter64InSubgroup(COUNTER_NODES_VISITED, walk.nodesVisited);
    addToCounter64InSubgroup(COUNTER_TRIANGLE_TESTS, walk.triangleTests);
    uint truncated = subgroupAdd(walk.truncated ? 1u : 0u);
    if (subgroupElect() && truncated != 0u) atomicAdd(queueCounters[COUNTER_TRUNCATED], truncated);
}

#endif // VKPT_TRAVERSAL_STATS_GLSL
