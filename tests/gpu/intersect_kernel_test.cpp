// intersect_kernel_test.cpp — shared/intersect.h on the device against its C++ build.
// Hit/miss decisions must agree exactly, except in a thin band where the answer hangs on the
// last bits: within 1e-5 (relative) of an edge, of tMin or tMax, of a box face, or for grazing
// rays. The band is found in double precision, independently of both float versions; its size
// and the disagreements inside it are counted and bounded. Distances and barycentrics of hits
// outside the band agree within 1e-5 relative: the device may fuse multiply-adds (lavapipe
// goes through LLVM) and Vulkan allows division 2.5 ULP of error.
#include "gpu_test_support.h"
#include "kernel_test_io.h"
#include "shared/intersect.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace vkpt::test::intersect_kernel_test {
namespace {

using gpu::test::IntersectInput;
using gpu::test::IntersectOutput;
using DVec3 = glm::dvec3;

constexpr double kBand = 1e-5;
constexpr double kValueTolerance = 1e-5;
constexpr std::uint32_t kRayCount = 1u << 16;

// Rays aimed at a point of the triangle's plane with barycentrics in [-0.25, 1.25] (about
// half hit) from distances 0.5–3, with boxes placed around the aim point (most rays hit). On
// purpose, some rays are hard cases: aimed exactly at an edge or a vertex, with tMax just
// around the hit, axis-aligned (zero direction components), or starting on a box face.
constexpr bool isEdgeCase(std::size_t i) {
    return i % 17 == 0 || i % 19 == 0 || i % 23 == 0;
}
constexpr bool isTMaxCase(std::size_t i) {
    return i % 7 == 0;
}
constexpr bool isAxisCase(std::size_t i) {
    return i % 11 == 0;
}
constexpr bool isOnFaceCase(std::size_t i) {
    return i % 13 == 0;
}
constexpr bool isHardCase(std::size_t i) {
    return isEdgeCase(i) || isTMaxCase(i) || isAxisCase(i) || isOnFaceCase(i);
}

class InputMaker {
public:
    IntersectInput make(std::size_t i) {
        IntersectInput r{};
        r.v0 = gpu::vec4(point(1.0f), 0);
        r.v1 = gpu::vec4(point(1.0f), 0);
        r.v2 = gpu::vec4(point(1.0f), 0);
        const gpu::vec3 target = aim(r, i);
        const gpu::vec3 direction = isAxisCase(i) ? axis() : direction3();
        const float distance = 0.5f + 2.5f * unit_(random_);
        const float tMax =
            isTMaxCase(i) ? distance * (1.0f + 1e-3f * (unit_(random_) - 0.5f)) : VKPT_FAR;
        r.origin = gpu::vec4(target - distance * direction, i % 5 == 0 ? 1e-3f : 0.0f);
        r.direction = gpu::vec4(direction, tMax);
        const gpu::vec3 centre = target + point(0.6f);
        const gpu::vec3 half =
            gpu::vec3(0.1f) + 0.5f * gpu::vec3(unit_(random_), unit_(random_), unit_(random_));
        r.boxMin = gpu::vec4(centre - half, 0);
        r.boxMax = gpu::vec4(centre + half, 0);
        if (isOnFaceCase(i)) r.origin.x = r.boxMin.x;
        return r;
    }

private:
    gpu::vec3 point(float extent) {
        return extent *
               gpu::vec3(2 * unit_(random_) - 1, 2 * unit_(random_) - 1, 2 * unit_(random_) - 1);
    }
    gpu::vec3 direction3() {
        std::normal_distribution<float> normal;
        return glm::normalize(gpu::vec3(normal(random_), normal(random_), normal(random_)));
    }
    gpu::vec3 axis() {
        gpu::vec3 d(0.0f);
        d[static_cast<int>(random_() % 3)] = random_() % 2 ? 1.0f : -1.0f;
        return d;
    }
    gpu::vec3 aim(const IntersectInput& r, std::size_t i) {
        float b1 = 1.5f * unit_(random_) - 0.25f;
        float b2 = 1.5f * unit_(random_) - 0.25f;
        if (i % 17 == 0) b1 = 0.0f;      // on edge v0-v2
        if (i % 19 == 0) b2 = 1.0f - b1; // on edge v1-v2
        if (i % 23 == 0) b1 = b2 = 0.0f; // at vertex v0
        return gpu::vec3(r.v0) * (1.0f - b1 - b2) + gpu::vec3(r.v1) * b1 + gpu::vec3(r.v2) * b2;
    }

    std::mt19937 random_{99u};
    std::uniform_real_distribution<float> unit_{0.0f, 1.0f};
};

// Exact-enough (double) triangle test: is the ray's decision within the band?
bool triangleInBand(const IntersectInput& r) {
    const DVec3 o(r.origin), d(r.direction), v0(r.v0), e1 = DVec3(r.v1) - v0, e2 = DVec3(r.v2) - v0;
    const DVec3 p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    const double scale = glm::length(e1) * glm::length(e2) * glm::length(d);
    if (std::abs(det) <= kBand * scale) return true; // grazing or degenerate
    const DVec3 s = o - v0, q = glm::cross(s, e1);
    const double u = glm::dot(s, p) / det, v = glm::dot(d, q) / det, t = glm::dot(e2, q) / det;
    const double edge = std::min({std::abs(u), std::abs(v), std::abs(1.0 - u - v)});
    const double tScale = std::max(1.0, std::abs(t));
    const bool nearT =
        std::abs(t - r.origin.w) <= kBand * tScale || std::abs(t - r.direction.w) <= kBand * tScale;
    return edge <= kBand || nearT;
}

// Double slab test with the same zero-direction convention: is entry ≈ exit?
bool boxInBand(const IntersectInput& r) {
    double enter = r.origin.w, exit = r.direction.w;
    for (int a = 0; a < 3; ++a) {
        const double o = r.origin[a], d = r.direction[a];
        if (d == 0.0) {
            if (o < r.boxMin[a] || o > r.boxMax[a]) return false; // a clean miss
            continue;
        }
        const double t0 = (r.boxMin[a] - o) / d, t1 = (r.boxMax[a] - o) / d;
        enter = std::max(enter, std::min(t0, t1));
        exit = std::min(exit, std::max(t0, t1));
    }
    return std::abs(exit - enter) <= kBand * std::max({1.0, std::abs(enter), std::abs(exit)});
}

// Decisions in the band, split by whether the ray was made hard on purpose; a plain random
// ray should almost never land in the band.
struct Tally {
    std::size_t band = 0;
    std::size_t plainInBand = 0;
    std::size_t plain = 0;
    std::size_t bandDisagreements = 0;
    std::size_t hits = 0;
    double worstValueError = 0.0; // relative, over the hits compared

    void compare(double device, double cpu, double scale, const char* what, std::size_t i) {
        const double error = std::abs(device - cpu) / std::max(1.0, scale);
        worstValueError = std::max(worstValueError, error);
        EXPECT_LE(error, kValueTolerance)
            << "ray " << i << " " << what << ": device " << device << ", C++ " << cpu;
    }

    void count(std::size_t i, bool inBand, bool agree) {
        plain += isHardCase(i) ? 0 : 1;
        if (!inBand) return;
        ++band;
        plainInBand += isHardCase(i) ? 0 : 1;
        bandDisagreements += agree ? 0 : 1;
    }

    void report(const char* what) const {
        std::printf("%s: %zu rays, %zu in the band (%zu of %zu plain random rays), %zu "
                    "decisions differ there; %zu hits compared outside it, largest relative "
                    "difference %.3g\n",
                    what, static_cast<std::size_t>(kRayCount), band, plainInBand, plain,
                    bandDisagreements, hits, worstValueError);
        EXPECT_LE(plainInBand, plain / 100) << "the band must be thin for ordinary rays";
        EXPECT_LE(bandDisagreements, kRayCount / 200) << "at most 0.5 % of decisions differ";
    }
};

class IntersectKernel : public GpuTest {
protected:
    static constexpr std::uint32_t kCount = kRayCount;

    void SetUp() override {
        GpuTest::SetUp();
        InputMaker maker;
        for (std::size_t i = 0; i < kCount; ++i)
            inputs_.push_back(maker.make(i));
        const Buffer intersectInputs =
            makeStorageBuffer("intersectInputs", std::span<const IntersectInput>(inputs_));
        const Buffer intersectOutputs =
            makeStorageBuffer("intersectOutputs", kCount * sizeof(IntersectOutput));
        const Kernel kernel = makeKernel("run_intersect", 2, sizeof(std::uint32_t));
        runKernel(kernel, {&intersectInputs, &intersectOutputs}, kCount, pushConstantBytes(kCount));
        outputs_ = download<IntersectOutput>(context(), intersectOutputs, kCount);
    }

    std::vector<IntersectInput> inputs_;
    std::vector<IntersectOutput> outputs_;
};

TEST_F(IntersectKernel, TriangleDecisionsAgreeOutsideEdgeBand) {
    Tally tally;
    for (std::uint32_t i = 0; i < kCount; ++i) {
        const IntersectInput& r = inputs_[i];
        const gpu::TriangleHit cpu =
            gpu::intersectTriangle(gpu::vec3(r.origin), gpu::vec3(r.direction), gpu::vec3(r.v0),
                                   gpu::vec3(r.v1), gpu::vec3(r.v2), r.origin.w, r.direction.w);
        const IntersectOutput& device = outputs_[i];
        const bool agree = (device.hits.x != 0) == cpu.hit;
        const bool inBand = triangleInBand(r);
        tally.count(i, inBand, agree);
        if (!agree && tally.bandDisagreements <= 3) {
            std::printf("ray %u: device %s (t %.9g u %.9g v %.9g), C++ %s (t %.9g u %.9g v %.9g)\n",
                        i, device.hits.x ? "hit" : "miss", device.triangle.x, device.triangle.y,
                        device.triangle.z, cpu.hit ? "hit" : "miss", cpu.t, cpu.u, cpu.v);
        }
        if (inBand) continue;
        ASSERT_TRUE(agree) << "ray " << i << ": device hit " << device.hits.x << ", C++ "
                           << cpu.hit;
        if (!cpu.hit) continue;
        ++tally.hits;
        tally.compare(device.triangle.x, cpu.t, cpu.t, "t", i);
        tally.compare(device.triangle.y, cpu.u, 1.0, "u", i);
        tally.compare(device.triangle.z, cpu.v, 1.0, "v", i);
        const gpu::vec3 n =
            gpu::triangleFaceNormal(gpu::vec3(r.v0), gpu::vec3(r.v1), gpu::vec3(r.v2));
        EXPECT_LE(glm::length(gpu::vec3(device.faceNormal) - n), kValueTolerance * glm::length(n));
    }
    tally.report("triangles");
    EXPECT_GT(tally.hits, kCount / 8) << "too few hits to test anything";
}

TEST_F(IntersectKernel, BoxDecisionsAgreeOutsideFaceBand) {
    Tally tally;
    for (std::uint32_t i = 0; i < kCount; ++i) {
        const IntersectInput& r = inputs_[i];
        const gpu::vec3 inverse = gpu::safeInverseDirection(gpu::vec3(r.direction));
        const float cpu = gpu::intersectBox(gpu::vec3(r.origin), inverse, gpu::vec3(r.boxMin),
                                            gpu::vec3(r.boxMax), r.origin.w, r.direction.w);
        const IntersectOutput& device = outputs_[i];
        for (int a = 0; a < 3; ++a) {
            tally.compare(device.inverseDirection[a], inverse[a], std::abs(inverse[a]),
                          "inverse direction", i);
        }
        const bool cpuHit = cpu < VKPT_FAR;
        const bool agree = (device.hits.y != 0) == cpuHit;
        const bool inBand = boxInBand(r);
        tally.count(i, inBand, agree);
        if (inBand) continue;
        ASSERT_TRUE(agree) << "ray " << i << ": device box hit " << device.hits.y << ", C++ "
                           << cpuHit;
        if (!cpuHit) continue;
        ++tally.hits;
        tally.compare(device.box.x, cpu, std::abs(cpu), "box entry", i);
    }
    tally.report("boxes");
    EXPECT_GT(tally.hits, kCount / 4) << "too few hits to test anything";
}

} // namespace
} // namespace vkpt::test::intersect_kernel_test
