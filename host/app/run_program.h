// run_program.h — main()'s one catch, shared by the command-line programs: a failure ends with
// one line on stderr and the exit code of DESIGN's error contract.
#pragma once

#include <functional>
#include <string>

namespace vkpt {

// Runs `body` and returns its exit code; on an exception prints "<program>: error: <what>" and
// returns 1 for InputError, 2 for DeviceError (Vulkan or no device), 3 for anything else.
int runProgram(const std::string& program, const std::function<int()>& body);

} // namespace vkpt
