// scratch_directory.h — where a test writes the files it makes (scenes it generates, images a
// program renders): a folder of its own under the system's temporary directory, one per process
// (ctest runs the cases of one binary as parallel processes), made on first use and removed when
// the process ends, so that a test run from any folder leaves nothing behind in it.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace vkpt::test {

inline const std::filesystem::path& scratchDirectory() {
    struct Scratch {
        std::filesystem::path path =
            std::filesystem::temp_directory_path() / ("vkpt-test-" + std::to_string(::getpid()));
        Scratch() {
            std::filesystem::remove_all(path);
            std::filesystem::create_directories(path);
        }
        ~Scratch() {
            std::error_code ignored; // at exit: nothing left to report to
            std::filesystem::remove_all(path, ignored);
        }
    };
    static const Scratch scratch;
    return scratch.path;
}

// `name` inside the process's scratch directory.
inline std::string scratchPath(const std::string& name) {
    return (scratchDirectory() / name).string();
}

} // namespace vkpt::test
