// errors.cpp — assertion failures become InternalError exceptions that name the place.
#include "common/errors.h"

namespace vkpt {

void failAssertion(const char* condition, const std::string& message, const char* file, int line) {
    throw InternalError(std::string(file) + ":" + std::to_string(line) + ": assertion '" +
                        condition + "' failed: " + message);
}

} // namespace vkpt
