// gltf_extensions.h — which glTF extensions vkpt honours: the required ones are checked before
// anything else reads the file, the used-but-ignored ones are named once after loading.
#pragma once

#include <string>
#include <vector>

namespace vkpt::gltf {

// Whether vkpt implements the extension (it changes what is rendered and vkpt follows it).
bool isSupportedExtension(const std::string& extension);

// An extension the file requires changes the meaning of its data; rendering without it would
// give a silently wrong image. Throws GltfProblem naming every unsupported one in one line.
void checkRequiredExtensions(const std::vector<std::string>& extensionsRequired);

// The extensions in extensionsUsed that vkpt does not implement, each once, in file order.
std::vector<std::string> ignoredExtensions(const std::vector<std::string>& extensionsUsed);

} // namespace vkpt::gltf
