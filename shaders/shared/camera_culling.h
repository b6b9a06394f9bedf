// camera_culling.h — glTF's back-face culling of single-sided materials, for camera rays: the
// question both executors ask of a camera ray's closest hit, and the bound on how many such
// hits one camera ray passes. glTF 2.0 §3.9.6 ("doubleSided: false" means back-face culling
// is enabled) describes what every viewer shows; assets are authored for it (a room whose near
// wall faces away from the camera), so the camera sees through the back of an opaque
// single-sided surface. Every other ray (extension, shadow, light probe) meets both sides as
// before, so light transport, MIS and shadows are unchanged; docs/scene-model.md says why.
// Reaches the scene through scene_view.h.
#ifndef VKPT_CAMERA_CULLING_H
#define VKPT_CAMERA_CULLING_H

#include "host_device.h"
#include "instance.h"
#include "intersect.h"
#include "materials.h"
#include "scene_view.h"
#include "sphere.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// The most culled back faces one camera ray passes before the next hit counts whatever its side
// (a bound for the device's loop; both executors stop at the same crossing).
#define CAMERA_CULLED_FACES_MAX 8u

// Whether the camera sees only the front of material `material`: single-sided and opaque. A
// material that transmits (KHR_materials_transmission, and the volume it may bound) keeps both
// sides: a ray inside closed glass must meet its inner faces.
VKPT_FN bool hidesBackFaceFromCamera(uint material VKPT_SCENE_PARAM) {
    if ((sceneMaterialFlags(material VKPT_SCENE_ARG) & MATERIAL_DOUBLE_SIDED) != 0u) return false;
    return !(sceneHasTransmission(VKPT_SCENE_ARG_ONLY) &&
             sceneMaterialTransmission(material VKPT_SCENE_ARG) > 0.0f);
}

// Whether crossing `h` of primitive `index` (placed by `instance`, NO_INSTANCE in the world's own
// geometry) by the camera ray from `origin` along `direction` (world space) is the back face of
// a material the camera sees only from the front. The side is surface.h's: a triangle's front
// is where its corners run counter-clockwise, a sphere's is its outside. In a mesh's own space
// the sign of dot(face, direction) is the world's: the world face normal is det(A)·A^−T·n and
// the direction A·d, and a mirroring placement (det < 0) is the one whose front surface.h flips.
VKPT_FN bool hiddenFromCamera(uint index, uint instance, TriangleHit h, vec3 origin,
                              vec3 direction VKPT_SCENE_PARAM) {
    Triangle primitive = scenePrimitive(index VKPT_SCENE_ARG);
    if (!hidesBackFaceFromCamera(placedMaterialIndex(instance, primitive VKPT_SCENE_ARG)
                                     VKPT_SCENE_ARG))
        return false;
    vec3 d = direction;
    vec3 o = origin;
#if VKPT_INSTANCES
    if (sceneHasInstances(VKPT_SCENE_ARG_ONLY) && instance != NO_INSTANCE) {
        Instance x = sceneInstance(instance VKPT_SCENE_ARG);
        d = instanceRayDirection(x, direction);
        o = instanceRayOrigin(x, origin);
    }
#endif
    if (sceneHasSpheres(VKPT_SCENE_ARG_ONLY) && isSpherePrimitive(primitive))
        return dot(sphereNormalAt(o + h.t * d, primitive.v0), d) > 0.0f;
    return dot(unitFaceNormal(primitive.v0, primitive.v1, primitive.v2), d) > 0.0f;
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_CAMERA_CULLING_H
