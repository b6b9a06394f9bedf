// two_level_bvh.cpp — builds the bottom levels, places them under the top level and lays all of
// them out for both walks.
#include "prepare/two_level_bvh.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <span>

#include "bvh/bvh_wide.h"
#include "common/errors.h"
#include "common/phase_log.h"
#include "prepare/bvh_cache.h"
#include "prepare/level_cache.h"

namespace vkpt {

namespace {

// One bottom level before its nodes are placed: its tree and its flattened nodes, numbered
// from 0 like its primitives.
struct BottomLevel {
    PreparedMesh mesh;
    // Its nodes: a level kept by the level cache reads them there (not copied twice), another
    // holds its own.
    std::span<const gpu::WideBvhNode> nodes;
    std::vector<gpu::WideBvhNode> ownNodes;
    BvhStats stats;
};

template <typename T> void append(std::vector<T>& to, const std::vector<T>& from) {
    to.insert(to.end(), from.begin(), from.end());
}

BottomLevel buildBottomLevel(const TriangleSoup& soup, std::span<const SceneSphere> spheres,
                             const Scene& scene, const PrepareOptions& options, bool withUvs,
                             bool withTangents, PreparedScene& prepared) {
    const LevelGeometry geometry{soup, spheres, scene.materials};
    const LevelLayout layout{options.bvh, withUvs, withTangents};
    BottomLevel level;
    PreparedLevel built;
    const PreparedLevel* source = &built;
    if (options.levelCache != nullptr) {
        // Copied: the cache keeps the level for the frames after.
        source = &options.levelCache->get(geometry, layout, options.bvhCache, BuildPhases::Silent);
        level.mesh.tree = source->bvh.tree;
        level.nodes = source->bvh.nodes;
    } else {
        built = prepareLevel(geometry, layout, options.bvhCache, BuildPhases::Silent);
        level.mesh.tree = std::move(built.bvh.tree);
        level.ownNodes = std::move(built.bvh.nodes);
        level.nodes = level.ownNodes; // the buffer stays where it is when the level moves
    }
    level.stats = source->stats;
    const GpuPrimitives& primitives = source->primitives;
    level.mesh.firstPrimitive = static_cast<std::uint32_t>(prepared.triangles.size());
    level.mesh.primitiveCount = static_cast<std::uint32_t>(primitives.records.size());
    append(prepared.triangles, primitives.records);
    append(prepared.normals, primitives.normals);
    append(prepared.uvs, primitives.uvs);
    append(prepared.tangents, primitives.tangents);
    prepared.levelHashes.push_back(source->hashes);
    return level;
}

// Room for every level's primitives at once: appended level by level into arrays without room,
// the world's records (a large set's tens of MiB) would be copied again, to fresh pages, for each
// mesh that follows them.
void reservePrimitiveArrays(const Scene& scene, bool withUvs, bool withTangents,
                            PreparedScene& prepared) {
    std::size_t count = scene.triangleCount() + scene.spheres.size();
    for (const SceneMesh& mesh : scene.meshes)
        count += mesh.triangleCount();
    prepared.triangles.reserve(count);
    prepared.normals.reserve(count);
    if (withUvs) prepared.uvs.reserve(3 * count);
    if (withTangents) prepared.tangents.reserve(count);
}

// Appends a bottom level's nodes, renumbered to their place in the one node array and to its
// primitives' place in the one primitive array.
void appendNodes(BottomLevel& level, std::vector<gpu::WideBvhNode>& nodes) {
    const auto first = static_cast<std::uint32_t>(nodes.size());
    level.mesh.rootNode = first;
    for (gpu::WideBvhNode node : level.nodes) {
        node.childBase += first;
        if (node.parent != BVH_END) node.parent += first;
        node.primitiveBase += level.mesh.firstPrimitive;
        nodes.push_back(node);
    }
    level.nodes = {};
    level.ownNodes = {};
}

glm::vec4 row(const glm::dmat4& m, int r) {
    return glm::vec4(float(m[0][r]), float(m[1][r]), float(m[2][r]), float(m[3][r]));
}

float below(double x) {
    return std::nextafter(static_cast<float>(x), std::numeric_limits<float>::lowest());
}

float above(double x) {
    return std::nextafter(static_cast<float>(x), std::numeric_limits<float>::max());
}

static_assert(SceneInstance::kKeepMaterial == INSTANCE_OWN_MATERIALS,
              "a scene instance's material carries over to the device record as it is");

// A placement of bottom level `level` by objectToWorld, before the top level orders them.
struct Placement {
    std::uint32_t level;
    glm::dmat4 objectToWorld;
    std::uint32_t material = INSTANCE_OWN_MATERIALS;
};

// Adds a bottom level's counts to the whole's; returns its depth.
std::uint32_t addStats(const BvhStats& stats, BvhStats& total) {
    total.nodeCount += stats.nodeCount;
    total.leafCount += stats.leafCount;
    total.maxLeafSize = std::max(total.maxLeafSize, stats.maxLeafSize);
    return stats.maxDepth;
}

} // namespace

gpu::Instance makeGpuInstance(const glm::dmat4& objectToWorld, std::uint32_t root,
                              std::uint32_t mesh, std::uint32_t material) {
    const glm::dmat4 worldToObject = glm::inverse(objectToWorld);
    gpu::Instance x{};
    x.worldToObject0 = row(worldToObject, 0);
    x.worldToObject1 = row(worldToObject, 1);
    x.worldToObject2 = row(worldToObject, 2);
    x.root = root;
    x.flags = glm::determinant(glm::dmat3(objectToWorld)) < 0.0 ? INSTANCE_MIRRORED : 0u;
    x.mesh = mesh;
    x.material = material;
    x.objectToWorld0 = row(objectToWorld, 0);
    x.objectToWorld1 = row(objectToWorld, 1);
    x.objectToWorld2 = row(objectToWorld, 2);
    return x;
}

Aabb placedBounds(const Aabb& own, const glm::dmat4& objectToWorld) {
    Aabb box;
    if (own.empty()) return box;
    glm::dvec3 lo(std::numeric_limits<double>::max());
    glm::dvec3 hi(std::numeric_limits<double>::lowest());
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p((corner & 1) ? own.max.x : own.min.x,
                           (corner & 2) ? own.max.y : own.min.y,
                           (corner & 4) ? own.max.z : own.min.z);
        const glm::dvec3 w(objectToWorld * glm::dvec4(p, 1.0));
        lo = glm::min(lo, w);
        hi = glm::max(hi, w);
    }
    box.min = glm::vec3(below(lo.x), below(lo.y), below(lo.z));
    box.max = glm::vec3(above(hi.x), above(hi.y), above(hi.z));
    return box;
}

void prepareTwoLevel(const Scene& scene, const PrepareOptions& options, bool withUvs,
                     bool withTangents, PreparedScene& prepared) {
    const auto start = std::chrono::steady_clock::now();
    ScopedPhase bottomPhase("bottom-level BVHs"); // built, or taken from the frame before
    std::vector<BottomLevel> levels;
    std::vector<Placement> placements;
    reservePrimitiveArrays(scene, withUvs, withTangents, prepared);
    // The world's own geometry, placed unmoved by an instance of its own.
    if (scene.triangleCount() + scene.spheres.size() > 0) {
        levels.push_back(buildBottomLevel(scene, scene.spheres, scene, options, withUvs,
                                          withTangents, prepared));
        placements.push_back({0, glm::dmat4(1.0)});
    }
    const auto firstMeshLevel = static_cast<std::uint32_t>(levels.size());
    for (const SceneMesh& mesh : scene.meshes) {
        for (std::uint32_t material : mesh.materialIndices)
            VKPT_ASSERT(!scene.materials[material].emits(),
                        "an instanced mesh holds no emitter (the loader flattens them)");
        levels.push_back(
            buildBottomLevel(mesh, {}, scene, options, withUvs, withTangents, prepared));
    }
    for (const SceneInstance& instance : scene.instances)
        placements.push_back(
            {firstMeshLevel + instance.mesh, instance.objectToWorld, instance.material});
    VKPT_ASSERT(prepared.triangles.size() < BVH_MAX_TRIANGLES, "primitive count fits a leaf word");
    bottomPhase.end();

    ScopedPhase topPhase("top-level BVH");
    std::vector<Aabb> bounds;
    bounds.reserve(placements.size());
    for (const Placement& p : placements)
        bounds.push_back(placedBounds(levels[p.level].mesh.tree.nodes[0].bounds, p.objectToWorld));
    BvhBuildOptions top = options.bvh;
    top.maxLeafSize = 1; // entering an instance costs a transform: one per leaf, culled alone
    prepared.instanceTree = buildBvh(bounds, top);
    prepared.nodes = flattenWideBvh(prepared.instanceTree);
    std::size_t nodeCount = prepared.nodes.size();
    for (const BottomLevel& level : levels)
        nodeCount += level.nodes.size();
    prepared.nodes.reserve(nodeCount);
    for (BottomLevel& level : levels)
        appendNodes(level, prepared.nodes);
    for (std::uint32_t placement : prepared.instanceTree.primitiveOrder) {
        const Placement& p = placements[placement];
        prepared.instances.push_back(
            makeGpuInstance(p.objectToWorld, levels[p.level].mesh.rootNode, p.level, p.material));
    }
    topPhase.end();

    prepared.bvhStats = computeBvhStats(prepared.instanceTree, top);
    std::uint32_t deepestBottom = 0;
    for (BottomLevel& level : levels) {
        deepestBottom = std::max(deepestBottom, addStats(level.stats, prepared.bvhStats));
        prepared.meshes.push_back(std::move(level.mesh));
    }
    prepared.bvhStats.maxDepth += deepestBottom + 1; // a top-level leaf leads to a bottom root
    prepared.bvhStats.buildSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace vkpt
