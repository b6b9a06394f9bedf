// tangents.cpp — MikkTSpace-style tangent generation over a triangle soup (tangents.h).
#include "scene/tangents.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>

namespace vkpt {
namespace {

// A triangle's own frame (step 1): the unnormalised ∂p/∂u, −∂p/∂v and its handedness
// (0: no texture-coordinate area, no frame).
struct TriangleFrame {
    glm::vec3 tangent{0.0f};
    glm::vec3 bitangent{0.0f};
    float handedness = 0.0f;
};

// For edges e1 = p1 − p0, e2 = p2 − p0 and texture-coordinate edges d1, d2:
// e1 = d1.x·∂p/∂u + d1.y·∂p/∂v and e2 likewise, so ∂p/∂u = (e1·d2.y − e2·d1.y)/det and
// ∂p/∂v = (e2·d1.x − e1·d2.x)/det with det = d1.x·d2.y − d2.x·d1.y (Lengyel, "Mathematics for 3D
// Game Programming and Computer Graphics", §7.8.3).
TriangleFrame triangleFrame(const glm::vec3* p, const glm::vec3* n, const glm::vec2* t) {
    const glm::vec3 e1 = p[1] - p[0];
    const glm::vec3 e2 = p[2] - p[0];
    const glm::vec2 d1 = t[1] - t[0];
    const glm::vec2 d2 = t[2] - t[0];
    const float det = d1.x * d2.y - d2.x * d1.y;
    TriangleFrame frame;
    if (!(std::abs(det) > 0.0f) || !std::isfinite(1.0f / det)) return frame;
    frame.tangent = (e1 * d2.y - e2 * d1.y) / det;
    frame.bitangent = -(e2 * d1.x - e1 * d2.x) / det; // glTF's +Y is towards smaller v
    const float side = glm::dot(glm::cross(n[0] + n[1] + n[2], frame.tangent), frame.bitangent);
    const bool finite =
        std::isfinite(side) && std::isfinite(glm::dot(frame.tangent, frame.tangent));
    frame.handedness = !finite ? 0.0f : side > 0.0f ? 1.0f : side < 0.0f ? -1.0f : 0.0f;
    return frame;
}

glm::vec3 projectOnPlane(const glm::vec3& v, const glm::vec3& n) {
    return v - n * glm::dot(n, v);
}

// v / |v|, or zero when v has no usable length.
glm::vec3 unitOrZero(const glm::vec3& v) {
    const float length = glm::length(v);
    return length > 0.0f && std::isfinite(length) ? v / length : glm::vec3(0.0f);
}

// The angle at corner k of the triangle, between its edges projected on the plane of n.
float cornerAngle(const glm::vec3* p, std::size_t k, const glm::vec3& n) {
    const glm::vec3 a = unitOrZero(projectOnPlane(p[(k + 1) % 3] - p[k], n));
    const glm::vec3 b = unitOrZero(projectOnPlane(p[(k + 2) % 3] - p[k], n));
    return std::acos(glm::clamp(glm::dot(a, b), -1.0f, 1.0f));
}

// Position, normal and texture coordinate bit for bit (−0 as +0): MikkTSpace's vertex identity.
using VertexKey = std::array<std::uint32_t, 8>;

VertexKey vertexKey(const glm::vec3& p, const glm::vec3& n, const glm::vec2& t) {
    const float values[8] = {p.x, p.y, p.z, n.x, n.y, n.z, t.x, t.y};
    VertexKey key{};
    for (std::size_t i = 0; i < 8; ++i) {
        const float canonical = values[i] + 0.0f;
        std::memcpy(&key[i], &canonical, sizeof(float));
    }
    return key;
}

// A vertex's accumulated tangents, one per handedness (index 0: −1, 1: +1).
struct VertexSums {
    std::array<glm::vec3, 2> tangent{glm::vec3(0.0f), glm::vec3(0.0f)};
};

std::size_t sideIndex(float handedness) {
    return handedness < 0.0f ? 0 : 1;
}

// Step 4: the vertex's tangent for a corner of the given handedness (0: a triangle without
// texture-coordinate area, which takes either side's tangent, +1 first).
glm::vec4 finishTangent(const VertexSums& sums, float handedness, const glm::vec3& n) {
    const std::size_t first = handedness == 0.0f ? 1 : sideIndex(handedness);
    for (const std::size_t side : {first, 1 - first}) {
        const glm::vec3 t = unitOrZero(projectOnPlane(sums.tangent[side], n));
        if (t == glm::vec3(0.0f)) continue;
        const float w = handedness != 0.0f ? handedness : (side == 0 ? -1.0f : 1.0f);
        return glm::vec4(t, w);
    }
    return glm::vec4(anyOrthogonal(n), handedness != 0.0f ? handedness : 1.0f);
}

} // namespace

glm::vec3 anyOrthogonal(const glm::vec3& n) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    return glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
}

std::vector<glm::vec4> generateTangents(std::span<const glm::vec3> positions,
                                        std::span<const glm::vec3> normals,
                                        std::span<const glm::vec2> texcoords) {
    const std::size_t corners = positions.size();
    const std::vector<glm::vec2> zeros(texcoords.empty() ? corners : 0, glm::vec2(0.0f));
    const std::span<const glm::vec2> uv = texcoords.empty() ? std::span(zeros) : texcoords;
    std::vector<TriangleFrame> frames(corners / 3);
    std::map<VertexKey, VertexSums> vertices;
    for (std::size_t i = 0; i < frames.size(); ++i) {
        const glm::vec3* p = &positions[3 * i];
        const glm::vec3* n = &normals[3 * i];
        frames[i] = triangleFrame(p, n, &uv[3 * i]);
        for (std::size_t k = 0; k < 3; ++k) {
            VertexSums& sums = vertices[vertexKey(p[k], n[k], uv[3 * i + k])];
            if (frames[i].handedness == 0.0f) continue;
            const glm::vec3 t = unitOrZero(projectOnPlane(frames[i].tangent, n[k]));
            sums.tangent[sideIndex(frames[i].handedness)] += cornerAngle(p, k, n[k]) * t;
        }
    }
    std::vector<glm::vec4> tangents(corners);
    for (std::size_t c = 0; c < 3 * frames.size(); ++c) {
        const VertexSums& sums = vertices.at(vertexKey(positions[c], normals[c], uv[c]));
        tangents[c] = finishTangent(sums, frames[c / 3].handedness, normals[c]);
    }
    return tangents;
}

} // namespace vkpt
