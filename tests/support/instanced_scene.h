// instanced_scene.h — a generated glTF scene that places meshes many times, for the instancing
// tests and benchmarks: a floor, two ceiling lights sharing one emissive mesh (which the loader
// flattens: emitters stay in world space), and a grid of displaced spheres and boxes standing on
// the floor, each turned about y and scaled (some mirrored); the spheres placed half by nodes
// sharing the mesh and half by one EXT_mesh_gpu_instancing node. The same spec gives the same
// file, byte for byte.
#pragma once

#include <cstdint>
#include <string>

namespace vkpt::test {

struct InstancedSceneSpec {
    std::uint32_t columns = 4;   // placements per row
    std::uint32_t rows = 4;      // rows of placements
    std::uint32_t rings = 6;     // each sphere has 4·rings² triangles
    bool gpuInstancing = true;   // half the spheres through EXT_mesh_gpu_instancing
    bool mirrored = true;        // every third placement mirrored in x
    bool separateBuffer = false; // the buffer in a .bin beside the .gltf (large scenes)
};

// Triangles the scene places: floor, lights, spheres and boxes.
std::uint64_t instancedScenePlacedTriangles(const InstancedSceneSpec& spec);

void writeInstancedScene(const InstancedSceneSpec& spec, const std::string& path);

} // namespace vkpt::test
