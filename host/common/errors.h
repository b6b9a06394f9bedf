// errors.h — the error types every layer throws and main() turns into one line and an exit code.
#pragma once

#include <stdexcept>
#include <string>

namespace vkpt {

// Bad input that a user can fix: a missing or malformed file, an index out of range.
// The message names the file and the place, e.g.
// "cornell.gltf: mesh 3, primitive 0: index 812 >= vertex count 600". Exit code 1.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The compute device failed or none fits (VulkanError, host/gpu/vk_check.h, is one). Declared
// here so that main() can tell it from other failures without knowing Vulkan. Exit code 2.
class DeviceError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A programmer error caught by VKPT_ASSERT. Exit code 3.
class InternalError : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

[[noreturn]] void failAssertion(const char* condition, const std::string& message, const char* file,
                                int line);

} // namespace vkpt

// Invariants of our own code (not input checks); on in every build, since the checks are cheap
// next to the work they guard.
#define VKPT_ASSERT(cond, msg)                                                                     \
    do {                                                                                           \
        if (!(cond)) ::vkpt::failAssertion(#cond, (msg), __FILE__, __LINE__);                      \
    } while (false)
