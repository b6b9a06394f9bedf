// traversal_rays.cpp — a SceneIntersector that answers with the ordered stack walk and writes
// down each query, sorted by where in the path it comes.
#include "traversal_rays.h"

#include "reference/integrators.h"
#include "reference/stack_intersector.h"
#include "shared/camera.h"
#include "shared/rng.h"

namespace vkpt::bench {

namespace {

enum SetIndex { kCameraRays, kBounceRays, kCameraShadowRays, kBounceShadowRays, kSetCount };

class RecordingIntersector final : public SceneIntersector {
public:
    RecordingIntersector(std::unique_ptr<SceneIntersector> answer, std::vector<RaySet>& sets)
        : answer_(std::move(answer)), sets_(sets) {}

    void beginSample() { closestQueries_ = 0; }

    // A query from tMin > 0 walks the previous ray again beyond a culled face: same set.
    ClosestHit closestHit(const glm::vec3& origin, const glm::vec3& direction,
                          float tMin) override {
        if (tMin == 0.0f) ++closestQueries_;
        SetIndex set = closestQueries_ == 1 ? kCameraRays : kBounceRays;
        sets_[set].rays.push_back({origin, direction, tMin, VKPT_FAR});
        return answer_->closestHit(origin, direction, tMin);
    }

    // A shadow ray before the first extension ray leaves the camera ray's hit.
    bool occluded(const glm::vec3& origin, const glm::vec3& direction, float tMax) override {
        SetIndex set = closestQueries_ <= 1 ? kCameraShadowRays : kBounceShadowRays;
        sets_[set].rays.push_back({origin, direction, 0.0f, tMax});
        return answer_->occluded(origin, direction, tMax);
    }

private:
    std::unique_ptr<SceneIntersector> answer_;
    std::vector<RaySet>& sets_;
    std::uint32_t closestQueries_ = 0;
};

// Hands the one recording intersector to the SceneTracer that owns it.
class RecordingFactory final : public IntersectorFactory {
public:
    RecordingFactory(const PreparedScene& scene, std::vector<RaySet>& sets)
        : stack_(scene), sets_(sets) {}
    std::unique_ptr<SceneIntersector> makeIntersector() const override {
        return std::make_unique<RecordingIntersector>(stack_.makeIntersector(), sets_);
    }

private:
    StackIntersectors stack_;
    std::vector<RaySet>& sets_;
};

} // namespace

std::vector<RaySet> recordRenderRays(const PreparedScene& scene, const gpu::Camera& camera,
                                     const RenderSettings& settings) {
    std::vector<RaySet> sets{{"closest, coherent", false, {}},
                             {"closest, incoherent", false, {}},
                             {"any-hit, coherent", true, {}},
                             {"any-hit, incoherent", true, {}}};
    RecordingFactory factory(scene, sets);
    SceneTracer tracer(scene, factory);
    IntegratorContext context{settings, tracer, camera};
    // SceneTracer owns the intersector; the factory made exactly this one.
    auto& recorder = static_cast<RecordingIntersector&>(tracer.intersector());
    for (std::uint32_t y = 0; y < camera.height; ++y)
        for (std::uint32_t x = 0; x < camera.width; ++x) {
            const std::uint32_t pixel = y * camera.width + x;
            glm::vec4 jitter = gpu::randomFloats(settings.seed, pixel, 0, 0, DIM_CAMERA);
            glm::vec2 film(float(x) + jitter.x, float(y) + jitter.y);
            recorder.beginSample();
            integrate(context, {settings.seed, pixel, 0},
                      {camera.position, gpu::cameraRayDirection(camera, film)});
        }
    return sets;
}

} // namespace vkpt::bench
