// tangents.h — tangent frames for normal mapping, generated the way glTF exporters assume:
// MikkTSpace (Mikkelsen, "Simulation of Wrinkled Surfaces Revisited", MSc thesis, 2008), written
// from its description. docs/scene-model.md lists where it departs from the reference code.
#pragma once

#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace vkpt {

// Per-corner tangents of a triangle soup (corner 3i + k of triangle i), as glTF's TANGENT:
// xyz unit and orthogonal to the corner's normal, w = ±1 with bitangent = w·cross(n, t) pointing
// along the texture's +Y (towards smaller v: glTF puts v = 0 at the image's top).
//
// 1. Each triangle's tangent ∂p/∂u and bitangent −∂p/∂v from its positions and texture
//    coordinates (the solution of the 2×2 system of its edges), and its handedness: the sign of
//    (n × ∂p/∂u)·(−∂p/∂v) for the sum n of its corner normals. Triangles whose texture
//    coordinates have no area have no tangent of their own.
// 2. Corners with equal position, normal and texture coordinate (bit for bit) are one vertex;
//    a vertex is split by handedness, so a mirrored seam keeps two frames.
// 3. At each corner the triangle's tangent, projected on the corner normal's plane and
//    normalised, counts with the triangle's angle at that corner (also measured in that plane).
// 4. The sum is projected on the normal's plane once more and normalised. A corner whose vertex
//    has no tangent of its handedness (only degenerate texture coordinates, or tangents
//    parallel to the normal) takes the other handedness' direction at that vertex if there is
//    one, else any unit vector orthogonal to its normal; w is the triangle's handedness, +1 for
//    a degenerate one: always a valid orthonormal frame.
//
// normals are unit; texcoords may be empty (every corner at (0, 0): step 4's fallback).
std::vector<glm::vec4> generateTangents(std::span<const glm::vec3> positions,
                                        std::span<const glm::vec3> normals,
                                        std::span<const glm::vec2> texcoords);

// A unit vector orthogonal to the unit vector n (Duff et al., "Building an Orthonormal Basis,
// Revisited", JCGT 6(1), 2017).
glm::vec3 anyOrthogonal(const glm::vec3& n);

} // namespace vkpt
