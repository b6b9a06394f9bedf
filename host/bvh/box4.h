// box4.h — boxes in four-float vectors (GCC/Clang vector extensions: SSE on x86-64, NEON on
// arm64, plain code elsewhere) for the BVH build's inner loops, which extend a box per
// primitive: one vector min and one max instead of six scalar ones. The fourth lane is kept 0.
#pragma once

#include <cstdint>
#include <cstring>
#include <limits>

#include <glm/glm.hpp>

#include "bvh/bvh_build.h"

namespace vkpt {

using Float4 = float __attribute__((vector_size(16)));
using Int4 = std::int32_t __attribute__((vector_size(16)));

// x, y, z of a vec3 followed by any 4 bytes, the fourth lane cleared: the build keeps a
// primitive's index there, whose bits would be a denormal float, slow in arithmetic.
inline Float4 loadXyz(const glm::vec3& v) {
    Float4 value;
    std::memcpy(&value, &v, sizeof value);
    const Int4 keepXyz = {-1, -1, -1, 0};
    return reinterpret_cast<Float4>(reinterpret_cast<Int4>(value) & keepXyz);
}

// The same comparisons as glm::min and glm::max (Aabb::extend), lane by lane, so that a NaN
// coordinate is handled as the scalar code handles it.
inline Float4 min4(const Float4& current, const Float4& v) {
    return v < current ? v : current;
}
inline Float4 max4(const Float4& current, const Float4& v) {
    return current < v ? v : current;
}

struct Box4 {
    Float4 min = {std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
                  std::numeric_limits<float>::max(), 0.0f};
    Float4 max = {std::numeric_limits<float>::lowest(), std::numeric_limits<float>::lowest(),
                  std::numeric_limits<float>::lowest(), 0.0f};

    void extend(const Float4& lo, const Float4& hi) {
        min = min4(min, lo);
        max = max4(max, hi);
    }
    void extend(const Float4& point) { extend(point, point); }

    // Aabb::surfaceArea's expression, in the same order of operations (so the same bits), for
    // a box that is not empty: the SAH sweep's running unions, which start at a bin the
    // centroid mapping never leaves empty.
    float surfaceArea() const {
        const Float4 d = max - min;
        const Float4 products = d * __builtin_shufflevector(d, d, 1, 2, 0, 3); // xy, yz, zx
        return 2.0f * (products[0] + products[1] + products[2]);
    }

    Aabb toAabb() const {
        return Aabb{glm::vec3(min[0], min[1], min[2]), glm::vec3(max[0], max[1], max[2])};
    }
};

} // namespace vkpt
