// embree_intersectors.cpp — the prepared scene's triangles handed to Embree 3 in BVH order, so
// that Embree's primID maps straight back to vkpt's primitive index; cut-outs in a geometry of
// their own with filter functions, so that opaque triangles cost Embree no callback.
#include "embree/embree_intersectors.h"

#include <embree3/rtcore.h>

#include <array>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "common/errors.h"
#include "reference/alpha_mask_filter.h"

namespace vkpt::bench {

namespace {

// One Embree geometry: which vkpt primitive each of its primIDs is, and the alpha test when
// its triangles are cut-outs (nullptr otherwise).
struct GeometryInfo {
    std::vector<std::uint32_t> primitives;
    const AlphaMaskFilter* alphaMask = nullptr;
};

// Embree reports errors through a callback; keep the first and throw after the call.
void recordError(void* userPtr, RTCError, const char* message) {
    auto* first = static_cast<std::string*>(userPtr);
    if (first->empty()) *first = message ? message : "unknown error";
}

// Both filters (intersection and occlusion) ask the reference's alpha test. For the
// intersection filter the ray's tfar holds the candidate's distance (Embree 3 API,
// rtcSetGeometryIntersectFilterFunction).
void alphaMaskFilterFunction(const RTCFilterFunctionNArguments* args) {
    const auto* info = static_cast<const GeometryInfo*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        RTCRayN* r = args->ray;
        RTCHitN* h = args->hit;
        const unsigned n = args->N;
        RayQuery ray{{RTCRayN_org_x(r, n, i), RTCRayN_org_y(r, n, i), RTCRayN_org_z(r, n, i)},
                     {RTCRayN_dir_x(r, n, i), RTCRayN_dir_y(r, n, i), RTCRayN_dir_z(r, n, i)}};
        gpu::TriangleHit hit{RTCRayN_tfar(r, n, i), RTCHitN_u(h, n, i), RTCHitN_v(h, n, i), true};
        std::uint32_t primitive = info->primitives[RTCHitN_primID(h, n, i)];
        if (!info->alphaMask->accepts(primitive, NO_INSTANCE, ray, hit)) args->valid[i] = 0;
    }
}

std::size_t countSpheres(const PreparedScene& scene) {
    std::size_t spheres = 0;
    for (const gpu::Triangle& t : scene.triangles)
        spheres += gpu::isSpherePrimitive(t) ? 1 : 0;
    return spheres;
}

} // namespace

struct EmbreeIntersectors::State {
    std::string firstError;
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    AlphaMaskFilter alphaMask;
    std::vector<GeometryInfo> geometries; // indexed by geomID

    explicit State(const PreparedScene& prepared) : alphaMask(prepared) {}

    ~State() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }

    void check(const char* what) const {
        if (!firstError.empty())
            throw std::runtime_error(std::string("Embree: ") + what + ": " + firstError);
    }

    void createDevice(std::uint32_t threads) {
        std::string config = threads > 0 ? "threads=" + std::to_string(threads) : "";
        device = rtcNewDevice(config.c_str());
        if (!device)
            throw std::runtime_error("Embree: cannot create a device (error " +
                                     std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
        rtcSetDeviceErrorFunction(device, recordError, &firstError);
    }

    void addTriangles(const PreparedScene& prepared, GeometryInfo info) {
        if (info.primitives.empty()) return;
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        const std::size_t count = info.primitives.size();
        auto* vertices = static_cast<glm::vec3*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(glm::vec3), 3 * count));
        auto* indices = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), count));
        check("geometry buffers");
        for (std::size_t i = 0; i < count; ++i) {
            const gpu::Triangle& t = prepared.triangles[info.primitives[i]];
            vertices[3 * i] = t.v0;
            vertices[3 * i + 1] = t.v1;
            vertices[3 * i + 2] = t.v2;
            for (std::uint32_t k = 0; k < 3; ++k)
                indices[3 * i + k] = std::uint32_t(3 * i + k);
        }
        rtcSetGeometryBuildQuality(g, RTC_BUILD_QUALITY_HIGH);
        geometries.push_back(std::move(info)); // reserved: the address below stays valid
        GeometryInfo& stored = geometries.back();
        rtcSetGeometryUserData(g, &stored);
        if (stored.alphaMask) {
            rtcSetGeometryIntersectFilterFunction(g, alphaMaskFilterFunction);
            rtcSetGeometryOccludedFilterFunction(g, alphaMaskFilterFunction);
        }
        rtcCommitGeometry(g);
        unsigned id = rtcAttachGeometry(scene, g);
        rtcReleaseGeometry(g);
        check("geometry");
        VKPT_ASSERT(id == geometries.size() - 1, "Embree numbers geometries in attach order");
    }

    // Opaque triangles in one geometry, cut-outs in another; both keep BVH order.
    void build(const PreparedScene& prepared) {
        scene = rtcNewScene(device);
        rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
        GeometryInfo opaque, masked;
        masked.alphaMask = &alphaMask;
        for (std::uint32_t i = 0; i < prepared.triangles.size(); ++i) {
            bool cutOut =
                prepared.features.alphaMask && gpu::isAlphaMaskedPrimitive(prepared.triangles[i]);
            (cutOut ? masked : opaque).primitives.push_back(i);
        }
        geometries.reserve(2); // Embree keeps pointers to the entries
        addTriangles(prepared, std::move(opaque));
        addTriangles(prepared, std::move(masked));
        rtcCommitScene(scene);
        check("scene build");
    }
};

EmbreeIntersectors::EmbreeIntersectors(const PreparedScene& scene, std::uint32_t threads)
    : state_(std::make_unique<State>(scene)) {
    if (std::size_t spheres = countSpheres(scene))
        throw InputError(
            std::to_string(spheres) +
            " spheres (KHR_implicit_shapes): the Embree baseline traces triangles only");
    if (scene.features.instances)
        throw InputError(std::to_string(scene.instances.size()) +
                         " instances: the Embree baseline traces one level of world-space "
                         "triangles (render with --instancing off)");
    state_->createDevice(threads);
    auto start = std::chrono::steady_clock::now();
    state_->build(scene);
    buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

EmbreeIntersectors::~EmbreeIntersectors() = default;

namespace {

// Embree's ray for a query: t in (tMin, tMax], every mask bit, no motion blur.
RTCRay embreeRay(const RayQuery& q) {
    RTCRay r{};
    r.org_x = q.origin.x;
    r.org_y = q.origin.y;
    r.org_z = q.origin.z;
    r.tnear = q.tMin;
    r.dir_x = q.direction.x;
    r.dir_y = q.direction.y;
    r.dir_z = q.direction.z;
    r.tfar = q.tMax;
    r.mask = ~0u;
    return r;
}

} // namespace

ClosestHit EmbreeIntersectors::closestHit(const RayQuery& query) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit r{};
    r.ray = embreeRay(query);
    r.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    r.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(state_->scene, &context, &r);
    if (r.hit.geomID == RTC_INVALID_GEOMETRY_ID) return {};
    const std::uint32_t primitive = state_->geometries[r.hit.geomID].primitives[r.hit.primID];
    return {r.ray.tfar, r.hit.u, r.hit.v, primitive, true};
}

bool EmbreeIntersectors::anyHit(const RayQuery& query) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay r = embreeRay(query);
    rtcOccluded1(state_->scene, &context, &r);
    return r.tfar < 0.0f; // Embree sets tfar to −∞ when something is found
}

namespace {

class EmbreeIntersector final : public SceneIntersector {
public:
    explicit EmbreeIntersector(const EmbreeIntersectors& embree) : embree_(embree) {}

    ClosestHit closestHit(const glm::vec3& origin, const glm::vec3& direction,
                          float tMin) override {
        // Embree's tnear is inclusive, the interface's tMin exclusive.
        const float tNear = tMin > 0.0f ? std::nextafter(tMin, VKPT_FAR) : tMin;
        return embree_.closestHit({origin, direction, tNear, VKPT_FAR});
    }
    bool occluded(const glm::vec3& origin, const glm::vec3& direction, float tMax) override {
        return embree_.anyHit({origin, direction, 0.0f, tMax});
    }

private:
    const EmbreeIntersectors& embree_;
};

} // namespace

std::unique_ptr<SceneIntersector> EmbreeIntersectors::makeIntersector() const {
    return std::make_unique<EmbreeIntersector>(*this);
}

std::string EmbreeIntersectors::version() {
    return RTC_VERSION_STRING;
}

} // namespace vkpt::bench
