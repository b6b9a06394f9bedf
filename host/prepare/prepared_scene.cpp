// prepared_scene.cpp — builds the BVH over the scene's primitives and lays the scene out for
// rendering, creating only the arrays its features need (or all of them, for --general).
#include "prepare/prepared_scene.h"

#include <chrono>

#include "bvh/bvh_wide.h"
#include "common/errors.h"
#include "common/phase_log.h"
#include "prepare/bvh_cache.h"
#include "prepare/emitters.h"
#include "prepare/environment_map.h"
#include "prepare/gpu_materials.h"
#include "prepare/gpu_primitives.h"
#include "prepare/level_cache.h"
#include "prepare/light_tree.h"
#include "prepare/two_level_bvh.h"
#include "shared/albedo_lookup.h"

namespace vkpt {

namespace {

void prepareEnvironment(const Scene& scene, double radius, PreparedScene& prepared, double& power) {
    prepared.environment = gpu::EnvironmentParams{};
    prepared.environment.emitterIndex = NO_EMITTER;
    power = 0.0;
    if (!scene.environment.present()) return;
    EnvironmentDistribution distribution = buildEnvironmentDistribution(scene.environment, radius);
    prepared.environment.radiance = scene.environment.radiance;
    prepared.environment.width = scene.environment.width;
    prepared.environment.height = scene.environment.height;
    prepared.environmentTexels = std::move(distribution.texels);
    prepared.environmentCdf = std::move(distribution.cdf);
    // A present environment is always sampled, however dark its map: the floor keeps its
    // selection probability above 0 so that MIS weights stay defined.
    power = distribution.power > 0.0 ? distribution.power : 1e-30;
}

std::uint32_t findEnvironmentEmitter(const std::vector<gpu::Emitter>& emitters) {
    for (std::size_t i = 0; i < emitters.size(); ++i)
        if (emitters[i].kind == EMITTER_ENVIRONMENT) return std::uint32_t(i);
    return NO_EMITTER;
}

// One BVH over the scene's own geometry.
void prepareSingleLevel(const Scene& scene, const PrepareOptions& options, bool withUvs,
                        bool withTangents, PreparedScene& prepared) {
    const std::size_t primitiveCount = scene.triangleCount() + scene.spheres.size();
    VKPT_ASSERT(primitiveCount < BVH_MAX_TRIANGLES, "primitive count fits a leaf word");
    auto start = std::chrono::steady_clock::now();
    const LevelGeometry geometry{scene, scene.spheres, scene.materials};
    const LevelLayout layout{options.bvh, withUvs, withTangents};
    PreparedLevel built;
    if (options.levelCache != nullptr) {
        // Copied: the kept level stays for the frames after.
        built = options.levelCache->get(geometry, layout, options.bvhCache, BuildPhases::Logged);
    } else {
        built = prepareLevel(geometry, layout, options.bvhCache, BuildPhases::Logged);
    }
    std::chrono::duration<double> buildTime = std::chrono::steady_clock::now() - start;
    prepared.tree = std::move(built.bvh.tree);
    prepared.nodes = std::move(built.bvh.nodes);
    prepared.bvhStats = built.stats;
    prepared.bvhStats.buildSeconds = buildTime.count();
    prepared.triangles = std::move(built.primitives.records);
    prepared.normals = std::move(built.primitives.normals);
    prepared.uvs = std::move(built.primitives.uvs);
    prepared.tangents = std::move(built.primitives.tangents);
    prepared.levelHashes = {built.hashes};
}

bool usesLightTree(LightSampler sampler, std::size_t emitters) {
    if (emitters <= 1) return false; // nothing to choose
    if (sampler == LightSampler::Auto) return emitters >= kLightTreeMinEmitters;
    return sampler == LightSampler::Bvh;
}

} // namespace

double sceneBoundingRadius(const Scene& scene) {
    Bounds bounds = computeBounds(scene);
    if (bounds.min.x > bounds.max.x) return 1.0;
    double radius = 0.5 * glm::length(glm::dvec3(bounds.max) - glm::dvec3(bounds.min));
    return radius > 0.0 ? radius : 1.0;
}

PreparedScene prepareScene(const Scene& scene, const PrepareOptions& options) {
    VKPT_ASSERT(scene.positions.size() == 3 * scene.triangleCount(), "three vertices a triangle");
    PreparedScene prepared;
    prepared.usedFeatures = analyseScene(scene);
    prepared.features =
        options.general ? generalFeatures(prepared.usedFeatures) : prepared.usedFeatures;
    const SceneFeatures features = prepared.features;
    if (features.instances) {
        prepareTwoLevel(scene, options, features.textureCoordinates(), features.tangents(),
                        prepared);
    } else {
        prepareSingleLevel(scene, options, features.textureCoordinates(), features.tangents(),
                           prepared);
    }
    prepared.materials = makeGpuMaterials(scene.materials);
    if (features.specularLobes()) prepared.specularLobes = makeGpuSpecularLobes(scene.materials);
    if (features.diffuseTransmission || features.dispersion)
        prepared.materialLobes = makeGpuMaterialLobes(scene.materials);
    // The film nodes' tables (KHR_materials_iridescence) come last and only with a film.
    if (features.metallicRoughnessMaterials)
        prepared.albedoTables.assign(gpu::albedoTableEntries.begin(),
                                     features.iridescence ? gpu::albedoTableEntries.end()
                                                          : gpu::albedoTableEntries.begin() +
                                                                VKPT_ALBEDO_ENTRIES_WITHOUT_FILM);
    if (features.textures()) {
        GpuTextures textures = makeGpuTextures(scene);
        prepared.textures = std::move(textures.textures);
        prepared.texels = std::move(textures.texels);
    }

    const double radius = sceneBoundingRadius(scene);
    double environmentPower = 0.0;
    prepareEnvironment(scene, radius, prepared, environmentPower);
    ScopedPhase emitterPhase("emitters");
    EmitterList emitters =
        buildEmitters(scene, prepared.triangles, prepared.materials, {environmentPower, radius});
    emitterPhase.end();
    prepared.emitters = std::move(emitters.emitters);
    // The loader's count cannot know which emitting triangles repeat one another.
    prepared.usedFeatures.emitterCount = std::uint32_t(prepared.emitters.size());
    prepared.features.emitterCount = prepared.usedFeatures.emitterCount;
    if (prepared.features.emitterCdf()) prepared.emitterCdf = std::move(emitters.cdf);
    prepared.usedFeatures.lightTree = usesLightTree(options.lightSampler, prepared.emitters.size());
    prepared.features.lightTree = prepared.usedFeatures.lightTree;
    if (prepared.features.lightTree) {
        ScopedPhase lightTreePhase("light BVH");
        prepared.lightTree = buildLightTree(prepared.emitters, emitters.powers, prepared.triangles,
                                            prepared.materials);
    }
    prepared.totalEmittedPower = emitters.totalPower;
    prepared.environment.emitterIndex = findEnvironmentEmitter(prepared.emitters);
    return prepared;
}

} // namespace vkpt
