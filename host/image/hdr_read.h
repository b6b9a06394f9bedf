// hdr_read.h — reading the linear float images a render takes as input (environment maps):
// Radiance RGBE (.hdr) through stb_image, and PFM through the comparison reader.
#pragma once

#include <string>

#include "image/image.h"

namespace vkpt {

// A Radiance .hdr file ("#?RADIANCE" or "#?RGBE", the standard -Y H +X W orientation), row 0
// at the top as the file stores it. Throws InputError "<path>: <problem>" for a missing,
// truncated or malformed file.
Image readRadianceHdr(const std::string& path);

// .hdr or .pfm by the file name's extension (case-insensitive); InputError for any other.
Image readFloatImage(const std::string& path);

} // namespace vkpt
