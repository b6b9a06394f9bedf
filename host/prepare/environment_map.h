// environment_map.h — the environment light on the host: an equirectangular map read from a
// file (--env), and the tables by which both renderers importance sample it
// (shared/environment.h reads them).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "shared/host_device.h"

namespace vkpt {

// The largest map accepted: a side of 65536 texels keeps texel indices exact in float
// (environmentCell), and 2^28 texels keep every CDF index within 32 bits.
inline constexpr std::uint32_t kMaxEnvironmentSide = 65536;
inline constexpr std::uint64_t kMaxEnvironmentTexels = std::uint64_t(1) << 28;

// The layout PreparedScene uploads (environmentTexels, environmentCdf), and what light
// selection needs to know of the environment.
struct EnvironmentDistribution {
    std::vector<glm::vec4> texels; // the map's RGB (w = 0), row 0 at the top; empty: constant
    // height rows of width inclusive conditional CDF entries (row r by the luminance of its
    // texels), then height inclusive marginal entries (row r by its luminance sum × sin θ of
    // its centre). Every row and the marginal end at exactly 1. Empty for a constant colour.
    std::vector<float> cdf;
    // Flux for emitter selection, π·R²·∫ luminance(L) dω (pbrt-v4's ImageInfiniteLight::Phi):
    // what enters the bounding sphere of radius R, in the units of the other emitters' powers.
    double power = 0.0;
    glm::dvec3 averageRadiance{0.0}; // (1/4π)·∫ L dω, the scale included
    // An all-black map: sampled as if every texel had luminance 1 (rows by sin θ, so nearly
    // uniform over the sphere) so that the tables stay a valid pdf; its power is 0, so light
    // selection never picks it, but BSDF-sampled rays still get a finite MIS weight.
    bool uniformFallback = false;
};

// Reads an equirectangular .hdr or .pfm map (row 0 at the top, +Y; see shared/environment.h
// for the orientation) with `scale` as its radiance factor. Throws InputError naming the path
// for a missing or malformed file, an empty or oversized image, a non-finite or negative
// texel, or a non-finite or negative scale.
SceneEnvironment readEnvironmentMap(const std::string& path, glm::vec3 scale);

// The sampling tables of `environment`'s map and its power, for a scene whose bounding sphere
// has radius sceneRadius. A constant colour has no tables: its power is 4π²R²·luminance.
EnvironmentDistribution buildEnvironmentDistribution(const SceneEnvironment& environment,
                                                     double sceneRadius);

// The parameters the kernels read: radiance, the map's size (0 for a constant colour) and the
// environment's index in the emitter list (NO_EMITTER when there is none).
gpu::EnvironmentParams makeEnvironmentParams(const SceneEnvironment& environment,
                                             std::uint32_t emitterIndex);

} // namespace vkpt
