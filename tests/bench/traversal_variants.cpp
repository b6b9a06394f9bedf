// traversal_variants.cpp — each variant traces a ray set its own way: CPU walks on a fixed
// number of threads taking chunks of rays from a shared counter, Embree the same way, the
// device kernels through DeviceRayQueries in batches.
#include "traversal_variants.h"

#include <atomic>
#include <cstdio>
#include <mutex>
#include <thread>

#include "../support/ray_queries.h"
#include "bvh/bvh_traverse.h"
#include "bvh/wide_traverse.h"
#include "reference/alpha_mask_filter.h"
#ifdef VKPT_HAVE_EMBREE
#include "embree/embree_intersectors.h"
#endif

namespace vkpt::bench {

namespace {

// Bytes per counted node and per primitive test of each layout: the one place that says so.
// The stack walk counts box tests, two per StackBvhPair it reads; the device's wide walk (and
// its CPU run) counts node visits, one gpu::WideBvhNode each (eight child boxes). Both read
// gpu::Triangle records.
constexpr WalkLayout kStackWalkLayout{sizeof(StackBvhPair) / 2, sizeof(gpu::Triangle)};
constexpr WalkLayout kWideLayout{sizeof(gpu::WideBvhNode), sizeof(gpu::Triangle)};

constexpr std::uint32_t kChunk = 256; // rays a thread takes at a time

// Runs traceOne(query, counters) -> TraceOutcome over the set on `threads` threads.
template <typename TraceOne>
TraversalCounters traceInParallel(const RaySet& set, std::vector<TraceOutcome>& outcomes,
                                  std::uint32_t threads, const TraceOne& traceOne) {
    outcomes.resize(set.rays.size());
    std::atomic<std::size_t> next{0};
    std::mutex mutex;
    TraversalCounters total;
    auto worker = [&] {
        TraversalCounters counters;
        for (std::size_t first = next.fetch_add(kChunk); first < set.rays.size();
             first = next.fetch_add(kChunk)) {
            std::size_t last = std::min(set.rays.size(), first + kChunk);
            for (std::size_t i = first; i < last; ++i)
                outcomes[i] = traceOne(set.rays[i], counters);
        }
        std::lock_guard<std::mutex> lock(mutex);
        total.nodesVisited += counters.nodesVisited;
        total.triangleTests += counters.triangleTests;
    };
    std::vector<std::thread> pool;
    for (std::uint32_t t = 0; t < threads; ++t)
        pool.emplace_back(worker);
    for (std::thread& thread : pool)
        thread.join();
    return total;
}

TraceOutcome outcomeOf(const ClosestHit& hit) {
    return {hit.t, hit.hit};
}

// A CPU walk of vkpt's own (closest and any-hit function pair over its layout), with the
// reference's alpha test where the scene has cut-outs.
template <typename Closest, typename Any> class CpuWalkVariant final : public TraversalVariant {
public:
    CpuWalkVariant(VariantInfo info, const PreparedScene& scene, std::uint32_t threads,
                   Closest closest, Any any)
        : TraversalVariant(std::move(info)), alphaMask_(scene),
          filter_(scene.features.alphaMask ? &alphaMask_ : nullptr), threads_(threads),
          closest_(closest), any_(any) {}

    TraceWork trace(const RaySet& set, std::vector<TraceOutcome>& outcomes) override {
        TraversalCounters counters = traceInParallel(
            set, outcomes, threads_, [&](RayQuery ray, TraversalCounters& c) -> TraceOutcome {
                ray.filter = filter_;
                if (set.anyHit) return {0.0f, any_(ray, c)};
                return outcomeOf(closest_(ray, c));
            });
        return {counters.nodesVisited, counters.triangleTests, std::nullopt};
    }

private:
    AlphaMaskFilter alphaMask_;
    const HitFilter* filter_;
    std::uint32_t threads_;
    Closest closest_;
    Any any_;
};

template <typename Closest, typename Any>
std::unique_ptr<TraversalVariant> makeCpuWalk(VariantInfo info, const PreparedScene& scene,
                                              std::uint32_t threads, Closest closest, Any any) {
    return std::make_unique<CpuWalkVariant<Closest, Any>>(std::move(info), scene, threads, closest,
                                                          any);
}

// The walks share the tree laid out for them, which the variant's lambdas own.
std::unique_ptr<TraversalVariant> stackWalk(const PreparedScene& scene, std::uint32_t threads) {
    VariantInfo info{"vkpt-ref ordered stack walk, " + std::to_string(threads) + " threads",
                     kStackWalkLayout, false, true};
    auto bvh = std::make_shared<const StackBvh>(makeStackBvh(scene.tree, scene.triangles));
    return makeCpuWalk(
        std::move(info), scene, threads,
        [&scene, bvh](const RayQuery& r, TraversalCounters& c) {
            return closestHitStack(*bvh, r, &c);
        },
        [&scene, bvh](const RayQuery& r, TraversalCounters& c) {
            return anyHitStack(*bvh, r, &c);
        });
}

// shared/wide_bvh.h, the kernels' own code, run on the CPU (wide_traverse.h).
std::unique_ptr<TraversalVariant> wideWalkOnCpu(const PreparedScene& scene, std::uint32_t threads) {
    VariantInfo info{"device walk on the CPU (8-wide), " + std::to_string(threads) + " threads",
                     kWideLayout};
    return makeCpuWalk(
        std::move(info), scene, threads,
        [&scene](const RayQuery& r, TraversalCounters& c) {
            return closestHitWide(scene.nodes, scene.triangles, r, &c);
        },
        [&scene](const RayQuery& r, TraversalCounters& c) {
            return anyHitWide(scene.nodes, scene.triangles, r, &c);
        });
}

// trace_closest and trace_shadow on the Vulkan device, rays uploaded and answers read back in
// batches (included in the time: on lavapipe that is a memory copy). The kernels count nodes
// (COUNTER_NODES), not triangle tests.
class DeviceKernelVariant final : public TraversalVariant {
public:
    DeviceKernelVariant(std::unique_ptr<GpuContext> context, const PreparedScene& scene,
                        std::uint32_t batch)
        : TraversalVariant({"device kernels on " + context->deviceInfo().name, kWideLayout}),
          context_(std::move(context)), queries_(*context_, scene, batchFor(*context_, batch)) {}

    TraceWork trace(const RaySet& set, std::vector<TraceOutcome>& outcomes) override {
        std::vector<DeviceRay> rays;
        rays.reserve(set.rays.size());
        for (const RayQuery& r : set.rays)
            rays.push_back({r.origin, r.direction, r.tMax});
        std::uint64_t nodesBefore = queries_.nodesVisited();
        const double kernelBefore = queries_.kernelSeconds();
        outcomes.assign(set.rays.size(), {});
        if (set.anyHit) {
            std::vector<bool> blocked = queries_.occluded(rays);
            for (std::size_t i = 0; i < rays.size(); ++i)
                outcomes[i].hit = blocked[i];
        } else {
            std::vector<gpu::HitRecord> hits = queries_.closest(rays);
            for (std::size_t i = 0; i < rays.size(); ++i)
                outcomes[i] = {hits[i].t, hits[i].triangle != NO_HIT};
        }
        return {queries_.nodesVisited() - nodesBefore, std::nullopt,
                queries_.kernelSeconds() - kernelBefore};
    }

private:
    static std::uint32_t batchFor(const GpuContext& context, std::uint32_t requested) {
        if (requested > 0)
            return (requested + WORKGROUP_SIZE - 1) / WORKGROUP_SIZE * WORKGROUP_SIZE;
        return context.deviceInfo().type == VK_PHYSICAL_DEVICE_TYPE_CPU ? 1u << 14 : 1u << 22;
    }

    std::unique_ptr<GpuContext> context_;
    DeviceRayQueries queries_;
};

std::unique_ptr<TraversalVariant> deviceKernels(const PreparedScene& scene,
                                                const VariantOptions& options) {
    try {
        return std::make_unique<DeviceKernelVariant>(std::make_unique<GpuContext>(options.gpu),
                                                     scene, options.deviceBatch);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "traversal_bench: device kernels left out: %s\n", error.what());
        return nullptr;
    }
}

#ifdef VKPT_HAVE_EMBREE
// Embree's rtcIntersect1 / rtcOccluded1 on the same threads; it counts no work.
class EmbreeVariant final : public TraversalVariant {
public:
    EmbreeVariant(const PreparedScene& scene, std::uint32_t threads)
        : TraversalVariant({"Embree " + EmbreeIntersectors::version() + " (BVH high), " +
                                std::to_string(threads) + " threads",
                            {},
                            true,
                            false}),
          embree_(scene, threads), threads_(threads) {}

    TraceWork trace(const RaySet& set, std::vector<TraceOutcome>& outcomes) override {
        traceInParallel(set, outcomes, threads_,
                        [&](const RayQuery& r, TraversalCounters&) -> TraceOutcome {
                            if (set.anyHit) return {0.0f, embree_.anyHit(r)};
                            return outcomeOf(embree_.closestHit(r));
                        });
        return {};
    }

    double buildSeconds() const { return embree_.buildSeconds(); }

private:
    EmbreeIntersectors embree_;
    std::uint32_t threads_;
};
#endif

} // namespace

std::vector<std::unique_ptr<TraversalVariant>>
makeTraversalVariants(const PreparedScene& scene, const VariantOptions& options) {
    std::vector<std::unique_ptr<TraversalVariant>> variants;
#ifdef VKPT_HAVE_EMBREE
    auto embree = std::make_unique<EmbreeVariant>(scene, options.threads);
    std::printf("  Embree BVH build (RTC_BUILD_QUALITY_HIGH, %u threads): %.3f s\n",
                options.threads, embree->buildSeconds());
    variants.push_back(std::move(embree));
#else
    std::fprintf(stderr, "traversal_bench: built without Embree: no baseline, no ratios\n");
#endif
    variants.push_back(stackWalk(scene, options.threads));
    variants.push_back(wideWalkOnCpu(scene, options.threads));
    if (options.device)
        if (auto device = deviceKernels(scene, options)) variants.push_back(std::move(device));
    return variants;
}

} // namespace vkpt::bench
