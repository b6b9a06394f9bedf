// self_intersection_test.cpp — a ray spawned from a surface with the shared offset
// (shared/ray_offset.h: 64 float epsilons of the triangle's coordinate scale along its normal)
// never re-hits the triangle it leaves: 10^6 random triangles of every size and position, each
// with a random point and a random outgoing direction down to grazing angles — in C++ as
// vkpt-ref computes it, and on the device as shade_hits does (kernels/spawn_rays.comp).
#include <gtest/gtest.h>

#include <cmath>

#include "../gpu/gpu_test_support.h"
#include "shared/intersect.h"
#include "shared/ray_offset.h"
#include "shared/rng.h"
#include "shared/sampling.h"
#include "spawn_io.h"
#include "vkpt_extremes_kernels.h"

namespace vkpt::self_intersection_test {
namespace {

float logUniform(float u, float lo, float hi) {
    return lo * std::pow(hi / lo, u);
}

glm::vec3 randomUnit(glm::vec2 u) {
    float z = 1.0f - 2.0f * u.x, r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    float phi = 2.0f * VKPT_PI * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

struct SpawnCase {
    glm::vec3 v0, v1, v2;
    glm::vec3 point;     // on the triangle, by barycentric interpolation as the renderers do
    glm::vec3 normal;    // unit geometric normal on the side the ray leaves towards
    glm::vec3 direction; // into that side, from grazing (cos 1e-4) to perpendicular
    glm::vec3 bary;      // of the point
    float side;          // +1: the front, −1: the back
};

// Triangles centred up to 1e6 from the origin, from 1e-4 to 1e4 in size but never smaller than
// 1e-4 of their distance (about 800 float steps there): a smaller one collapses onto the float
// grid and is no longer a triangle.
SpawnCase makeCase(std::uint32_t i) {
    glm::vec4 a = gpu::randomFloats(23, i, 0, 0, 10), b = gpu::randomFloats(23, i, 0, 0, 11);
    glm::vec4 c = gpu::randomFloats(23, i, 0, 0, 12), d = gpu::randomFloats(23, i, 0, 0, 13);
    float distance = a.y < 0.2f ? 0.0f : logUniform(a.z, 1e-3f, 1e6f);
    float size = logUniform(a.x, std::max(1e-4f, 1e-4f * distance), 1e4f);
    glm::vec3 centre = distance * randomUnit({a.w, b.x});
    SpawnCase s;
    s.v0 = centre + size * randomUnit({b.y, b.z});
    s.v1 = centre + size * randomUnit({b.w, c.x});
    s.v2 = centre + size * randomUnit({c.y, c.z});
    glm::vec3 bary = gpu::sampleTriangleBarycentrics({c.w, d.x});
    s.point = bary.x * s.v0 + bary.y * s.v1 + bary.z * s.v2;
    s.side = d.y < 0.5f ? 1.0f : -1.0f;
    s.bary = bary;
    s.normal = gpu::unitFaceNormal(s.v0, s.v1, s.v2) * s.side;
    float cosTheta = logUniform(d.z, 1e-4f, 1.0f);
    float phi = 2.0f * VKPT_PI * d.w;
    float sinTheta = std::sqrt(1.0f - cosTheta * cosTheta);
    glm::vec3 local(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
    s.direction = gpu::basisToWorld(gpu::makeBasis(s.normal), local);
    return s;
}

// Exact side test in double against the triangle's plane.
bool onNormalSide(const SpawnCase& s, glm::vec3 origin) {
    glm::dvec3 n =
        glm::cross(glm::dvec3(s.v1) - glm::dvec3(s.v0), glm::dvec3(s.v2) - glm::dvec3(s.v0));
    if (glm::dot(n, glm::dvec3(s.normal)) < 0.0) n = -n;
    return glm::dot(n, glm::dvec3(origin) - glm::dvec3(s.v0)) > 0.0;
}

TEST(SelfIntersection, SpawnedRaysNeverReHitTheirOwnTriangle) {
    std::uint64_t tested = 0, reHits = 0, degenerate = 0;
    for (std::uint32_t i = 0; i < 1000000; ++i) {
        SpawnCase s = makeCase(i);
        if (s.normal == glm::vec3(0.0f) || glm::dot(s.direction, s.normal) <= 0.0f) {
            ++degenerate; // a needle so thin that its normal is not representable
            continue;
        }
        glm::vec3 origin = gpu::offsetFromSurface(s.point, s.normal,
                                                  gpu::triangleCoordinateScale(s.v0, s.v1, s.v2));
        ++tested;
        reHits += gpu::intersectTriangle(origin, s.direction, s.v0, s.v1, s.v2, 0.0f, VKPT_FAR).hit;
    }
    EXPECT_EQ(reHits, 0u) << "of " << tested << " spawned rays";
    EXPECT_LT(degenerate, 100u) << "random triangles should rarely be needles";
}

// The offset point must stay on the chosen side of the plane, however far from the origin.
TEST(SelfIntersection, OffsetOriginLiesOnTheNormalSide) {
    std::uint64_t wrongSide = 0;
    for (std::uint32_t i = 0; i < 1000000; ++i) {
        SpawnCase s = makeCase(i);
        if (s.normal == glm::vec3(0.0f)) continue;
        glm::vec3 origin = gpu::offsetFromSurface(s.point, s.normal,
                                                  gpu::triangleCoordinateScale(s.v0, s.v1, s.v2));
        wrongSide += !onNormalSide(s, origin);
    }
    EXPECT_EQ(wrongSide, 0u);
}

// The same 10^6 cases spawned on the device, in batches of 2^18.
class SelfIntersectionOnTheDevice : public test::GpuTest {};

TEST_F(SelfIntersectionOnTheDevice, SpawnedRaysNeverReHitTheirOwnTriangle) {
    const extremes_kernels::EmbeddedKernel& embedded = extremes_kernels::findKernel("spawn_rays");
    KernelDesc desc;
    desc.name = std::string(embedded.name);
    desc.spirv = embedded.spirv;
    desc.bindings = {{0, DescriptorKind::StorageBuffer}, {1, DescriptorKind::StorageBuffer}};
    desc.pushConstantSize = sizeof(std::uint32_t);
    const Kernel kernel(context(), std::move(desc));
    constexpr std::uint32_t kBatch = 1u << 18;
    std::uint64_t tested = 0, reHits = 0, wrongSide = 0;
    for (std::uint32_t first = 0; first < 1000000; first += kBatch) {
        const std::uint32_t count = std::min(kBatch, 1000000 - first);
        std::vector<SpawnCase> cases;
        std::vector<gpu::test::SpawnInput> inputs;
        for (std::uint32_t i = first; i < first + count; ++i) {
            SpawnCase s = makeCase(i);
            if (s.normal == glm::vec3(0.0f) || glm::dot(s.direction, s.normal) <= 0.0f) continue;
            cases.push_back(s);
            inputs.push_back({glm::vec4(s.v0, 0.0f), glm::vec4(s.v1, 0.0f), glm::vec4(s.v2, 0.0f),
                              glm::vec4(s.bary, s.side), glm::vec4(s.direction, 0.0f)});
        }
        const auto n = std::uint32_t(inputs.size());
        const Buffer in =
            makeStorageBuffer("spawnInputs", std::span<const gpu::test::SpawnInput>(inputs));
        const Buffer out = makeStorageBuffer("spawnOutputs", n * sizeof(gpu::test::SpawnOutput));
        runKernel(kernel, {&in, &out}, n, std::as_bytes(std::span<const std::uint32_t>(&n, 1)));
        const std::vector<gpu::test::SpawnOutput> outputs =
            download<gpu::test::SpawnOutput>(context(), out, n);
        for (std::uint32_t i = 0; i < n; ++i) {
            ++tested;
            reHits += outputs[i].origin.w != 0.0f;
            wrongSide += !onNormalSide(cases[i], glm::vec3(outputs[i].origin));
        }
    }
    EXPECT_EQ(reHits, 0u) << "of " << tested << " rays spawned on the device";
    EXPECT_EQ(wrongSide, 0u);
}

} // namespace
} // namespace vkpt::self_intersection_test
