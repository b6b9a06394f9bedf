// gltf_accessors.cpp — locating an accessor's elements in its buffer with every range checked,
// then reading them with memcpy (glTF data need not be aligned for the host).
#include "scene/gltf_accessors.h"

#include <algorithm>
#include <cstring>
#include <initializer_list>
#include <memory>
#include <optional>

#include "scene/gltf_document.h"

namespace vkpt::gltf {
namespace {

// Where an accessor's elements lie; everything in it has been checked against the buffer.
// A sparse accessor's elements are first gathered into `dense`, which `first` then points into.
struct Elements {
    const unsigned char* first = nullptr;
    std::size_t count = 0;
    std::size_t stride = 0;
    std::size_t componentSize = 0;
    std::shared_ptr<const std::vector<unsigned char>> dense;
};

std::string componentTypeName(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
        return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT:
        return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_INT:
        return "INT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return "FLOAT";
    case TINYGLTF_COMPONENT_TYPE_DOUBLE:
        return "DOUBLE";
    default:
        return "componentType " + std::to_string(componentType);
    }
}

std::string typeName(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR:
        return "SCALAR";
    case TINYGLTF_TYPE_VEC2:
        return "VEC2";
    case TINYGLTF_TYPE_VEC3:
        return "VEC3";
    case TINYGLTF_TYPE_VEC4:
        return "VEC4";
    case TINYGLTF_TYPE_MAT2:
        return "MAT2";
    case TINYGLTF_TYPE_MAT3:
        return "MAT3";
    case TINYGLTF_TYPE_MAT4:
        return "MAT4";
    default:
        return "type " + std::to_string(type);
    }
}

std::string accessorName(int index) {
    return "accessor " + std::to_string(index);
}

const tinygltf::Accessor& findAccessor(const tinygltf::Model& model, int index,
                                       const std::string& where) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) {
        throw GltfProblem(where + ": " + accessorName(index) + " does not exist (the file has " +
                          std::to_string(model.accessors.size()) + " accessors)");
    }
    return model.accessors[static_cast<std::size_t>(index)];
}

std::string joinAlternatives(std::initializer_list<int> componentTypes) {
    std::string text;
    std::size_t i = 0;
    for (int componentType : componentTypes) {
        if (i > 0) text += (i + 1 == componentTypes.size()) ? " or " : ", ";
        text += componentTypeName(componentType);
        ++i;
    }
    return text;
}

void requireLayout(const tinygltf::Accessor& accessor, int index, int type,
                   std::initializer_list<int> componentTypes, const std::string& where) {
    bool componentOk = false;
    for (int componentType : componentTypes)
        componentOk |= accessor.componentType == componentType;
    if (accessor.type == type && componentOk) return;
    throw GltfProblem(where + ": " + accessorName(index) + " is " + typeName(accessor.type) +
                      " of " + componentTypeName(accessor.componentType) + ", expected " +
                      typeName(type) + " of " + joinAlternatives(componentTypes));
}

const tinygltf::BufferView& findBufferView(const tinygltf::Model& model,
                                           const tinygltf::Accessor& accessor, int index,
                                           const std::string& where) {
    const int view = accessor.bufferView;
    if (view < 0) throw GltfProblem(where + ": " + accessorName(index) + " has no buffer view");
    if (static_cast<std::size_t>(view) >= model.bufferViews.size()) {
        throw GltfProblem(where + ": " + accessorName(index) + ": buffer view " +
                          std::to_string(view) + " does not exist");
    }
    return model.bufferViews[static_cast<std::size_t>(view)];
}

// One past the last byte the elements touch, relative to the view; nullopt on overflow.
std::optional<std::size_t> elementsEnd(std::size_t offset, std::size_t count, std::size_t stride,
                                       std::size_t elementSize) {
    std::size_t end = 0;
    if (__builtin_mul_overflow(count - 1, stride, &end) ||
        __builtin_add_overflow(end, elementSize, &end) ||
        __builtin_add_overflow(end, offset, &end)) {
        return std::nullopt;
    }
    return end;
}

std::size_t elementSizeOf(const tinygltf::Accessor& accessor) {
    // requireLayout has already restricted type and componentType to known values.
    const auto componentSize = static_cast<std::size_t>(
        tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(accessor.componentType)));
    const auto components = static_cast<std::size_t>(
        tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type)));
    return componentSize * components;
}

std::size_t strideOf(const tinygltf::BufferView& view, const tinygltf::Accessor& accessor,
                     int index, const std::string& where) {
    const std::size_t elementSize = elementSizeOf(accessor);
    const std::size_t stride = view.byteStride != 0 ? view.byteStride : elementSize;
    if (stride < elementSize) {
        throw GltfProblem(where + ": " + accessorName(index) + ": byteStride " +
                          std::to_string(stride) + " of buffer view " +
                          std::to_string(accessor.bufferView) + " is smaller than its " +
                          std::to_string(elementSize) + "-byte elements");
    }
    return stride;
}

void checkElementsInView(const tinygltf::BufferView& view, const tinygltf::Accessor& accessor,
                         int index, std::size_t stride, const std::string& where) {
    const std::size_t elementSize = elementSizeOf(accessor);
    const std::optional<std::size_t> end =
        elementsEnd(accessor.byteOffset, accessor.count, stride, elementSize);
    if (end && *end <= view.byteLength) return;
    throw GltfProblem(where + ": " + accessorName(index) + " reads past the end of buffer view " +
                      std::to_string(accessor.bufferView) + ": " + std::to_string(accessor.count) +
                      " elements of " + std::to_string(elementSize) + " bytes at stride " +
                      std::to_string(stride) + " from byte " + std::to_string(accessor.byteOffset) +
                      " need " + (end ? std::to_string(*end) : std::string("more than 2^64")) +
                      " bytes, the view has " + std::to_string(view.byteLength));
}

// Where a tightly packed run of `count` elements of `elementSize` bytes lies, checked against
// its view: a sparse accessor's indices and values (glTF 2.0, section 3.6.2.3).
const unsigned char* locatePacked(const tinygltf::Model& model, int viewIndex,
                                  std::size_t byteOffset, std::size_t count,
                                  std::size_t elementSize, const std::string& what) {
    if (viewIndex < 0 || static_cast<std::size_t>(viewIndex) >= model.bufferViews.size()) {
        throw GltfProblem(what + ": buffer view " + std::to_string(viewIndex) + " does not exist");
    }
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(viewIndex)];
    const std::optional<std::size_t> end = elementsEnd(byteOffset, count, elementSize, elementSize);
    if (!end || *end > view.byteLength) {
        throw GltfProblem(what + " reads past the end of buffer view " + std::to_string(viewIndex));
    }
    const auto& buffer = model.buffers[static_cast<std::size_t>(view.buffer)];
    return buffer.data.data() + view.byteOffset + byteOffset;
}

std::uint32_t readIndex(const unsigned char* bytes, std::size_t componentSize);

Elements locateDenseElements(const tinygltf::Model& model, const tinygltf::Accessor& accessor,
                             int index, const std::string& where) {
    const tinygltf::BufferView& view = findBufferView(model, accessor, index, where);
    const std::size_t stride = strideOf(view, accessor, index, where);
    if (accessor.count == 0) return {};
    checkElementsInView(view, accessor, index, stride, where);
    // checkBufferViews has already placed the view inside its buffer.
    const auto& buffer = model.buffers[static_cast<std::size_t>(view.buffer)];
    const auto componentSize = static_cast<std::size_t>(
        tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(accessor.componentType)));
    return {buffer.data.data() + view.byteOffset + accessor.byteOffset, accessor.count, stride,
            componentSize, nullptr};
}

// A sparse accessor: its buffer view's elements (zeros without one), then each listed element
// replaced by its value, gathered tightly packed.
Elements locateSparseElements(const tinygltf::Model& model, const tinygltf::Accessor& accessor,
                              int index, const std::string& where) {
    const std::size_t elementSize = elementSizeOf(accessor);
    const std::string what = where + ": " + accessorName(index) + ": sparse";
    auto dense = std::make_shared<std::vector<unsigned char>>(accessor.count * elementSize, 0);
    if (accessor.bufferView >= 0) {
        const Elements base = locateDenseElements(model, accessor, index, where);
        for (std::size_t i = 0; i < base.count; ++i)
            std::memcpy(dense->data() + i * elementSize, base.first + i * base.stride, elementSize);
    }
    const int indexType = accessor.sparse.indices.componentType;
    if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
        throw GltfProblem(what + " indices are " + componentTypeName(indexType) +
                          ", expected UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
    }
    if (accessor.sparse.count < 0 || accessor.sparse.indices.byteOffset < 0 ||
        accessor.sparse.values.byteOffset < 0) {
        throw GltfProblem(what + " has a negative count or byteOffset");
    }
    const auto count = static_cast<std::size_t>(accessor.sparse.count);
    const auto componentSize = static_cast<std::size_t>(
        tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(accessor.componentType)));
    if (count == 0) return {dense->data(), accessor.count, elementSize, componentSize, dense};
    const auto indexSize = static_cast<std::size_t>(
        tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(indexType)));
    const unsigned char* indices =
        locatePacked(model, accessor.sparse.indices.bufferView,
                     static_cast<std::size_t>(accessor.sparse.indices.byteOffset), count, indexSize,
                     what + " indices");
    const unsigned char* values =
        locatePacked(model, accessor.sparse.values.bufferView,
                     static_cast<std::size_t>(accessor.sparse.values.byteOffset), count,
                     elementSize, what + " values");
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint32_t element = readIndex(indices + i * indexSize, indexSize);
        if (element >= accessor.count) {
            throw GltfProblem(what + " index " + std::to_string(element) + " >= count " +
                              std::to_string(accessor.count));
        }
        std::memcpy(dense->data() + element * elementSize, values + i * elementSize, elementSize);
    }
    return {dense->data(), accessor.count, elementSize, componentSize, std::move(dense)};
}

Elements locateElements(const tinygltf::Model& model, const tinygltf::Accessor& accessor, int index,
                        const std::string& where) {
    return accessor.sparse.isSparse ? locateSparseElements(model, accessor, index, where)
                                    : locateDenseElements(model, accessor, index, where);
}

template <typename T> T readValue(const unsigned char* bytes) {
    T value;
    std::memcpy(&value, bytes, sizeof(T));
    return value;
}

// One component as a float. A normalized integer c stands for c / (2^n − 1) unsigned and
// max(c / (2^(n−1) − 1), −1) signed (glTF 2.0, section 3.11); an unnormalized one for its value.
float readComponent(const unsigned char* bytes, int componentType, bool normalized) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const auto c = static_cast<float>(readValue<std::int8_t>(bytes));
        return normalized ? std::max(c / 127.0f, -1.0f) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return normalized ? static_cast<float>(bytes[0]) / 255.0f : static_cast<float>(bytes[0]);
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        const auto c = static_cast<float>(readValue<std::int16_t>(bytes));
        return normalized ? std::max(c / 32767.0f, -1.0f) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        const auto c = static_cast<float>(readValue<std::uint16_t>(bytes));
        return normalized ? c / 65535.0f : c;
    }
    default:
        return readValue<float>(bytes);
    }
}

// N components per element, any of the types readComponent knows.
template <int N>
std::vector<glm::vec<N, float>> readVectors(const tinygltf::Model& model,
                                            const tinygltf::Accessor& accessor, int index,
                                            const std::string& where) {
    const Elements elements = locateElements(model, accessor, index, where);
    std::vector<glm::vec<N, float>> values(elements.count);
    for (std::size_t i = 0; i < elements.count; ++i) {
        const unsigned char* element = elements.first + i * elements.stride;
        for (int c = 0; c < N; ++c) {
            values[i][c] = readComponent(element + std::size_t(c) * elements.componentSize,
                                         accessor.componentType, accessor.normalized);
        }
    }
    return values;
}

constexpr std::initializer_list<int> kFloatOnly = {TINYGLTF_COMPONENT_TYPE_FLOAT};
constexpr std::initializer_list<int> kQuantizedTypes = {
    TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE,
    TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT,
    TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};

void requireNormalizedIntegers(const tinygltf::Accessor& accessor, int index, const char* use,
                               const std::string& where) {
    if (accessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT || accessor.normalized) return;
    throw GltfProblem(where + ": " + accessorName(index) + " is " + typeName(accessor.type) +
                      " of " + componentTypeName(accessor.componentType) +
                      " but not normalized, as " + use + " must be");
}

std::uint32_t readIndex(const unsigned char* bytes, std::size_t componentSize) {
    switch (componentSize) {
    case 1:
        return bytes[0];
    case 2:
        return readValue<std::uint16_t>(bytes);
    default:
        return readValue<std::uint32_t>(bytes);
    }
}

} // namespace

void checkBufferViews(const tinygltf::Model& model) {
    for (std::size_t i = 0; i < model.bufferViews.size(); ++i) {
        const tinygltf::BufferView& view = model.bufferViews[i];
        const std::string where = "buffer view " + std::to_string(i);
        if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) {
            throw GltfProblem(where + ": buffer " + std::to_string(view.buffer) +
                              " does not exist (the file has " +
                              std::to_string(model.buffers.size()) + " buffers)");
        }
        const std::size_t size = model.buffers[static_cast<std::size_t>(view.buffer)].data.size();
        if (view.byteOffset > size || view.byteLength > size - view.byteOffset) {
            throw GltfProblem(where + ": byteOffset " + std::to_string(view.byteOffset) +
                              " + byteLength " + std::to_string(view.byteLength) +
                              " exceeds buffer " + std::to_string(view.buffer) + " (" +
                              std::to_string(size) + " bytes)");
        }
    }
}

bool allowsQuantizedAttributes(const tinygltf::Model& model) {
    const auto& required = model.extensionsRequired;
    return std::find(required.begin(), required.end(), "KHR_mesh_quantization") != required.end();
}

std::vector<glm::vec3> readPositions(const tinygltf::Model& model, int accessorIndex,
                                     const std::string& where) {
    const tinygltf::Accessor& accessor = findAccessor(model, accessorIndex, where);
    requireLayout(accessor, accessorIndex, TINYGLTF_TYPE_VEC3,
                  allowsQuantizedAttributes(model) ? kQuantizedTypes : kFloatOnly, where);
    return readVectors<3>(model, accessor, accessorIndex, where);
}

std::vector<glm::vec3> readNormals(const tinygltf::Model& model, int accessorIndex,
                                   const std::string& where) {
    const tinygltf::Accessor& accessor = findAccessor(model, accessorIndex, where);
    if (allowsQuantizedAttributes(model)) {
        requireLayout(accessor, accessorIndex, TINYGLTF_TYPE_VEC3,
                      {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE,
                       TINYGLTF_COMPONENT_TYPE_SHORT},
                      where);
        requireNormalizedIntegers(accessor, accessorIndex, "normals", where);
    } else {
        requireLayout(accessor, accessorIndex, TINYGLTF_TYPE_VEC3, kFloatOnly, where);
    }
    return readVectors<3>(model, accessor, accessorIndex, where);
}

std::vector<glm::vec4> readTangents(const tinygltf::Model& model, int accessorIndex,
                                    const std::string& where) {
    const tinygltf::Accessor& accessor = findAccessor(model, accessorIndex, where);
    if (allowsQuantizedAttributes(model)) {
        requireLayout(accessor, accessorIndex, TINYGLTF_TYPE_VEC4,
                      {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE,
                       TINYGLTF_COMPONENT_TYPE_SHORT},
                      where);
        requireNormalizedIntegers(accessor, accessorIndex, "tangents", where);
    } else {
        requireLayout(accessor, accessorIndex, TINYGLTF_TYPE_VEC4, kFloatOnly, where);
    }
    return readVectors<4>(model, accessor, accessorIndex, where);
}

std::vector<glm::vec4> readRotations(const tinygltf::Model& model, int accessorIndex,
                                     const std::string& where) {
    const tinygltf::Accessor& accessor = findAccessor(model, accessorIndex, where);
    requireLayout(accessor, accessorIndex, TINYGLTF_TYPE_VEC4,
                  {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE,
                   TINYGLTF_COMPONENT_TYPE_SHORT},
                  where);
    requireNormalizedIntegers(accessor, accessorIndex, "rotations", where);
    return readVectors<4>(model, accessor, accessorIndex, where);
}

std::vector<glm::vec2> readTexcoords(const tinygltf::Model& model, int accessorIndex,
                                     const std::string& where) {
    const tinygltf::Accessor& accessor = findAccessor(model, accessorIndex, where);
    if (allowsQuantizedAttributes(model)) {
        requireLayout(accessor, accessorIndex, TINYGLTF_TYPE_VEC2, kQuantizedTypes, where);
    } else {
        requireLayout(accessor, accessorIndex, TINYGLTF_TYPE_VEC2,
                      {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                       TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                      where);
        requireNormalizedIntegers(accessor, accessorIndex, "texture coordinates", where);
    }
    return readVectors<2>(model, accessor, accessorIndex, where);
}

std::vector<float> readFloatComponents(const tinygltf::Model& model, int accessorIndex, int type,
                                       bool normalizedIntegers, const std::string& where) {
    const tinygltf::Accessor& accessor = findAccessor(model, accessorIndex, where);
    if (normalizedIntegers) {
        requireLayout(accessor, accessorIndex, type, kQuantizedTypes, where);
        requireNormalizedIntegers(accessor, accessorIndex, "these values", where);
    } else {
        requireLayout(accessor, accessorIndex, type, kFloatOnly, where);
    }
    const Elements elements = locateElements(model, accessor, accessorIndex, where);
    const auto components = static_cast<std::size_t>(
        tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type)));
    std::vector<float> values(elements.count * components);
    for (std::size_t i = 0; i < elements.count; ++i) {
        const unsigned char* element = elements.first + i * elements.stride;
        for (std::size_t c = 0; c < components; ++c) {
            values[i * components + c] = readComponent(element + c * elements.componentSize,
                                                       accessor.componentType, accessor.normalized);
        }
    }
    return values;
}

std::vector<glm::uvec4> readJoints(const tinygltf::Model& model, int accessorIndex,
                                   const std::string& where) {
    const tinygltf::Accessor& accessor = findAccessor(model, accessorIndex, where);
    requireLayout(accessor, accessorIndex, TINYGLTF_TYPE_VEC4,
                  {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                  where);
    const Elements elements = locateElements(model, accessor, accessorIndex, where);
    std::vector<glm::uvec4> joints(elements.count);
    for (std::size_t i = 0; i < elements.count; ++i) {
        const unsigned char* element = elements.first + i * elements.stride;
        for (int c = 0; c < 4; ++c) {
            joints[i][c] = readIndex(element + std::size_t(c) * elements.componentSize,
                                     elements.componentSize);
        }
    }
    return joints;
}

std::size_t accessorElementCount(const tinygltf::Model& model, int accessorIndex,
                                 const std::string& where) {
    return findAccessor(model, accessorIndex, where).count;
}

std::vector<std::uint32_t> readIndices(const tinygltf::Model& model, int accessorIndex,
                                       const std::string& where) {
    const tinygltf::Accessor& accessor = findAccessor(model, accessorIndex, where);
    requireLayout(accessor, accessorIndex, TINYGLTF_TYPE_SCALAR,
                  {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                   TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                  where);
    const Elements elements = locateElements(model, accessor, accessorIndex, where);
    std::vector<std::uint32_t> indices(elements.count);
    for (std::size_t i = 0; i < elements.count; ++i) {
        indices[i] = readIndex(elements.first + i * elements.stride, elements.componentSize);
    }
    return indices;
}

} // namespace vkpt::gltf
