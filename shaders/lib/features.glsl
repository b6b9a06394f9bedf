// features.glsl — the scene features a kernel is specialised for (FEATURE_* of
// shared/host_device.h), as boolean specialisation constants. The host sets them from the
// scene's SceneFeatures when it creates the pipelines (host/render/wavefront_kernels.cpp) and
// folds them into the module (host/gpu/spirv_specialise.h), so code guarded by a feature the
// scene lacks never reaches the driver and its buffers are never read. The defaults (everything on) are the general kernels.
#ifndef VKPT_FEATURES_GLSL
#define VKPT_FEATURES_GLSL

#include "shared/host_device.h"

#ifndef VKPT_DIFFUSE_ONLY
#define VKPT_DIFFUSE_ONLY 0
#endif

#if VKPT_DIFFUSE_ONLY
// The build for scenes whose materials are all Lambertian (shaders/CMakeLists.txt): the layered
// BSDF's features are constants of the build, which its optimiser folds away, so a driver never
// parses code such a scene cannot reach.
const bool featureMetallicRoughness = false;
const bool featureTransmission = false;
const bool featureClearcoat = false;
const bool featureSheen = false;
const bool featureSpecularTextures = false;
const bool featureAnisotropy = false;
const bool featureIridescence = false;
const bool featureDiffuseTransmission = false;
const bool featureDispersion = false;
#else
// glTF GGX materials (diffuse-only scenes keep the Lambertian BSDF alone).
layout(constant_id = FEATURE_METALLIC_ROUGHNESS) const bool featureMetallicRoughness = true;
// KHR_materials_transmission, _ior, _volume: glass lobes, volumes, an ior other than 1.5.
layout(constant_id = FEATURE_TRANSMISSION) const bool featureTransmission = true;
// Some material has a KHR_materials_clearcoat layer.
layout(constant_id = FEATURE_CLEARCOAT) const bool featureClearcoat = true;
// Some material has a KHR_materials_sheen layer.
layout(constant_id = FEATURE_SHEEN) const bool featureSheen = true;
// Some GGX material has a KHR_materials_specular texture.
layout(constant_id = FEATURE_SPECULAR_TEXTURES) const bool featureSpecularTextures = true;
// Some GGX material has KHR_materials_anisotropy: shading reads triangleTangents for its direction.
layout(constant_id = FEATURE_ANISOTROPY) const bool featureAnisotropy = true;
// Some GGX material has a KHR_materials_iridescence film.
layout(constant_id = FEATURE_IRIDESCENCE) const bool featureIridescence = true;
// Some material's diffuse base transmits (KHR_materials_diffuse_transmission): shading reads
// materialLobes, and light sampling reaches the far side of a thin wall.
layout(constant_id = FEATURE_DIFFUSE_TRANSMISSION) const bool featureDiffuseTransmission = true;
// Some glass disperses (KHR_materials_dispersion): a path that meets it carries a wavelength in
// PathState (shared/dispersion.h).
layout(constant_id = FEATURE_DISPERSION) const bool featureDispersion = true;
#endif
// Base colour, metallic-roughness or emissive textures, and the TEXCOORD_0 they are read at.
layout(constant_id = FEATURE_TEXTURES) const bool featureTextures = true;
// alphaMode MASK: traversals skip the cut-out parts of such materials.
layout(constant_id = FEATURE_ALPHA_MASK) const bool featureAlphaMask = true;
// Analytic spheres among the primitives.
layout(constant_id = FEATURE_SPHERES) const bool featureSpheres = true;
// KHR_lights_punctual point, spot and directional lights.
layout(constant_id = FEATURE_PUNCTUAL_LIGHTS) const bool featurePunctualLights = true;
// Rays that leave the scene see an environment (a constant colour or a map).
layout(constant_id = FEATURE_ENVIRONMENT) const bool featureEnvironment = true;
// The environment is an equirectangular map (environmentTexels, environmentCdf).
layout(constant_id = FEATURE_ENVIRONMENT_MAP) const bool featureEnvironmentMap = true;
// More than one emitter: selection reads the CDF (emitterCdf).
layout(constant_id = FEATURE_EMITTER_CDF) const bool featureEmitterCdf = true;
// Emitters are chosen by the light BVH (lightTree) instead of the power CDF.
layout(constant_id = FEATURE_LIGHT_TREE) const bool featureLightTree = true;
// Some material is double-sided: emission may leave the back face.
layout(constant_id = FEATURE_DOUBLE_SIDED) const bool featureDoubleSided = true;
// Some material has a normal texture: shading reads triangleTangents and bends the normal.
layout(constant_id = FEATURE_NORMAL_MAPS) const bool featureNormalMaps = true;
// A two-level BVH: the top level's leaves are instances of meshes (shared/instance.h). A layout
// the scene has or has not, not a feature the general kernels add: the kernels it changes are
// built once for each (VKPT_INSTANCES, shared/host_device.h), so it is a constant of the build.
const bool featureInstances = VKPT_INSTANCES != 0;

#endif // VKPT_FEATURES_GLSL
