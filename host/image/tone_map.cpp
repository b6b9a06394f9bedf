// tone_map.cpp — the operators 8-bit output can apply, written from their specifications.
#include "image/tone_map.h"

#include <algorithm>
#include <cmath>

namespace vkpt {

namespace {

// PBR Neutral's constants, as its specification names them.
constexpr float kF90 = 0.04f;                    // Fresnel reflectance at normal incidence, IoR 1.5
constexpr float kStartCompression = 0.8f - kF90; // Ks
constexpr float kDesaturation = 0.15f;           // Kd

// A non-finite component is not a colour: written as 0 (black), as the PNG always has; the
// float formats and the statistics are where NaNs get reported. Negative radiance is none.
float representable(float c) {
    return c > 0.0f && std::isfinite(c) ? c : 0.0f;
}

} // namespace

glm::vec3 pbrNeutralToneMap(glm::vec3 colour) {
    // The toe: subtract f, which follows x − x²/(4·F90) up to x = 2·F90 and F90 beyond, with x
    // the smallest component, so that dark colours keep their contrast.
    const float x = std::min({colour.r, colour.g, colour.b});
    const float f = x <= 2.0f * kF90 ? x - x * x / (4.0f * kF90) : kF90;
    const glm::vec3 shifted = colour - f;
    const float p = std::max({shifted.r, shifted.g, shifted.b});
    if (p <= kStartCompression) return shifted;
    // The peak compressed: pn = 1 − (1 − Ks)² / (p + 1 − 2·Ks), which meets p at Ks with slope 1
    // and tends to 1; then g mixes the scaled colour towards grey pn as p − pn grows.
    const float pn = 1.0f - (1.0f - kStartCompression) * (1.0f - kStartCompression) /
                                (p + 1.0f - 2.0f * kStartCompression);
    const float g = 1.0f / (kDesaturation * (p - pn) + 1.0f);
    return shifted * (pn / p) * g + glm::vec3(pn) * (1.0f - g);
}

glm::vec3 applyToneMap(ToneMap toneMap, glm::vec3 colour) {
    const glm::vec3 c(representable(colour.r), representable(colour.g), representable(colour.b));
    switch (toneMap) {
    case ToneMap::PbrNeutral:
        return pbrNeutralToneMap(c);
    case ToneMap::Clamp:
        break;
    }
    return c;
}

const char* toneMapName(ToneMap toneMap) {
    return toneMap == ToneMap::PbrNeutral ? "neutral" : "clamp";
}

} // namespace vkpt
