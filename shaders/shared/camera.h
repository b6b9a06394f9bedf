// camera.h — the camera's rays (perspective or orthographic), shared so both renderers shoot the
// same rays.
#ifndef VKPT_CAMERA_H
#define VKPT_CAMERA_H

#include "host_device.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// filmPosition is in pixels from the top-left corner: (x + u, y + v) with u, v in [0, 1) is a
// one-pixel box filter. The image plane's coordinates (right, up), each in [-1, 1] before the
// horizontal one is stretched by the aspect ratio.
VKPT_FN vec2 cameraPlanePosition(Camera camera, vec2 filmPosition) {
    float sx = (2.0f * filmPosition.x / float(camera.width) - 1.0f) * camera.aspect;
    float sy = 1.0f - 2.0f * filmPosition.y / float(camera.height);
    return vec2(sx, sy);
}

// Where the ray starts: the camera position for a perspective camera; for an orthographic one
// the point of the plane through it (orthogonal to forward) that the sample covers, ymag above
// and ymag·aspect to the right of the centre at the image's edges.
VKPT_FN vec3 cameraRayOrigin(Camera camera, vec2 filmPosition) {
    if (camera.projection != CAMERA_ORTHOGRAPHIC) return camera.position;
    vec2 s = cameraPlanePosition(camera, filmPosition) * camera.orthoHalfHeight;
    return camera.position + s.x * camera.right + s.y * camera.up;
}

// The unit direction of the ray through filmPosition: through the point at distance 1 on the
// pinhole's image plane, or forward for every orthographic ray.
VKPT_FN vec3 cameraRayDirection(Camera camera, vec2 filmPosition) {
    if (camera.projection == CAMERA_ORTHOGRAPHIC) return camera.forward;
    vec2 s = cameraPlanePosition(camera, filmPosition) * camera.tanHalfFovY;
    return normalize(camera.forward + s.x * camera.right + s.y * camera.up);
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_CAMERA_H
