// integrators.h — the reference's estimators of the radiance arriving along a camera ray.
#pragma once

#include "common/render_settings.h"
#include "reference/scene_tracer.h"
#include "shared/sample_features.h"
#include "shared/sampler.h"

namespace vkpt {

// Which numbers a camera sample draws (shared/sampler.h): the render's sampler setup and image
// width with the sample's seed, pixel and index.
struct SampleKey {
    std::uint32_t samplerSetup = 0;
    std::uint32_t width = 0;
    std::uint32_t seed = 0;
    std::uint32_t pixel = 0;
    std::uint32_t sampleIndex = 0;
};

// The four numbers of one (bounce, dimension) of the sample (docs/integrator.md).
inline glm::vec4 sampleFloats(const SampleKey& key, std::uint32_t bounce, std::uint32_t dimension) {
    return gpu::sampleFloats(key.samplerSetup, key.width, key.seed, key.pixel, key.sampleIndex,
                             bounce, dimension);
}

struct IntegratorContext {
    const RenderSettings& settings;
    SceneTracer& tracer;
    const gpu::Camera& camera;
};

struct CameraRay {
    glm::vec3 origin;
    glm::vec3 direction;
};

// Each integrator writes the camera sample's AOVs from its own first hit into `firstHit` when
// that is not null (a miss leaves it as it is: gpu::missFeatures()).

// Next-event estimation with MIS (power heuristic) against cosine-weighted BSDF sampling,
// Russian roulette by shared/path_rules.h.
glm::vec3 integratePath(IntegratorContext& context, const SampleKey& key, const CameraRay& ray,
                        gpu::SampleFeatures* firstHit);

// CS184's direct lighting: emission seen directly plus one bounce, estimated either with N
// uniform hemisphere directions or with N light samples (no MIS: each alone is unbiased).
glm::vec3 integrateDirect(IntegratorContext& context, const SampleKey& key, const CameraRay& ray,
                          gpu::SampleFeatures* firstHit);

// The shading normal at the first hit mapped to colour (n + 1) / 2; black on a miss.
glm::vec3 integrateNormals(IntegratorContext& context, const CameraRay& ray,
                           gpu::SampleFeatures* firstHit);

glm::vec3 integrate(IntegratorContext& context, const SampleKey& key, const CameraRay& ray,
                    gpu::SampleFeatures* firstHit = nullptr);

// The AOVs of a camera ray's hit (for the integrators).
void recordFirstHit(const IntegratorContext& context, const gpu::SurfacePoint& surface, float t,
                    const CameraRay& ray, gpu::SampleFeatures* firstHit);

} // namespace vkpt
