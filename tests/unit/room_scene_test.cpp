// room_scene_test.cpp — the benchmarks' generated room: its size follows the triangle count, it
// is closed around a camera that stands inside, and the glTF file reads back as the same scene.
#include <gtest/gtest.h>

#include "../support/room_scene.h"
#include "../support/test_directory.h"
#include "bvh/bvh_traverse.h"
#include "bvh/synthetic_scenes.h"
#include "scene/gltf_loader.h"

namespace vkpt::room_scene_test {
namespace {

constexpr std::size_t kRoomTriangles = 14; // six walls and the light, two triangles each

TEST(RoomScene, TriangleCountFollowsTheParameter) {
    EXPECT_EQ(test::makeRoomScene(1000000).triangleCount(), 1000000 + kRoomTriangles);
    EXPECT_EQ(test::makeRoomScene(10000).triangleCount(), 10000 + kRoomTriangles);
    EXPECT_EQ(test::makeRoomScene(0).triangleCount(), 16 + kRoomTriangles); // 2 rings at least
}

TEST(RoomScene, SameCountSameScene) {
    test::RoomScene a = test::makeRoomScene(5000), b = test::makeRoomScene(5000);
    ASSERT_EQ(a.meshes.size(), b.meshes.size());
    for (std::size_t i = 0; i < a.meshes.size(); ++i)
        EXPECT_EQ(a.meshes[i].positions, b.meshes[i].positions);
}

// The camera stands inside the room and outside the sphere (radius at most 1.075).
TEST(RoomScene, CameraIsInsideTheRoom) {
    test::RoomScene room = test::makeRoomScene(10000);
    glm::vec3 c = room.cameraPosition;
    EXPECT_TRUE(glm::all(glm::greaterThan(c, room.roomMin)));
    EXPECT_TRUE(glm::all(glm::lessThan(c, room.roomMax)));
    EXPECT_GT(glm::length(c), 1.1f);
}

// Every ray from the camera, and from points inside the room, hits something: the walls leave
// no gap, so no path escapes to the (black) background.
TEST(RoomScene, RoomIsClosed) {
    test::RoomScene room = test::makeRoomScene(10000);
    Scene scene = test::toScene(room);
    BvhTree tree = buildBvh(triangleBounds(scene.positions));
    std::vector<gpu::Triangle> triangles;
    for (std::uint32_t source : tree.primitiveOrder) {
        const glm::vec3* p = &scene.positions[3 * std::size_t(source)];
        triangles.push_back({p[0], 0u, p[1], NO_EMITTER, p[2], source});
    }
    StackBvh stackBvh = makeStackBvh(tree, triangles);
    synthetic::Rng rng(11);
    int escaped = 0;
    for (int i = 0; i < 20000; ++i) {
        glm::vec3 origin = i % 2 ? room.cameraPosition : rng.inBox(room.roomMin, room.roomMax);
        RayQuery ray{origin, rng.unitVector()};
        if (!closestHitStack(stackBvh, ray).hit) ++escaped;
    }
    EXPECT_EQ(escaped, 0);
}

class RoomSceneFile : public test::TestDirectory {
protected:
    RoomSceneFile() : TestDirectory("room_scene") {}
};

// The written .gltf + .bin loads as the in-memory scene: same triangles, materials and camera.
TEST_F(RoomSceneFile, LoadsAsTheSceneInMemory) {
    test::RoomScene room = test::makeRoomScene(2000);
    test::writeRoomSceneGltf(room, path("room.gltf"));
    EXPECT_TRUE(std::filesystem::exists(path("room.bin")));
    Scene loaded = loadGltfScene(path("room.gltf"));
    Scene memory = test::toScene(room);
    EXPECT_EQ(loaded.positions, memory.positions);
    EXPECT_EQ(loaded.materialIndices, memory.materialIndices);
    ASSERT_EQ(loaded.materials.size(), memory.materials.size());
    for (std::size_t i = 0; i < memory.materials.size(); ++i) {
        EXPECT_EQ(loaded.materials[i].baseColor, memory.materials[i].baseColor);
        EXPECT_EQ(loaded.materials[i].emission, memory.materials[i].emission);
        EXPECT_TRUE(loaded.materials[i].isDiffuseOnly());
    }
    ASSERT_EQ(loaded.cameras.size(), 1u);
    EXPECT_EQ(loaded.cameras[0].position, memory.cameras[0].position);
    EXPECT_EQ(loaded.cameras[0].forward, memory.cameras[0].forward);
    EXPECT_FLOAT_EQ(loaded.cameras[0].yfov, memory.cameras[0].yfov);
}

} // namespace
} // namespace vkpt::room_scene_test
