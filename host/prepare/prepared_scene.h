// prepared_scene.h — the loaded scene in the layouts both executors consume: the BVH tree (or,
// with instances, its two levels), its flattened nodes, primitives (triangles and spheres) and
// their normals, texture coordinates and tangents in BVH order, materials, textures, the emitter
// list and the environment. An array a scene's features do not need stays empty
// (docs/scene-model.md), unless the general layout was asked for.
#pragma once

#include <optional>
#include <vector>

#include "bvh/bvh_build.h"
#include "common/render_settings.h"
#include "prepare/level_cache.h"
#include "scene/scene.h"
#include "scene/scene_features.h"
#include "shared/host_device.h"
#include "shared/scene_array_table.h"

namespace vkpt {

// A bottom-level BVH of a two-level scene: the world's own geometry or a stored mesh, in its own
// space. Its nodes and primitives are ranges of PreparedScene::nodes and ::triangles.
struct PreparedMesh {
    BvhTree tree; // leaves index its own primitives, 0 .. primitiveCount − 1
    std::uint32_t rootNode = 0;
    std::uint32_t firstPrimitive = 0; // in triangles, normals, uvs and tangents
    std::uint32_t primitiveCount = 0;
};

// A template template argument of one parameter (std::vector has two).
template <class T> using HostArray = std::vector<T>;

// The arrays the device reads are the members of gpu::SceneArrayMembers, one std::vector per row
// of shared/scene_array_table.h (nodes, triangles, ..., albedoTables), named in its `member`
// column; the rest is here.
struct PreparedScene : gpu::SceneArrayMembers<HostArray> {
    BvhTree tree;                         // single-level: for the reference's stack traversal
    BvhStats bvhStats;                    // with the build time (two-level: of all levels)
    gpu::EnvironmentParams environment{}; // emitterIndex NO_EMITTER without an environment
    // Two-level scenes (features.instances, two_level_bvh.h): the bottom levels (the world's own
    // geometry first when it has any, then Scene::meshes), the top level over the instances'
    // world boxes (the instances array holds the instances in its leaf order); `tree` is then
    // empty.
    std::vector<PreparedMesh> meshes;
    BvhTree instanceTree;
    // Per bottom level, in the order of the primitive arrays (the one level of a single-level
    // scene): what its records hash to, for the scene's fingerprint (scene_hash.h).
    std::vector<LevelHashes> levelHashes;
    SceneFeatures features;     // what the scene uses (all of it for a general layout)
    SceneFeatures usedFeatures; // what the scene uses, whatever the layout
    double totalEmittedPower = 0.0;
};

// Where --light-sampler auto starts choosing emitters by the light BVH. Below it the tree's
// walk costs time for choices that differ little from power sampling's: at equal samples the
// Cornell boxes' relMSE stayed within 1 % (2 and 12 emitters) while their whole-process times
// grew 3–37 %; from EmissiveStrengthTest's 60 emitters on it won (relMSE 2.2× lower, relMSE ×
// seconds 1.5–1.6×; the many-lights scene's 4,608: 4.4–6.1×). docs/trade/light-sampler.md.
inline constexpr std::uint32_t kLightTreeMinEmitters = 16;

struct PrepareOptions {
    BvhBuildOptions bvh;
    // --general: every array present and every feature on, as if the scene used everything.
    bool general = false;
    // --light-sampler: how several emitters are chosen (the light BVH or power; auto: the light
    // BVH from kLightTreeMinEmitters on).
    LightSampler lightSampler = LightSampler::Auto;
    // An animation's frames: bottom-level trees kept from the frames before, taken again for
    // geometry whose primitives' boxes did not change (bvh_cache.h); nullptr: every tree built.
    BvhCache* bvhCache = nullptr;
    // An animation's frames: bottom levels (trees, records and their hashes) kept from the frames
    // before, taken again for geometry that is the very same (level_cache.h); on a miss the tree
    // still comes through bvhCache. nullptr: every level prepared.
    LevelCache* levelCache = nullptr;
};

PreparedScene prepareScene(const Scene& scene, const PrepareOptions& options = {});

// The radius of the scene's bounding sphere: directional and environment light cover a disk
// of it (their power estimates). 1 for an empty scene.
double sceneBoundingRadius(const Scene& scene);

// Triangles and shading normals in the order of tree.primitiveOrder.
void makeGpuTriangles(const Scene& scene, const BvhTree& tree,
                      std::vector<gpu::Triangle>& triangles,
                      std::vector<gpu::TriangleNormals>& normals);

} // namespace vkpt
