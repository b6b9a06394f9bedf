// gltf_json_prepass.cpp — reads extensionsRequired and rewrites what tinygltf 2.7 would reject in
// compressed files, with nlohmann::json (the JSON library tinygltf itself is built on, so both
// accept the same texts).
#include "scene/gltf_json_prepass.h"

#include <limits>

#include <nlohmann/json.hpp>

#include "scene/gltf_document.h"

namespace vkpt::gltf {
namespace {

using nlohmann::json;

// A one-byte data: URI, which tinygltf decodes in .gltf and .glb alike ("AA==" is one zero).
constexpr const char* kOneByteUri = "data:application/octet-stream;base64,AA==";

std::vector<std::string> stringArray(const json& document, const char* key) {
    std::vector<std::string> strings;
    const auto found = document.find(key);
    if (found == document.end() || !found->is_array()) return strings;
    for (const json& value : *found) {
        if (value.is_string()) strings.push_back(value.get<std::string>());
    }
    return strings;
}

const json* extension(const json& object, const char* name) {
    if (!object.is_object()) return nullptr;
    const auto extensions = object.find("extensions");
    if (extensions == object.end() || !extensions->is_object()) return nullptr;
    const auto found = extensions->find(name);
    return found == extensions->end() ? nullptr : &*found;
}

bool setAsideDracoIndices(json& document, JsonPrepass& prepass) {
    bool changed = false;
    json& meshes = document["meshes"];
    if (!meshes.is_array()) return false;
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        if (!meshes[m].is_object()) continue;
        const auto found = meshes[m].find("primitives");
        if (found == meshes[m].end() || !found->is_array()) continue;
        json& primitives = *found;
        for (std::size_t p = 0; p < primitives.size(); ++p) {
            json& primitive = primitives[p];
            if (extension(primitive, "KHR_draco_mesh_compression") == nullptr) continue;
            const auto indices = primitive.find("indices");
            if (indices == primitive.end() || !indices->is_number_integer()) continue;
            const auto accessor = indices->get<std::int64_t>();
            if (accessor < 0 || accessor > std::numeric_limits<int>::max()) continue;
            prepass.dracoIndices.push_back({m, p, static_cast<int>(accessor)});
            primitive.erase(indices);
            changed = true;
        }
    }
    return changed;
}

bool isFallbackBuffer(const json& buffer) {
    const json* meshopt = extension(buffer, "EXT_meshopt_compression");
    if (meshopt == nullptr || !meshopt->is_object()) return false;
    const auto fallback = meshopt->find("fallback");
    return fallback != meshopt->end() && fallback->is_boolean() && fallback->get<bool>();
}

bool setAsideFallbackBuffers(json& document, JsonPrepass& prepass) {
    bool changed = false;
    json& buffers = document["buffers"];
    if (!buffers.is_array()) return false;
    for (std::size_t b = 0; b < buffers.size(); ++b) {
        json& buffer = buffers[b];
        if (!isFallbackBuffer(buffer)) continue;
        const auto byteLength = buffer.find("byteLength");
        if (byteLength == buffer.end() || !byteLength->is_number_unsigned()) continue;
        prepass.fallbackBuffers.push_back({b, byteLength->get<std::uint64_t>()});
        buffer["uri"] = kOneByteUri;
        buffer["byteLength"] = 1;
        changed = true;
    }
    return changed;
}

// tinygltf 2.7 decodes data: URIs of PNG, JPEG, BMP and GIF images only and takes any other
// for a file name; an EXT_texture_webp image in a data: URI is handed to it as octet-stream,
// which it decodes, leaving the format to gltf_images.cpp (which reads the signature).
bool relabelWebpDataUris(json& document) {
    static const std::string kWebp = "data:image/webp;base64,";
    static const std::string kOctets = "data:application/octet-stream;base64,";
    bool changed = false;
    json& images = document["images"];
    if (!images.is_array()) return false;
    for (json& image : images) {
        if (!image.is_object()) continue;
        const auto uri = image.find("uri");
        if (uri == image.end() || !uri->is_string()) continue;
        const std::string& text = uri->get_ref<const std::string&>();
        if (!text.starts_with(kWebp)) continue;
        *uri = kOctets + text.substr(kWebp.size());
        changed = true;
    }
    return changed;
}

} // namespace

std::optional<JsonPrepass> prepassJson(std::string_view text) {
    json document = json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/false);
    if (document.is_discarded() || !document.is_object()) return std::nullopt;
    JsonPrepass prepass;
    prepass.extensionsRequired = stringArray(document, "extensionsRequired");
    bool changed = false;
    if (document.contains("meshes")) changed |= setAsideDracoIndices(document, prepass);
    if (document.contains("buffers")) changed |= setAsideFallbackBuffers(document, prepass);
    if (document.contains("images")) changed |= relabelWebpDataUris(document);
    prepass.json = changed ? document.dump() : std::string(text);
    return prepass;
}

void restoreSetAside(const JsonPrepass& prepass, tinygltf::Model& model) {
    for (const SetAsideIndices& set : prepass.dracoIndices) {
        // tinygltf keeps every mesh and primitive of the JSON, in order.
        model.meshes.at(set.mesh).primitives.at(set.primitive).indices = set.accessor;
    }
    for (const SetAsideBuffer& set : prepass.fallbackBuffers) {
        if (set.byteLength > kMaxDecodedBytes) {
            throw GltfProblem("buffer " + std::to_string(set.buffer) + ": the fallback buffer's " +
                              std::to_string(set.byteLength) +
                              " bytes exceed the 1 GiB vkpt decodes");
        }
        tinygltf::Buffer& buffer = model.buffers.at(set.buffer);
        buffer.uri.clear();
        buffer.data.assign(static_cast<std::size_t>(set.byteLength), 0);
    }
}

} // namespace vkpt::gltf
