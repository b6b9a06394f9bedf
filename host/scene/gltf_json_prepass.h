// gltf_json_prepass.h — the glTF JSON read once before tinygltf parses it: extensionsRequired is
// taken out first, so that an unsupported extension is reported before anything can misreport
// it, and the constructs of the compression extensions that tinygltf 2.7 rejects or misreads are
// set aside, to be put back into its Model after its parse (WebP data: URIs are relabelled).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <tiny_gltf.h>

namespace vkpt::gltf {

// A KHR_draco_mesh_compression primitive's `indices`: the accessor has no buffer view by the
// extension's definition, and tinygltf 2.7 fails the whole parse on an indices accessor without
// one ("accessor[0] invalid bufferView").
struct SetAsideIndices {
    std::size_t mesh = 0;
    std::size_t primitive = 0;
    int accessor = -1;
};

// An EXT_meshopt_compression fallback buffer: it has no data (no uri), which tinygltf 2.7
// rejects in a .gltf and takes for the BIN chunk in a .glb. It is handed to tinygltf as one byte
// and given its byteLength of zeros afterwards; the decoded views fill it (gltf_meshopt.h).
struct SetAsideBuffer {
    std::size_t buffer = 0;
    std::uint64_t byteLength = 0;
};

struct JsonPrepass {
    std::vector<std::string> extensionsRequired;
    std::vector<SetAsideIndices> dracoIndices;
    std::vector<SetAsideBuffer> fallbackBuffers;
    std::string json; // the JSON to hand tinygltf: the input unless something was set aside
};

// nullopt when the text is not JSON: tinygltf then reports the error in its words.
std::optional<JsonPrepass> prepassJson(std::string_view json);

// Puts what prepassJson set aside back into the Model tinygltf made of prepass.json.
// Throws GltfProblem when a fallback buffer is larger than vkpt decodes (kMaxDecodedBytes).
void restoreSetAside(const JsonPrepass& prepass, tinygltf::Model& model);

// The most bytes a fallback buffer may declare: 1 GiB, far beyond any scene vkpt can upload,
// and a bound on what a few bytes of compressed data can make the loader allocate.
constexpr std::uint64_t kMaxDecodedBytes = std::uint64_t(1) << 30;

} // namespace vkpt::gltf
