// tone_map.h — how 8-bit output maps linear radiance (after the exposure) into [0, 1] before
// the sRGB encoding; float outputs (.pfm, .hdr, .exr) stay linear and never pass through here.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "common/render_settings.h"

namespace vkpt {

// The Khronos PBR Neutral tone mapper (KhronosGroup/ToneMapping, PBR_Neutral/README.md, "PBR
// Neutral Specification"): colours whose largest component, after a small toe offset, stays
// below Ks = 0.76 pass unchanged, so a base colour lit by a unit light is reproduced; above it
// the peak is compressed towards 1 and the colour desaturated towards white (Kd = 0.15), so
// highlights roll off instead of clipping with a shift of hue. Non-negative input; the output
// lies in [0, 1].
glm::vec3 pbrNeutralToneMap(glm::vec3 colour);

// The operator `toneMap` names, applied to a linear colour; a negative, NaN or infinite
// component counts as 0 (black, as the PNG has always written it). Clamp leaves the rest as it
// is (the sRGB encoding clamps to [0, 1]).
glm::vec3 applyToneMap(ToneMap toneMap, glm::vec3 colour);

// "neutral" or "clamp", as --tonemap spells it.
const char* toneMapName(ToneMap toneMap);

} // namespace vkpt
