// atomic_write.cpp — write, fsync, rename, fsync the folder.
#include "state/atomic_write.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <unistd.h>

#include "common/errors.h"

namespace vkpt {

namespace {

// The data must be on the disk before the rename makes it the checkpoint; the folder's entry
// after it. Without the first, a crash of the machine could leave a renamed but empty file.
bool syncPath(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const bool synced = ::fsync(fd) == 0 || errno == EINVAL; // EINVAL: the fs cannot sync
    ::close(fd);
    return synced;
}

std::string folderOf(const std::string& path) {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    return parent.empty() ? "." : parent.string();
}

std::string temporaryPathFor(const std::string& path) {
    const std::filesystem::path p(path);
    return (p.parent_path() /
            ("." + p.filename().string() + ".partial-" + std::to_string(::getpid())))
        .string();
}

} // namespace

void writeAtomically(const std::string& path,
                     const std::function<void(const std::string&)>& write) {
    const std::string temporary = temporaryPathFor(path);
    try {
        write(temporary);
        if (!syncPath(temporary)) throw InputError(std::strerror(errno));
        if (std::rename(temporary.c_str(), path.c_str()) != 0)
            throw InputError(std::strerror(errno));
    } catch (const std::exception& error) {
        std::remove(temporary.c_str());
        // A message that names the temporary file names the real one instead.
        std::string reason = error.what();
        for (std::size_t at = reason.find(temporary); at != std::string::npos;
             at = reason.find(temporary, at + path.size()))
            reason.replace(at, temporary.size(), path);
        throw InputError(path + ": cannot write: " + reason);
    }
    syncPath(folderOf(path));
}

std::string rescuePathFor(const std::string& path) {
    const char* tmp = std::getenv("TMPDIR");
    const std::filesystem::path folder = tmp && *tmp ? tmp : "/tmp";
    const std::string name = std::filesystem::path(path).filename().string();
    return (folder / ("vkpt-rescue-" + std::to_string(::getpid()) + "-" + name)).string();
}

} // namespace vkpt
