// camera.h — the pinhole camera's ray directions, shared so both renderers shoot the same rays.
#ifndef VKPT_CAMERA_H
#define VKPT_CAMERA_H

#include "host_device.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// filmPosition is in pixels from the top-left corner: (x + u, y + v) with u, v in [0, 1) is a
// one-pixel box filter. Returns a unit direction.
VKPT_FN vec3 cameraRayDirection(Camera camera, vec2 filmPosition) {
    float sx =
        (2.0f * filmPosition.x / float(camera.width) - 1.0f) * camera.tanHalfFovY * camera.aspect;
    float sy = (1.0f - 2.0f * filmPosition.y / float(camera.height)) * camera.tanHalfFovY;
    return normalize(camera.forward + sx * camera.right + sy * camera.up);
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_CAMERA_H
