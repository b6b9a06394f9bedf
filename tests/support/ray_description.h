// ray_description.h — one line naming a ray query, for the traversal tests' failure messages.
#pragma once

#include <iomanip>
#include <sstream>
#include <string>

#include "bvh/bvh_traverse.h"

namespace vkpt::test {

inline std::string describeRay(const RayQuery& ray) {
    std::ostringstream s;
    s << std::setprecision(9) << "ray o=(" << ray.origin.x << ", " << ray.origin.y << ", "
      << ray.origin.z << ") d=(" << ray.direction.x << ", " << ray.direction.y << ", "
      << ray.direction.z << ") t in (" << ray.tMin << ", " << ray.tMax << ")";
    return s.str();
}

} // namespace vkpt::test
