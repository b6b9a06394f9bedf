// room_scene.cpp — the generated room with the displaced sphere, in memory and as glTF.
#include "room_scene.h"

#include <cmath>
#include <numeric>
#include <stdexcept>

#include "bvh/synthetic_scenes.h"
#include "gltf_writer.h"
#include "image/image_file.h"
#include "scene_builder.h"

namespace vkpt::test {

namespace {

// The room's inside: the sphere (radius 0.925–1.075 around the origin) stands on the floor.
constexpr glm::vec3 kRoomMin{-2.5f, -1.1f, -2.5f};
constexpr glm::vec3 kRoomMax{2.5f, 2.4f, 3.2f};
// The light hangs just below the ceiling, so that the two are not coplanar.
constexpr float kLightHalfWidth = 0.75f;
constexpr float kLightDrop = 0.01f;
constexpr glm::vec3 kLightEmission{10.0f};

// Two triangles for the quad a b c d, counter-clockwise seen from its front.
void appendQuad(std::vector<glm::vec3>& out, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    out.insert(out.end(), {a, b, c, a, c, d});
}

// One wall of the room: the quad a b c d, counter-clockwise seen from inside the room.
RoomMesh wall(const std::string& name, std::uint32_t material, glm::vec3 a, glm::vec3 b,
              glm::vec3 c, glm::vec3 d) {
    RoomMesh mesh{name, {}, material};
    appendQuad(mesh.positions, a, b, c, d);
    return mesh;
}

std::uint32_t sphereRings(std::uint32_t triangleCount) {
    double rings = std::round(std::sqrt(double(triangleCount) / 4.0));
    return std::max(2u, std::uint32_t(rings));
}

void addWalls(RoomScene& room, std::uint32_t white, std::uint32_t red, std::uint32_t green) {
    const glm::vec3 lo = kRoomMin, hi = kRoomMax;
    auto p = [&](int x, int y, int z) {
        return glm::vec3(x ? hi.x : lo.x, y ? hi.y : lo.y, z ? hi.z : lo.z);
    };
    room.meshes.push_back(wall("floor", white, p(0, 0, 0), p(0, 0, 1), p(1, 0, 1), p(1, 0, 0)));
    room.meshes.push_back(wall("ceiling", white, p(0, 1, 0), p(1, 1, 0), p(1, 1, 1), p(0, 1, 1)));
    room.meshes.push_back(wall("back", white, p(0, 0, 0), p(1, 0, 0), p(1, 1, 0), p(0, 1, 0)));
    room.meshes.push_back(wall("front", white, p(0, 0, 1), p(0, 1, 1), p(1, 1, 1), p(1, 0, 1)));
    room.meshes.push_back(wall("left", red, p(0, 0, 0), p(0, 1, 0), p(0, 1, 1), p(0, 0, 1)));
    room.meshes.push_back(wall("right", green, p(1, 0, 0), p(1, 0, 1), p(1, 1, 1), p(1, 1, 0)));
}

void addLight(RoomScene& room, std::uint32_t material) {
    const float y = kRoomMax.y - kLightDrop, h = kLightHalfWidth;
    room.meshes.push_back(wall("light", material, {-h, y, -h}, {h, y, -h}, {h, y, h}, {-h, y, h}));
}

} // namespace

std::size_t RoomScene::triangleCount() const {
    return std::accumulate(
        meshes.begin(), meshes.end(), std::size_t(0),
        [](std::size_t n, const RoomMesh& m) { return n + m.positions.size() / 3; });
}

namespace {

// Texture coordinates for the sphere's vertices: its x and y, so that the checker (repeated)
// shows a few squares across the sphere.
std::vector<glm::vec2> planarUvs(const std::vector<glm::vec3>& positions) {
    std::vector<glm::vec2> uvs;
    uvs.reserve(positions.size());
    for (const glm::vec3& p : positions)
        uvs.emplace_back(2.0f * p.x, 2.0f * p.y);
    return uvs;
}

// An 8 × 8 checker of light and dark grey, as PNG bytes.
std::vector<unsigned char> checkerPng() {
    constexpr std::uint32_t kSize = 8;
    std::vector<std::uint8_t> rgb;
    for (std::uint32_t y = 0; y < kSize; ++y)
        for (std::uint32_t x = 0; x < kSize; ++x)
            rgb.insert(rgb.end(), 3, ((x + y) % 2 == 0) ? std::uint8_t(230) : std::uint8_t(90));
    return detail::encodePngRgb8(kSize, kSize, rgb);
}

} // namespace

RoomScene makeRoomScene(std::uint32_t triangleCount, bool textured) {
    RoomScene room;
    room.materials = {{"white", glm::vec3(0.73f), glm::vec3(0.0f)},
                      {"red", {0.63f, 0.065f, 0.05f}, glm::vec3(0.0f)},
                      {"green", {0.14f, 0.45f, 0.091f}, glm::vec3(0.0f)},
                      {"sphere", glm::vec3(0.8f), glm::vec3(0.0f)},
                      {"light", glm::vec3(0.78f), kLightEmission}};
    addWalls(room, 0, 1, 2);
    addLight(room, 4);
    const std::uint32_t rings = sphereRings(triangleCount);
    room.meshes.push_back({"displaced sphere", synthetic::displacedSphere(rings, 2 * rings), 3});
    room.textured = textured;
    if (textured) room.meshes.back().uvs = planarUvs(room.meshes.back().positions);
    room.cameraPosition = {0.0f, 0.3f, 2.9f};
    room.cameraYfov = 0.9f;
    room.roomMin = kRoomMin;
    room.roomMax = kRoomMax;
    return room;
}

Scene toScene(const RoomScene& room) {
    if (room.textured) throw std::logic_error("toScene: a textured room is only written as glTF");
    Scene scene;
    scene.sourcePath = "generated room";
    for (const RoomMaterial& m : room.materials) {
        std::uint32_t index = addMaterial(scene, m.albedo, m.emission);
        scene.materials[index].name = m.name;
    }
    for (const RoomMesh& mesh : room.meshes)
        for (std::size_t i = 0; i < mesh.positions.size(); i += 3) {
            const glm::vec3 &a = mesh.positions[i], &b = mesh.positions[i + 1],
                            &c = mesh.positions[i + 2];
            if (glm::cross(b - a, c - a) == glm::vec3(0.0f)) continue; // as the loader does
            addTriangle(scene, a, b, c, mesh.material);
        }
    SceneCamera camera;
    camera.name = "room camera";
    camera.position = room.cameraPosition;
    camera.yfov = room.cameraYfov;
    scene.cameras.push_back(camera);
    return scene;
}

void writeRoomSceneGltf(const RoomScene& room, const std::string& path) {
    GltfWriter writer;
    const int checker = room.textured ? writer.addPngTexture(checkerPng()) : -1;
    for (const RoomMaterial& m : room.materials)
        writer.addMaterial(m.albedo, m.emission, m.name == "sphere" ? checker : -1);
    for (const RoomMesh& mesh : room.meshes) {
        MeshData data;
        data.positions = mesh.positions;
        data.uvs = mesh.uvs;
        data.indices.resize(mesh.positions.size());
        std::iota(data.indices.begin(), data.indices.end(), 0u);
        data.material = int(mesh.material);
        writer.addMesh(data);
    }
    writer.addCamera(room.cameraPosition, double(room.cameraYfov));
    writer.write(path, GltfWriter::Buffers::Separate);
}

} // namespace vkpt::test
