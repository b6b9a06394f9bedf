// gltf_document.h — the first loading step: file bytes to a tinygltf::Model, with every failure
// (missing file, garbage, truncated .glb, missing buffer) turned into one line in our wording.
#pragma once

#include <stdexcept>
#include <string>

#include <tiny_gltf.h>

namespace vkpt::gltf {

// A problem in the file, described by its place ("mesh 3, primitive 0: ...") but without the file
// name; loadGltfScene prefixes the path as given and rethrows it as an InputError.
class GltfProblem : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// "node 7": how a problem names the node it is in.
inline std::string nodeName(int index) {
    return "node " + std::to_string(index);
}

// Reads a .gltf (JSON) or .glb (binary) file, its external buffers and the encoded bytes of its
// external and data: URI images (Image::as_is). extensionsRequired is checked first, before
// tinygltf's own checks can misreport a compressed file (gltf_json_prepass.h); EXT_meshopt
// buffer views are decoded (gltf_meshopt.h). No image is decoded here (gltf_images.h).
tinygltf::Model parseGltfFile(const std::string& path);

} // namespace vkpt::gltf
