// scene_memory.h — the device memory each of a scene's buffers holds, reported by --stats so
// that a specialised render and a --general one can be compared.
#pragma once

#include <cstdint>
#include <string>

namespace vkpt {

struct SceneBufferBytes {
    std::string name;        // the buffer's debug name: "bvhNodes", ..., "absentData"
    std::uint64_t bytes = 0; // its allocation, alignment included
};

} // namespace vkpt
