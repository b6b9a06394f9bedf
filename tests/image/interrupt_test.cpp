// interrupt_test.cpp — Ctrl-C during a long vkpt render: the current pass finishes, the image
// so far is written, and the exit code is 130 (128 + SIGINT), as the command line promises.
#include <gtest/gtest.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "image/image_io.h"

extern char** environ;

namespace vkpt {
namespace {

struct Child {
    pid_t pid = -1;
    int stderrFd = -1;
};

Child spawnWithStderrPipe(const std::vector<std::string>& arguments) {
    int fds[2];
    if (pipe(fds) != 0) return {};
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDERR_FILENO);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    std::vector<char*> argv;
    for (const std::string& a : arguments)
        argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    Child child;
    if (posix_spawn(&child.pid, argv[0], &actions, nullptr, argv.data(), environ) != 0)
        child.pid = -1;
    posix_spawn_file_actions_destroy(&actions);
    close(fds[1]);
    child.stderrFd = fds[0];
    return child;
}

// Reads until `marker` appears (true) or the stream ends (false); everything read is kept.
bool readUntil(int fd, const std::string& marker, std::string& text) {
    char buffer[4096];
    while (text.find(marker) == std::string::npos) {
        ssize_t n = read(fd, buffer, sizeof(buffer));
        if (n <= 0) return false;
        text.append(buffer, std::size_t(n));
    }
    return true;
}

TEST(VkptInterrupt, CtrlCFinishesThePassWritesTheImageAndExits130) {
    const std::string output = (std::filesystem::current_path() / "interrupted.pfm").string();
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
} // namespace vkpt
