// embree_build.cpp — times Embree's BVH build over a triangle soup (embree_build.h).
#include "embree/embree_build.h"

#include <chrono>
#include <stdexcept>
#include <string>

#include <embree3/rtcore.h>

namespace vkpt::bench {

namespace {

RTCBuildQuality rtcQuality(EmbreeBuildQuality quality) {
    return quality == EmbreeBuildQuality::High ? RTC_BUILD_QUALITY_HIGH : RTC_BUILD_QUALITY_MEDIUM;
}

void throwOnError(RTCDevice device, const char* what) {
    const RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE)
        throw std::runtime_error(std::string("Embree: ") + what + ": error " +
                                 std::to_string(int(error)));
}

} // namespace

double embreeBuildSeconds(std::span<const glm::vec3> positions, EmbreeBuildQuality quality,
                          std::uint32_t threads) {
    const std::string config = threads > 0 ? "threads=" + std::to_string(threads) : "";
    RTCDevice device = rtcNewDevice(config.c_str());
    if (!device) throw std::runtime_error("Embree: cannot create a device");
    // The device's threads start here, outside the timed build, as embree-ref's do.
    const auto start = std::chrono::steady_clock::now();
    RTCScene scene = rtcNewScene(device);
    rtcSetSceneBuildQuality(scene, rtcQuality(quality));
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    const std::size_t count = positions.size() / 3;
    auto* vertices = static_cast<glm::vec3*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(glm::vec3), 3 * count));
    auto* indices = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), count));
    throwOnError(device, "geometry buffers");
    for (std::size_t i = 0; i < 3 * count; ++i) {
        vertices[i] = positions[i];
        indices[i] = std::uint32_t(i);
    }
    rtcSetGeometryBuildQuality(g, rtcQuality(quality));
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(scene);
    const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
    throwOnError(device, "scene build");
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
    return seconds.count();
}

} // namespace vkpt::bench
