// reference_cache.h — where the trade study keeps its reference images between runs: outside
// the repository, under $XDG_CACHE_HOME/vkpt (or ~/.cache/vkpt), named by the scene and the
// settings and keyed by a hash of both, with a small text file of how each was made.
#pragma once

#include <optional>
#include <string>

#include "common/render_settings.h"
#include "image/image.h"
#include "study/study_output.h"

namespace vkpt {

// Bumped when a change to the integrators makes cached references wrong. 2: the glTF
// metallic-roughness BSDF and textures changed every scene that is not diffuse-only.
inline constexpr int kReferenceCacheVersion = 2;

// $XDG_CACHE_HOME/vkpt, else $HOME/.cache/vkpt; throws InputError when neither is set.
std::string defaultCacheDirectory();

// <directory>/references/<scene stem>-<W>x<H>-<kind>-<spp>spp-<16 hex digits>.pfm, the digits
// an FNV-1a hash of the scene file's bytes, every setting that changes the image, and
// kReferenceCacheVersion. Throws InputError when the scene cannot be read.
std::string referenceCachePath(const std::string& directory, const RenderSettings& settings,
                               StudyReference kind);

struct CachedReference {
    Image image;
    ReferenceInfo info;
};

// The image and its description, or nothing when either file is missing or unreadable.
std::optional<CachedReference> readCachedReference(const std::string& pfmPath);

// Writes the PFM and its description (<path without .pfm>.txt) through temporary files renamed
// into place, so that an interrupted study never leaves half a reference behind.
void writeCachedReference(const std::string& pfmPath, const Image& image,
                          const ReferenceInfo& info);

} // namespace vkpt
