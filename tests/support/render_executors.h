// render_executors.h — the adaptor over which a render test is written once and run on each
// executor (as Mitsuba 3's tests run once per variant): a GoogleTest fixture per executor with
// `render(scene, settings[, stats])`, called through the renderers' public entry points, and the
// list of executors for TYPED_TEST_SUITE. Only this file knows how each executor is called.
#pragma once

#include <string>

#include <gtest/gtest.h>

#include "common/render_settings.h"
#include "common/render_stats.h"
#include "gpu_test_support.h"
#include "image/render_output.h"
#include "reference/reference_renderer.h"
#include "reference_render.h"
#include "render/wavefront.h"
#include "scene/camera.h"

namespace vkpt::test {

// The camera both executors see, so that their rays are the same.
inline gpu::Camera testCamera(const LoadedTestScene& loaded, const RenderSettings& settings) {
    return makeGpuCamera(selectCamera(loaded.scene, settings.cameraIndex), settings.width,
                         settings.height);
}

// vkpt-ref: the CPU reference, in-process.
class ReferenceExecutor : public ::testing::Test {
protected:
    RenderOutput render(const LoadedTestScene& loaded, const RenderSettings& settings,
                        RenderStats* statsOut = nullptr) {
        RenderStats stats;
        RenderOutput output =
            renderReference(loaded.prepared, testCamera(loaded, settings), settings, stats);
        if (statsOut) *statsOut = stats;
        return output;
    }
};

// vkpt: the wavefront renderer on the test device (lavapipe), validation on and failing the
// test on any message (GpuTest); a BVH walk cut short by the loop limit fails it too.
class WavefrontExecutor : public GpuTest {
protected:
    RenderOutput render(const LoadedTestScene& loaded, const RenderSettings& settings,
                        RenderStats* statsOut = nullptr) {
        WavefrontResult result =
            renderWavefront(context(), loaded.prepared, testCamera(loaded, settings), settings);
        EXPECT_EQ(result.truncatedTraversals, 0u) << "BVH walks cut short by a loop limit";
        if (statsOut) *statsOut = result.stats;
        return std::move(result.output);
    }
};

// In this order: GoogleTest numbers the instances Suite/0 (vkpt-ref) and Suite/1 (vkpt), which
// tests/render/CMakeLists.txt labels render and image; CTest names them
// Suite.Test<vkpt::test::ReferenceExecutor> and Suite.Test<vkpt::test::WavefrontExecutor>.
using Executors = ::testing::Types<ReferenceExecutor, WavefrontExecutor>;

} // namespace vkpt::test
