// ray_queries.cpp — uploads rays as queue records, dispatches one traversal kernel, downloads.
#include "ray_queries.h"

#include <algorithm>

#include "gpu/context.h"
#include "gpu/dispatch.h"
#include "gpu/submit.h"
#include "gpu/timestamps.h"
#include "gpu/upload.h"
#include "render/accumulation.h"
#include "render/device_scene.h"
#include "render/wavefront_kernels.h"
#include "render/work_buffers.h"

namespace vkpt {

struct DeviceRayQueries::State {
    State(GpuContext& c, const PreparedScene& scene, std::uint32_t batch)
        : context(c), batchSize(batch), deviceScene(uploadScene(c, scene)),
          buffers(c, batch, 1, 1, {.instances = scene.features.instances}),
          closestKernel(makeWavefrontKernel(c, WavefrontKernel::TraceClosest, scene.features)),
          shadowKernel(makeWavefrontKernel(c, WavefrontKernel::TraceShadow, scene.features)),
          closestSet(bindWavefrontKernel(closestKernel, WavefrontKernel::TraceClosest, table())),
          shadowSet(bindWavefrontKernel(shadowKernel, WavefrontKernel::TraceShadow, table())),
          timer(c, 1, "rayQueryTimer") {
        gpu::FrameParams frame{};
        frame.lightSamples = 1;
        frame.slotCount = batch;
        frame.pixelCount = 1;
        frame.emitterCount = deviceScene.emitterCount;
        frame.environment = deviceScene.environment;
        upload(context, buffers.frameParams, std::span<const gpu::FrameParams>(&frame, 1));
        fillBuffer(context, buffers.queueCounters, 0);
    }

    BufferTable table() const {
        BufferTable t;
        deviceScene.bind(t);
        buffers.bind(t);
        return t;
    }

    // The kernels read the current queue's ray count from queueCounters[COUNTER_RAYS].
    void setRayCount(std::uint32_t count) {
        upload(context, buffers.queueCounters, std::span<const std::uint32_t>(&count, 1),
               COUNTER_RAYS * sizeof(std::uint32_t));
    }

    void run(const Kernel& kernel, const DescriptorSet& set, std::uint32_t count) {
        // Extension rays of an even bounce: queue half 0, and none of the camera's culling of
        // single-sided back faces (shared/camera_culling.h), which bounce 0 would ask for.
        gpu::PassParams params{};
        params.bounce = 2;
        submitAndWait(context, kernel.name(), [&](VkCommandBuffer commands) {
            timer.recordReset(commands);
            timer.recordBegin(commands, kernel.name());
            recordDispatch(commands, kernel, set, {workgroupsFor(count, WORKGROUP_SIZE), 1, 1},
                           pushConstantBytes(params));
            timer.recordEnd(commands);
        });
        for (const KernelTime& time : timer.results())
            kernelNanoseconds += time.nanoseconds;
    }

    DeviceCounters counters() {
        std::vector<std::uint32_t> words =
            download<std::uint32_t>(context, buffers.queueCounters, COUNTER_WORDS);
        DeviceCounters result;
        std::copy(words.begin(), words.end(), result.words);
        return result;
    }

    GpuContext& context;
    std::uint32_t batchSize;
    DeviceScene deviceScene;
    WorkBuffers buffers;
    Kernel closestKernel;
    Kernel shadowKernel;
    DescriptorSet closestSet;
    DescriptorSet shadowSet;
    GpuTimer timer;
    std::uint64_t kernelNanoseconds = 0;
};

DeviceRayQueries::DeviceRayQueries(GpuContext& context, const PreparedScene& scene,
                                   std::uint32_t batchSize)
    : state_(std::make_unique<State>(context, scene, batchSize)) {}

DeviceRayQueries::~DeviceRayQueries() = default;

std::vector<gpu::HitRecord> DeviceRayQueries::closest(std::span<const DeviceRay> rays,
                                                      std::vector<std::uint32_t>* instances) {
    State& s = *state_;
    std::vector<gpu::HitRecord> hits;
    if (instances) instances->clear();
    for (std::size_t first = 0; first < rays.size(); first += s.batchSize) {
        const auto count =
            static_cast<std::uint32_t>(std::min<std::size_t>(s.batchSize, rays.size() - first));
        std::vector<gpu::RayRecord> records;
        for (std::uint32_t i = 0; i < count; ++i) {
            const DeviceRay& r = rays[first + i];
            records.push_back({r.origin, i, r.direction, 0u});
        }
        upload(s.context, s.buffers.rays, std::span<const gpu::RayRecord>(records));
        s.setRayCount(count);
        s.run(s.closestKernel, s.closestSet, count);
        std::vector<gpu::HitRecord> batch =
            download<gpu::HitRecord>(s.context, s.buffers.hits, count);
        hits.insert(hits.end(), batch.begin(), batch.end());
        if (!instances) continue;
        if (!s.buffers.hitInstances) {
            instances->insert(instances->end(), count, NO_INSTANCE);
            continue;
        }
        std::vector<std::uint32_t> found =
            download<std::uint32_t>(s.context, *s.buffers.hitInstances, count);
        instances->insert(instances->end(), found.begin(), found.end());
    }
    return hits;
}

std::vector<bool> DeviceRayQueries::occluded(std::span<const DeviceRay> rays) {
    State& s = *state_;
    std::vector<bool> result;
    for (std::size_t first = 0; first < rays.size(); first += s.batchSize) {
        const auto count =
            static_cast<std::uint32_t>(std::min<std::size_t>(s.batchSize, rays.size() - first));
        std::vector<gpu::ShadowRay> records;
        for (std::uint32_t i = 0; i < count; ++i) {
            const DeviceRay& r = rays[first + i];
            records.push_back(
                {r.origin, SHADOW_SEGMENT, r.direction, r.tMax, glm::vec3(0.0f), 0.0f});
        }
        upload(s.context, s.buffers.shadowRays, std::span<const gpu::ShadowRay>(records));
        s.setRayCount(count);
        s.run(s.shadowKernel, s.shadowSet, count);
        for (const gpu::ShadowRay& r :
             download<gpu::ShadowRay>(s.context, s.buffers.shadowRays, count))
            result.push_back((r.flags & SHADOW_VISIBLE) == 0);
    }
    return result;
}

std::uint32_t DeviceRayQueries::truncatedTraversals() {
    return state_->counters().words[COUNTER_TRUNCATED];
}

std::uint64_t DeviceRayQueries::nodesVisited() {
    return state_->counters().wide(COUNTER_NODES_VISITED);
}

double DeviceRayQueries::kernelSeconds() const {
    return double(state_->kernelNanoseconds) * 1e-9;
}

} // namespace vkpt
