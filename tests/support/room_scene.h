// room_scene.h — the benchmarks' large generated scene: a closed room (white walls, one red
// and one green, an emissive quad under the ceiling facing down) with the displaced sphere of
// vkpt::synthetic standing in it and a camera inside looking at the sphere. Built in memory
// for the benches and written as glTF so that every renderer can time itself on the same file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace vkpt::test {

struct RoomMaterial {
    std::string name;
    glm::vec3 albedo{0.0f};   // Lambertian (metallic 0, specular 0)
    glm::vec3 emission{0.0f}; // front face only
};

struct RoomMesh {
    std::string name;
    std::vector<glm::vec3> positions; // three per triangle, counter-clockwise from the front
    std::uint32_t material = 0;
    std::vector<glm::vec2> uvs{}; // one per position in a textured room, else empty
};

struct RoomScene {
    std::vector<RoomMaterial> materials;
    std::vector<RoomMesh> meshes;
    glm::vec3 cameraPosition{0.0f}; // the camera looks down −z, glTF's camera direction
    float cameraYfov = 0.9f;        // radians
    glm::vec3 roomMin{0.0f};        // the walls' inner faces
    glm::vec3 roomMax{0.0f};
    // The sphere's material has a base colour texture (a small checker) read at texture
    // coordinates given per vertex: the room with an array of texture coordinates as long as
    // the geometry, for scenes whose arrays outgrow one binding (docs/gpu.md).
    bool textured = false;

    std::size_t triangleCount() const;
};

// About `triangleCount` triangles: the sphere takes 2·r·2r of them with r rings (the nearest
// r to √(triangleCount/4), at least 2), the room 14 more. 1,000,000 gives r = 500, the
// 500 × 1000 sphere of bvh_build_bench. The same count gives the same scene, bit for bit.
RoomScene makeRoomScene(std::uint32_t triangleCount, bool textured = false);

// The scene as loadGltfScene would read the written file: flat normals, zero-area triangles
// left out. Untextured rooms only (std::logic_error otherwise).
Scene toScene(const RoomScene& room);

// A .gltf with its buffer in a .bin beside it (the same base name).
void writeRoomSceneGltf(const RoomScene& room, const std::string& path);

} // namespace vkpt::test
