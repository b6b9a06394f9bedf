// gltf_meshopt.cpp — reads a view's EXT_meshopt_compression object, checks its source range and
// the constraints the extension puts on byteStride and count, and runs the decoder and filter
// the extension names (EXT_meshopt_compression, "Compressed buffer views" and "Filters").
#include "scene/gltf_meshopt.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include <meshoptimizer.h>

#include "scene/gltf_document.h"
#include "scene/gltf_json_prepass.h"
#include "scene/gltf_values.h"

namespace vkpt::gltf {
namespace {

constexpr const char* kMeshopt = "EXT_meshopt_compression";

enum class Mode { Attributes, Triangles, Indices };
enum class Filter { None, Octahedral, Quaternion, Exponential };

struct CompressedView {
    int buffer = -1;
    std::size_t byteOffset = 0;
    std::size_t byteLength = 0;
    std::size_t byteStride = 0;
    std::size_t count = 0;
    Mode mode = Mode::Attributes;
    Filter filter = Filter::None;
};

// A non-negative integer member that fits in memory sizes; `fallback` when absent.
std::size_t readSize(const tinygltf::Value& object, const std::string& key, double fallback,
                     const std::string& where) {
    const double value = readNumber(object, key, fallback, where);
    if (value < 0.0 || value != std::floor(value) || value > double(kMaxDecodedBytes)) {
        throw GltfProblem(where + ": " + key + " must be an integer in [0, 2^30]");
    }
    return static_cast<std::size_t>(value);
}

Mode readMode(const tinygltf::Value& object, const std::string& where) {
    const std::string mode = readString(object, "mode", "", where);
    if (mode == "ATTRIBUTES") return Mode::Attributes;
    if (mode == "TRIANGLES") return Mode::Triangles;
    if (mode == "INDICES") return Mode::Indices;
    throw GltfProblem(where + ": mode '" + mode + "' is not ATTRIBUTES, TRIANGLES or INDICES");
}

Filter readFilter(const tinygltf::Value& object, const std::string& where) {
    const std::string filter = readString(object, "filter", "NONE", where);
    if (filter == "NONE") return Filter::None;
    if (filter == "OCTAHEDRAL") return Filter::Octahedral;
    if (filter == "QUATERNION") return Filter::Quaternion;
    if (filter == "EXPONENTIAL") return Filter::Exponential;
    throw GltfProblem(where + ": filter '" + filter +
                      "' is not NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL");
}

CompressedView readCompressedView(const tinygltf::Value& object, const std::string& where) {
    CompressedView view;
    view.buffer = readIndex(object, "buffer", where);
    if (view.buffer < 0) throw GltfProblem(where + ": no source buffer");
    view.byteOffset = readSize(object, "byteOffset", 0.0, where);
    view.byteLength = readSize(object, "byteLength", -1.0, where);
    view.byteStride = readSize(object, "byteStride", -1.0, where);
    view.count = readSize(object, "count", -1.0, where);
    view.mode = readMode(object, where);
    view.filter = readFilter(object, where);
    return view;
}

// The extension's constraints: attribute strides are multiples of 4 up to 256, index strides
// 2 or 4, triangle lists whole, and each filter on the strides it is defined for.
void checkLayout(const CompressedView& view, const std::string& where) {
    const std::size_t stride = view.byteStride;
    const bool attributes = view.mode == Mode::Attributes;
    const bool strideOk = attributes ? (stride > 0 && stride % 4 == 0 && stride <= 256)
                                     : (stride == 2 || stride == 4);
    if (!strideOk) {
        throw GltfProblem(where + ": byteStride " + std::to_string(stride) +
                          " is not allowed for this mode");
    }
    if (view.mode == Mode::Triangles && view.count % 3 != 0) {
        throw GltfProblem(where + ": TRIANGLES count " + std::to_string(view.count) +
                          " is not a multiple of 3");
    }
    const bool filterOk =
        view.filter == Filter::None ||
        (attributes && view.filter == Filter::Octahedral && (stride == 4 || stride == 8)) ||
        (attributes && view.filter == Filter::Quaternion && stride == 8) ||
        (attributes && view.filter == Filter::Exponential);
    if (!filterOk) {
        throw GltfProblem(where + ": the filter does not apply to this mode and byteStride");
    }
}

const std::vector<unsigned char>&
sourceBuffer(const tinygltf::Model& model, const CompressedView& view, const std::string& where) {
    if (static_cast<std::size_t>(view.buffer) >= model.buffers.size()) {
        throw GltfProblem(where + ": buffer " + std::to_string(view.buffer) +
                          " does not exist (the file has " + std::to_string(model.buffers.size()) +
                          " buffers)");
    }
    const auto& data = model.buffers[static_cast<std::size_t>(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset) {
        throw GltfProblem(where + ": the compressed bytes " + std::to_string(view.byteOffset) +
                          " + " + std::to_string(view.byteLength) + " exceed buffer " +
                          std::to_string(view.buffer) + " (" + std::to_string(data.size()) +
                          " bytes)");
    }
    return data;
}

void applyFilter(Filter filter, std::vector<unsigned char>& decoded, const CompressedView& view) {
    switch (filter) {
    case Filter::None:
        return;
    case Filter::Octahedral:
        meshopt_decodeFilterOct(decoded.data(), view.count, view.byteStride);
        return;
    case Filter::Quaternion:
        meshopt_decodeFilterQuat(decoded.data(), view.count, view.byteStride);
        return;
    case Filter::Exponential:
        meshopt_decodeFilterExp(decoded.data(), view.count, view.byteStride);
        return;
    }
}

// meshoptimizer's decoders return -1 for a header byte of an unknown codec version and -2 for a
// stream that ends early or does not parse (meshoptimizer.h, vertexcodec.cpp, indexcodec.cpp).
std::string describeDecodeError(int result) {
    if (result == -1) return "unknown codec version";
    if (result == -2) return "the stream is truncated or malformed";
    return "meshoptimizer error " + std::to_string(result);
}

std::vector<unsigned char> decodeStream(const CompressedView& view, const unsigned char* source,
                                        const std::string& where) {
    std::vector<unsigned char> decoded(view.count * view.byteStride);
    int result = -1;
    switch (view.mode) {
    case Mode::Attributes:
        result = meshopt_decodeVertexBuffer(decoded.data(), view.count, view.byteStride, source,
                                            view.byteLength);
        break;
    case Mode::Triangles:
        result = meshopt_decodeIndexBuffer(decoded.data(), view.count, view.byteStride, source,
                                           view.byteLength);
        break;
    case Mode::Indices:
        result = meshopt_decodeIndexSequence(decoded.data(), view.count, view.byteStride, source,
                                             view.byteLength);
        break;
    }
    if (result != 0) {
        throw GltfProblem(where + ": the compressed data does not decode (" +
                          describeDecodeError(result) + ")");
    }
    applyFilter(view.filter, decoded, view);
    return decoded;
}

// The decoded bytes replace the view's; they must fill it no further than its byteLength.
void writeIntoView(tinygltf::Model& model, const tinygltf::BufferView& target,
                   const std::vector<unsigned char>& decoded, const std::string& where) {
    if (target.buffer < 0 || static_cast<std::size_t>(target.buffer) >= model.buffers.size()) {
        throw GltfProblem(where + ": buffer " + std::to_string(target.buffer) + " does not exist");
    }
    auto& data = model.buffers[static_cast<std::size_t>(target.buffer)].data;
    if (decoded.size() > target.byteLength || target.byteOffset > data.size() ||
        target.byteLength > data.size() - target.byteOffset) {
        throw GltfProblem(where + ": " + std::to_string(decoded.size()) +
                          " decoded bytes do not fit the buffer view (byteLength " +
                          std::to_string(target.byteLength) + ", buffer " +
                          std::to_string(target.buffer) + " of " + std::to_string(data.size()) +
                          " bytes)");
    }
    if (!decoded.empty())
        std::memcpy(data.data() + target.byteOffset, decoded.data(), decoded.size());
}

// A fallback buffer holds no data the loader may use: only views the extension decodes fill it.
bool isFallbackBuffer(const tinygltf::Buffer& buffer) {
    const tinygltf::Value* object = findExtension(buffer.extensions, kMeshopt);
    const tinygltf::Value* fallback = object ? findMember(*object, "fallback") : nullptr;
    return fallback != nullptr && fallback->IsBool() && fallback->Get<bool>();
}

void checkNotOnFallback(const tinygltf::Model& model, const tinygltf::BufferView& view,
                        std::size_t index) {
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) return;
    if (!isFallbackBuffer(model.buffers[static_cast<std::size_t>(view.buffer)])) return;
    throw GltfProblem("buffer view " + std::to_string(index) + " reads the " + kMeshopt +
                      " fallback buffer " + std::to_string(view.buffer) +
                      " without decoding, and that buffer holds no data");
}

} // namespace

void decodeMeshoptBufferViews(tinygltf::Model& model) {
    for (std::size_t i = 0; i < model.bufferViews.size(); ++i) {
        const tinygltf::BufferView& target = model.bufferViews[i];
        const tinygltf::Value* object = findExtension(target.extensions, kMeshopt);
        if (object == nullptr) {
            checkNotOnFallback(model, target, i);
            continue;
        }
        const std::string where = "buffer view " + std::to_string(i) + ": " + kMeshopt;
        const CompressedView view = readCompressedView(*object, where);
        checkLayout(view, where);
        if (view.count * view.byteStride > kMaxDecodedBytes) {
            throw GltfProblem(where + ": count × byteStride exceeds the 1 GiB vkpt decodes");
        }
        const auto& source = sourceBuffer(model, view, where);
        const std::vector<unsigned char> decoded =
            decodeStream(view, source.data() + view.byteOffset, where);
        writeIntoView(model, target, decoded, where);
    }
}

} // namespace vkpt::gltf
