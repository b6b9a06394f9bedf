// studio_environment.h — the built-in environment that lights a scene which brings no light of
// its own (scene_lighting.h decides when): a neutral grey studio, an analytic function of the
// direction evaluated into an equirectangular map, so that both renderers light and importance
// sample it exactly as they do an --env map (docs/scene-model.md, "Default lighting").
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace vkpt {

// The map's size: 0.7° a texel, fine enough for the key light's soft edge (20° wide).
inline constexpr std::uint32_t kStudioWidth = 512;
inline constexpr std::uint32_t kStudioHeight = 256;

// The map's mean luminance over the sphere (texels weighted by their solid angles, as
// environment_map.h weighs them): what the lighting rule compares emitters against, as a
// constant so that deciding costs no map (making one takes 60 ms). The studio tests hold it to
// the map.
inline constexpr double kStudioMeanLuminance = 0.700759543;

// The name the log line and SceneEnvironment::sourcePath give it.
inline constexpr const char* kStudioName = "studio";

// Radiance arriving from unit direction `d` (world space, +Y up, the glTF convention), grey
// (R = G = B): a sky that brightens from the horizon (0.6) to the zenith (1.0), a darker floor
// (0.25) below a 4°-wide soft horizon, and a round key light of radiance 16 and 12° radius, its
// edge smoothed over 4°, 50° above the horizon on the side of −X and +Z (front left of a camera
// that looks along −Z, as vkpt's framing camera does).
float studioRadiance(const glm::vec3& d);

// The unit direction towards the key light's centre.
glm::vec3 studioKeyDirection();

// studioRadiance averaged over each texel of a kStudioWidth × kStudioHeight map (4 × 4 samples
// a texel, so the key light's edge is not aliased), with scale 1.
SceneEnvironment makeStudioEnvironment();

} // namespace vkpt
