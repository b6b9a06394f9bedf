// math_constants.h — π for host code, once, in the two precisions it is used in (the kernels
// have VKPT_PI in shaders/shared).
#pragma once

#include <numbers>

namespace vkpt {

inline constexpr double kPi = std::numbers::pi;
inline constexpr float kPiFloat = std::numbers::pi_v<float>;

} // namespace vkpt
