// emitter_power.h — what an emitting primitive sends out, as the power table and the light BVH
// weigh it: its emitted radiance (factor × strength × emissive texture) averaged over its surface.
#pragma once

#include <cstdint>

#include "shared/scene_view.h"

namespace vkpt {

// The luminance of the primitive's emission averaged over its surface. Without an emissive
// texture, the factor's luminance; with one, the mean over a fixed stratified set of points: an
// n × n grid of the unit square, warped onto the triangle as light sampling warps its numbers
// (a sphere: onto its surface), with n from 4 to 16 so that the points come about one texel apart
// on the texture. A primitive whose every point reads black gets 0: light sampling never picks
// it, and BSDF sampling alone finds whatever it emits between the points. `view` needs the
// scene's primitives, materials, uvs and textures.
double meanEmittedLuminance(std::uint32_t primitiveIndex, const gpu::SceneView& view);

} // namespace vkpt
