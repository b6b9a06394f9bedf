// ray_triangle_test.h — intersect.h's watertight triangle test for one ray against the many
// triangles of a CPU walk. gpu::intersectTriangleWatertight permutes each vertex into the ray's
// sheared axis order (kx, ky, kz) with run-time indices, which glm compiles to a switch per
// component. Here the permutation is applied as the vertices are read, and the shared function
// runs on the permuted ray and vertices with the identity order, which the compiler folds: the
// same float operations on the same values, so the same hits, t, u and v bit for bit.
#pragma once

#include <cstring>

#include <glm/glm.hpp>

#include "shared/intersect.h"

namespace vkpt {

class RayTriangleTest {
public:
    RayTriangleTest(const glm::vec3& origin, const glm::vec3& direction)
        : sheared_(gpu::shearRay(direction)), origin_(permute(origin)) {}

    // gpu::intersectTriangleWatertight(origin, shearRay(direction), v0, v1, v2, tMin, tMax).
    gpu::TriangleHit intersect(const glm::vec3& v0, const glm::vec3& v1, const glm::vec3& v2,
                               float tMin, float tMax) const {
        // (v − origin)[k] is v[k] − origin[k] whichever order the components come in.
        const gpu::ShearedRay identityOrder{0, 1, 2, sheared_.shear};
        return gpu::intersectTriangleWatertight(origin_, identityOrder, permute(v0), permute(v1),
                                                permute(v2), tMin, tMax);
    }

private:
    glm::vec3 permute(const glm::vec3& v) const {
        float c[3];
        std::memcpy(c, &v, sizeof c);
        return {c[sheared_.kx], c[sheared_.ky], c[sheared_.kz]};
    }

    gpu::ShearedRay sheared_;
    glm::vec3 origin_; // in the order (kx, ky, kz)
};

} // namespace vkpt
