// nets.h — whether a point set is a (0,m,2)-net in base 2: for every split m = a + c, each of
// the 2^m elementary intervals [i·2^-a, (i+1)·2^-a) × [j·2^-c, (j+1)·2^-c) holds one point.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace vkpt::test {

// Points as 32-bit binary fractions. Returns "" for a net, else the first interval shape and
// cell that does not hold exactly one point.
inline std::string netDefect(const std::vector<glm::uvec2>& points) {
    std::uint32_t m = 0;
    while ((std::size_t(1) << m) < points.size())
        ++m;
    if ((std::size_t(1) << m) != points.size()) return "not a power of two points";
    for (std::uint32_t a = 0; a <= m; ++a) {
        const std::uint32_t c = m - a;
        std::vector<std::uint32_t> count(std::size_t(1) << m, 0);
        for (const glm::uvec2& p : points) {
            const std::uint32_t i = a == 0 ? 0u : p.x >> (32u - a);
            const std::uint32_t j = c == 0 ? 0u : p.y >> (32u - c);
            ++count[(std::size_t(i) << c) | j];
        }
        for (std::size_t cell = 0; cell < count.size(); ++cell)
            if (count[cell] != 1)
                return "intervals 2^-" + std::to_string(a) + " x 2^-" + std::to_string(c) +
                       ": cell " + std::to_string(cell) + " holds " + std::to_string(count[cell]);
    }
    return "";
}

// A float of shared/rng.h's grid (a multiple of 2^-24 in [0, 1)) as a 32-bit binary fraction.
inline std::uint32_t unitFloatBits(float u) {
    return std::uint32_t(u * 16777216.0f) << 8u;
}

} // namespace vkpt::test
