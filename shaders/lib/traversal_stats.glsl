// traversal_stats.glsl — a workgroup's traversal work (BVH nodes and triangles tested, walks
// cut short), summed in shared memory and added to queueCounters once per workgroup, so the
// statistics cost one global atomic per 64 rays. Kernels call beginTraversalStats() and
// endTraversalStats() from every invocation (they contain barriers). Needs queueCounters
// and what traverse.glsl needs.
#ifndef VKPT_TRAVERSAL_STATS_GLSL
#define VKPT_TRAVERSAL_STATS_GLSL

#include "lib/counters.glsl"
#include "lib/traverse.glsl"

shared uint groupNodesVisited;
shared uint groupTriangleTests;
shared uint groupTruncated;

void beginTraversalStats() {
    if (gl_LocalInvocationIndex == 0u) {
        groupNodesVisited = 0u;
        groupTriangleTests = 0u;
        groupTruncated = 0u;
    }
    barrier();
}

void countTraversal(Traversal walk) {
    atomicAdd(groupNodesVisited, walk.nodesVisited);
    atomicAdd(groupTriangleTests, walk.triangleTests);
    if (walk.truncated) atomicAdd(groupTruncated, 1u);
}

void endTraversalStats() {
    barrier();
    if (gl_LocalInvocationIndex != 0u) return;
    addToCounter64(COUNTER_NODES_VISITED, groupNodesVisited);
    addToCounter64(COUNTER_TRIANGLE_TESTS, groupTriangleTests);
    if (groupTruncated != 0u) atomicAdd(queueCounters[COUNTER_TRUNCATED], groupTruncated);
}

#endif // VKPT_TRAVERSAL_STATS_GLSL
