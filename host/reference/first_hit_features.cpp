// first_hit_features.cpp — one camera ray per feature sample, rows of the window shared among
// threads.
#include "reference/first_hit_features.h"

#include <algorithm>
#include <atomic>
#include <limits>
#include <thread>

#include "reference/scene_tracer.h"
#include "shared/camera.h"
#include "shared/rng.h"

namespace vkpt {

namespace {

struct FeatureJob {
    const PreparedScene& scene;
    const IntersectorFactory& intersectors;
    const gpu::Camera& camera;
    std::uint32_t seed;
    const PixelRect& window;
    std::vector<FeatureRecord>& features;
    std::atomic<std::uint32_t> nextRow{0};
};

FeatureRecord pixelFeatures(FeatureJob& job, SceneTracer& tracer, std::uint32_t x,
                            std::uint32_t y) {
    const std::uint32_t pixel = y * job.camera.width + x;
    FeatureRecord f;
    f.depth = std::numeric_limits<float>::infinity();
    for (std::uint32_t s = 0; s < kFeatureSamples; ++s) {
        // The colour's camera sample s (docs/integrator.md): same jitter, same ray.
        const glm::vec4 jitter = gpu::randomFloats(job.seed, pixel, s, 0, DIM_CAMERA);
        const glm::vec2 film(float(x) + jitter.x, float(y) + jitter.y);
        const glm::vec3 origin = gpu::cameraRayOrigin(job.camera, film);
        const glm::vec3 direction = gpu::cameraRayDirection(job.camera, film);
        const ClosestHit hit = tracer.closest(origin, direction, RayKind::Camera);
        if (!hit.hit) continue;
        const gpu::SurfacePoint surface = tracer.surfaceAt(hit, origin, direction);
        f.albedo += surface.shading.baseColor;
        f.normal += surface.shadingNormal;
        f.depth = std::min(f.depth, hit.t * glm::dot(direction, job.camera.forward));
    }
    f.albedo /= float(kFeatureSamples);
    f.normal /= float(kFeatureSamples);
    return f;
}

void featureWorker(FeatureJob& job) {
    SceneTracer tracer(job.scene, job.intersectors);
    const PixelRect& w = job.window;
    for (std::uint32_t row = job.nextRow++; row < w.height(); row = job.nextRow++)
        for (std::uint32_t x = w.x0; x < w.x1; ++x)
            job.features[std::size_t(row) * w.width() + (x - w.x0)] =
                pixelFeatures(job, tracer, x, w.y0 + row);
}

} // namespace

std::vector<FeatureRecord> renderFirstHitFeatures(const PreparedScene& scene,
                                                  const IntersectorFactory& intersectors,
                                                  const gpu::Camera& camera, std::uint32_t seed,
                                                  const PixelRect& window, unsigned threads) {
    std::vector<FeatureRecord> features(window.area());
    FeatureJob job{scene, intersectors, camera, seed, window, features, {}};
    const unsigned count = std::max(
        1u, std::min(threads ? threads : std::thread::hardware_concurrency(), window.height()));
    std::vector<std::thread> workers;
    for (unsigned i = 0; i < count; ++i)
        workers.emplace_back(featureWorker, std::ref(job));
    for (std::thread& worker : workers)
        worker.join();
    return features;
}

} // namespace vkpt
