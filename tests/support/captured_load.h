// captured_load.h — loads a glTF scene with its stderr captured, so that tests can read the
// loader's notes (ignored extensions, unused textures) instead of letting them reach the log.
#pragma once

#include <string>

#include <gtest/gtest.h>

#include "scene/gltf_loader.h"

namespace vkpt::test {

// Loads `path`; its stderr goes into `notes` when given. A throwing load releases the capture
// before the exception leaves.
inline Scene loadCapturingNotes(const std::string& path, std::string* notes = nullptr) {
    testing::internal::CaptureStderr();
    Scene scene;
    try {
        scene = loadGltfScene(path);
    } catch (...) {
        testing::internal::GetCapturedStderr();
        throw;
    }
    const std::string captured = testing::internal::GetCapturedStderr();
    if (notes != nullptr) *notes = captured;
    return scene;
}

} // namespace vkpt::test
