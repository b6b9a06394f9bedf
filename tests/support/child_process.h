// child_process.h — runs a renderer as a separate process, as a user or a scheduler would, and
// reads its stderr as it goes, so that tests can signal or kill it at a chosen moment.
#pragma once

#include <csignal>
#include <string>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace vkpt::test {

struct Child {
    pid_t pid = -1;
    int stderrFd = -1;
};

// Starts argv[0] (a path) with the arguments; its stderr goes to a pipe, stdout to /dev/null.
// `environment` entries ("NAME=value") come on top of this process's environment.
inline Child spawnWithStderrPipe(const std::vector<std::string>& arguments,
                                 const std::vector<std::string>& environment = {}) {
    int fds[2];
    if (pipe(fds) != 0) return {};
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDERR_FILENO);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    std::vector<char*> argv;
    for (const std::string& a : arguments)
        argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    std::vector<char*> envp;
    for (const std::string& e : environment)
        envp.push_back(const_cast<char*>(e.c_str()));
    for (char** e = environ; *e; ++e)
        envp.push_back(*e);
    envp.push_back(nullptr);
    Child child;
    if (posix_spawn(&child.pid, argv[0], &actions, nullptr, argv.data(), envp.data()) != 0)
        child.pid = -1;
    posix_spawn_file_actions_destroy(&actions);
    close(fds[1]);
    child.stderrFd = fds[0];
    return child;
}

// Reads until `marker` appears (true) or the stream ends (false); everything read is kept.
inline bool readUntil(int fd, const std::string& marker, std::string& text) {
    char buffer[4096];
    while (text.find(marker) == std::string::npos) {
        ssize_t n = read(fd, buffer, sizeof(buffer));
        if (n <= 0) return false;
        text.append(buffer, std::size_t(n));
    }
    return true;
}

struct Finished {
    int exitCode = -1; // -1 when ended by a signal
    int signal = 0;
    std::string stderrText;
};

// Reads the rest of stderr and waits for the process.
inline Finished finish(Child& child, std::string text = {}) {
    readUntil(child.stderrFd, "\x01", text); // to the end of the stream
    close(child.stderrFd);
    int status = 0;
    waitpid(child.pid, &status, 0);
    Finished f;
    f.stderrText = std::move(text);
    if (WIFEXITED(status)) f.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) f.signal = WTERMSIG(status);
    return f;
}

// Runs to the end.
inline Finished runProcess(const std::vector<std::string>& arguments,
                           const std::vector<std::string>& environment = {}) {
    Child child = spawnWithStderrPipe(arguments, environment);
    return finish(child);
}

} // namespace vkpt::test
