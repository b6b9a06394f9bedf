// interrupt_test.cpp — Ctrl-C during a long vkpt render: the current pass finishes, the image
// so far is written, and the exit code is 130 (128 + SIGINT), as the command line promises.
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <string>

#include "../support/child_process.h"
#include "../support/scratch_directory.h"
#include "image/image_io.h"

namespace vkpt::interrupt_test {
namespace {

using test::Child;
using test::readUntil;
using test::spawnWithStderrPipe;

TEST(VkptInterrupt, CtrlCFinishesThePassWritesTheImageAndExits130) {
    const std::string output = test::scratchPath("interrupted.pfm");
    std::filesystem::remove(output);
    // A budget no test waits for: only the interrupt ends this render.
    Child child = spawnWithStderrPipe({VKPT_EXECUTABLE, "--spp", "1000000", "--res", "8", "8", "-o",
                                       output, VKPT_SCENES_DIR "/cornell-box.gltf"});
    ASSERT_GT(child.pid, 0) << "cannot start " << VKPT_EXECUTABLE;
    std::string text;
    // vkpt names its device once the handler is installed, just before the first pass.
    bool started = readUntil(child.stderrFd, ": device ", text);
    if (started) kill(child.pid, SIGINT);
    readUntil(child.stderrFd, "\x01", text); // drain to the end
    close(child.stderrFd);
    int status = 0;
    waitpid(child.pid, &status, 0);
    ASSERT_TRUE(started) << text;
    ASSERT_TRUE(WIFEXITED(status)) << "ended by a signal: " << text;
    EXPECT_EQ(WEXITSTATUS(status), 130) << text;
    ASSERT_TRUE(std::filesystem::exists(output)) << text;
    Image image = readPfm(output);
    float total = 0.0f;
    for (const glm::vec3& p : image.pixels)
        total += p.x + p.y + p.z;
    EXPECT_GT(total, 0.0f) << "the image holds the passes done";
}

} // namespace
} // namespace vkpt::interrupt_test
