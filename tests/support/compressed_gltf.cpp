// compressed_gltf.cpp — builds the test scene's JSON with nlohmann::json and its binary chunk by
// hand, so that each compressed form is laid out exactly as its extension specifies (including
// a meshopt fallback buffer without data, which glTF writers do not produce on their own).
#include "compressed_gltf.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <memory>
#include <stdexcept>

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>
#include <meshoptimizer.h>
#include <nlohmann/json.hpp>
#include <stb_image_write.h>
#include <webp/encode.h>

#include "meshes.h"

namespace vkpt::test {
namespace {

using nlohmann::json;
using Bytes = std::vector<std::uint8_t>;

constexpr int kFloat = 5126, kByte = 5120, kShort = 5122, kUnsignedShort = 5123,
              kUnsignedInt = 5125;

class SceneFile {
public:
    SceneFile() {
        doc_["asset"] = {{"version", "2.0"}, {"generator", "vkpt tests/support/compressed_gltf"}};
        doc_["buffers"] = json::array({json::object()});
    }

    json& doc() { return doc_; }

    // A view of bytes appended to the binary chunk (buffer 0), 4-byte aligned.
    int addView(const void* bytes, std::size_t size, int stride = 0) {
        while (bin_.size() % 4 != 0)
            bin_.push_back(0);
        json view = {{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", size}};
        if (stride != 0) view["byteStride"] = stride;
        const auto* first = static_cast<const std::uint8_t*>(bytes);
        bin_.insert(bin_.end(), first, first + size);
        return append("bufferViews", view);
    }

    int addAccessor(int view, int componentType, std::size_t count, const char* type,
                    bool normalized = false) {
        json accessor = {{"componentType", componentType}, {"count", count}, {"type", type}};
        if (view >= 0) accessor["bufferView"] = view;
        if (normalized) accessor["normalized"] = true;
        return append("accessors", accessor);
    }

    int append(const char* key, const json& value) {
        json& array = doc_[key];
        if (!array.is_array()) array = json::array();
        array.push_back(value);
        return int(array.size() - 1);
    }

    void require(const std::string& extension) {
        for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
            json& list = doc_[key];
            if (!list.is_array()) list = json::array();
            if (std::find(list.begin(), list.end(), extension) == list.end())
                list.push_back(extension);
        }
    }

    void writeGlb(const std::string& path) {
        while (bin_.size() % 4 != 0)
            bin_.push_back(0);
        doc_["buffers"][0]["byteLength"] = bin_.size();
        std::string text = doc_.dump();
        text.resize((text.size() + 3) / 4 * 4, ' ');
        const auto total = std::uint32_t(12 + 8 + text.size() + 8 + bin_.size());
        std::ofstream out(path, std::ios::binary);
        auto u32 = [&](std::uint32_t v) { out.write(reinterpret_cast<const char*>(&v), 4); };
        out.write("glTF", 4);
        u32(2);
        u32(total);
        u32(std::uint32_t(text.size()));
        u32(0x4E4F534Au); // JSON
        out.write(text.data(), std::streamsize(text.size()));
        u32(std::uint32_t(bin_.size()));
        u32(0x004E4942u); // BIN
        out.write(reinterpret_cast<const char*>(bin_.data()), std::streamsize(bin_.size()));
        if (!out) throw std::runtime_error("cannot write " + path);
    }

private:
    json doc_;
    Bytes bin_;
};

json boundsOf(const std::vector<glm::vec3>& points, bool upper) {
    glm::vec3 b = points.front();
    for (const glm::vec3& p : points)
        b = upper ? glm::max(b, p) : glm::min(b, p);
    return json::array({b.x, b.y, b.z});
}

// --- Floats: the uncompressed reference ------------------------------------------------------

json floatPrimitive(SceneFile& file, const TexturedMesh& mesh) {
    const std::size_t n = mesh.positions.size();
    const int position = file.addAccessor(
        file.addView(mesh.positions.data(), n * sizeof(glm::vec3)), kFloat, n, "VEC3");
    file.doc()["accessors"][std::size_t(position)]["min"] = boundsOf(mesh.positions, false);
    file.doc()["accessors"][std::size_t(position)]["max"] = boundsOf(mesh.positions, true);
    const int normal = file.addAccessor(file.addView(mesh.normals.data(), n * sizeof(glm::vec3)),
                                        kFloat, n, "VEC3");
    const int texcoord = file.addAccessor(
        file.addView(mesh.texcoords.data(), n * sizeof(glm::vec2)), kFloat, n, "VEC2");
    const int indices = file.addAccessor(file.addView(mesh.indices.data(), mesh.indices.size() * 4),
                                         kUnsignedInt, mesh.indices.size(), "SCALAR");
    return {{"attributes", {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", texcoord}}},
            {"indices", indices},
            {"material", 0}};
}

// --- Draco -----------------------------------------------------------------------------------

template <typename T>
int addDracoAttribute(draco::Mesh& mesh, draco::GeometryAttribute::Type kind, int components,
                      const std::vector<T>& values) {
    draco::GeometryAttribute attribute;
    attribute.Init(kind, nullptr, std::uint8_t(components), draco::DT_FLOAT32, false,
                   sizeof(float) * std::size_t(components), 0);
    const int id = mesh.AddAttribute(attribute, true, std::uint32_t(values.size()));
    for (std::size_t i = 0; i < values.size(); ++i)
        mesh.attribute(id)->SetAttributeValue(draco::AttributeValueIndex(std::uint32_t(i)),
                                              &values[i][0]);
    return id;
}

json dracoPrimitive(SceneFile& file, const TexturedMesh& mesh) {
    draco::Mesh source;
    source.set_num_points(std::uint32_t(mesh.positions.size()));
    const int position =
        addDracoAttribute(source, draco::GeometryAttribute::POSITION, 3, mesh.positions);
    const int normal = addDracoAttribute(source, draco::GeometryAttribute::NORMAL, 3, mesh.normals);
    const int texcoord =
        addDracoAttribute(source, draco::GeometryAttribute::TEX_COORD, 2, mesh.texcoords);
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3)
        source.AddFace({draco::PointIndex(mesh.indices[t]), draco::PointIndex(mesh.indices[t + 1]),
                        draco::PointIndex(mesh.indices[t + 2])});
    draco::Encoder encoder;
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, kDracoPositionBits);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, kDracoNormalBits);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, kDracoTexcoordBits);
    draco::EncoderBuffer encoded;
    const draco::Status status = encoder.EncodeMeshToBuffer(source, &encoded);
    if (!status.ok()) throw std::runtime_error("Draco: " + status.error_msg_string());
    // The accessors state the decoded counts, which Draco may change (it merges equal points).
    draco::DecoderBuffer buffer;
    buffer.Init(encoded.data(), encoded.size());
    const std::unique_ptr<draco::Mesh> decoded =
        draco::Decoder().DecodeMeshFromBuffer(&buffer).value();
    const std::size_t points = decoded->num_points();
    const int view = file.addView(encoded.data(), encoded.size());
    const int positionAccessor = file.addAccessor(-1, kFloat, points, "VEC3");
    file.doc()["accessors"][std::size_t(positionAccessor)]["min"] = boundsOf(mesh.positions, false);
    file.doc()["accessors"][std::size_t(positionAccessor)]["max"] = boundsOf(mesh.positions, true);
    const int normalAccessor = file.addAccessor(-1, kFloat, points, "VEC3");
    const int texcoordAccessor = file.addAccessor(-1, kFloat, points, "VEC2");
    const int indices =
        file.addAccessor(-1, kUnsignedInt, std::size_t(decoded->num_faces()) * 3, "SCALAR");
    file.require("KHR_draco_mesh_compression");
    const json ids = {{"POSITION", source.attribute(position)->unique_id()},
                      {"NORMAL", source.attribute(normal)->unique_id()},
                      {"TEXCOORD_0", source.attribute(texcoord)->unique_id()}};
    return {{"attributes",
             {{"POSITION", positionAccessor},
              {"NORMAL", normalAccessor},
              {"TEXCOORD_0", texcoordAccessor}}},
            {"indices", indices},
            {"material", 0},
            {"extensions",
             {{"KHR_draco_mesh_compression", {{"bufferView", view}, {"attributes", ids}}}}}};
}

// --- meshopt ---------------------------------------------------------------------------------

// Views into the fallback buffer (buffer 1) that the loader fills by decoding.
class MeshoptLayout {
public:
    explicit MeshoptLayout(SceneFile& file) : file_(file) {}

    int addAttributes(const Bytes& decoded, std::size_t count, int stride, const char* filter) {
        Bytes encoded(meshopt_encodeVertexBufferBound(count, std::size_t(stride)));
        encoded.resize(meshopt_encodeVertexBuffer(encoded.data(), encoded.size(), decoded.data(),
                                                  count, std::size_t(stride)));
        return addView(encoded, count, stride, "ATTRIBUTES", filter, true);
    }

    int addTriangles(const std::vector<std::uint32_t>& indices, std::size_t vertexCount) {
        Bytes encoded(meshopt_encodeIndexBufferBound(indices.size(), vertexCount));
        encoded.resize(meshopt_encodeIndexBuffer(encoded.data(), encoded.size(), indices.data(),
                                                 indices.size()));
        return addView(encoded, indices.size(), 4, "TRIANGLES", "NONE", false);
    }

    void finish() {
        file_.doc()["buffers"].push_back(
            {{"byteLength", fallbackSize_},
             {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
        file_.require("EXT_meshopt_compression");
    }

private:
    int addView(const Bytes& encoded, std::size_t count, int stride, const char* mode,
                const char* filter, bool attributes) {
        const int source = file_.addView(encoded.data(), encoded.size());
        const json& sourceView = file_.doc()["bufferViews"][std::size_t(source)];
        const std::size_t size = count * std::size_t(stride);
        json view = {{"buffer", 1}, {"byteOffset", fallbackSize_}, {"byteLength", size}};
        if (attributes) view["byteStride"] = stride;
        view["extensions"]["EXT_meshopt_compression"] = {{"buffer", 0},
                                                         {"byteOffset", sourceView["byteOffset"]},
                                                         {"byteLength", encoded.size()},
                                                         {"byteStride", stride},
                                                         {"count", count},
                                                         {"mode", mode},
                                                         {"filter", filter}};
        fallbackSize_ += (size + 3) / 4 * 4;
        // The view of the compressed bytes stays in the file, as encoders leave it.
        return file_.append("bufferViews", view);
    }

    SceneFile& file_;
    std::size_t fallbackSize_ = 0;
};

json meshoptPrimitive(SceneFile& file, const TexturedMesh& mesh) {
    const std::size_t n = mesh.positions.size();
    MeshoptLayout layout(file);
    Bytes positions(n * 12);
    std::memcpy(positions.data(), mesh.positions.data(), positions.size());
    const int positionView = layout.addAttributes(positions, n, 12, "NONE");
    std::vector<float> normals4;
    for (const glm::vec3& v : mesh.normals)
        normals4.insert(normals4.end(), {v.x, v.y, v.z, 0.0f});
    Bytes normals(n * 8);
    meshopt_encodeFilterOct(normals.data(), n, 8, kMeshoptNormalBits, normals4.data());
    const int normalView = layout.addAttributes(normals, n, 8, "OCTAHEDRAL");
    Bytes texcoords(n * 8);
    meshopt_encodeFilterExp(texcoords.data(), n, 8, kMeshoptTexcoordMantissaBits,
                            &mesh.texcoords[0].x);
    const int texcoordView = layout.addAttributes(texcoords, n, 8, "EXPONENTIAL");
    const int indexView = layout.addTriangles(mesh.indices, n);
    layout.finish();
    file.require("KHR_mesh_quantization"); // the OCTAHEDRAL normals are normalized SHORT
    const int position = file.addAccessor(positionView, kFloat, n, "VEC3");
    file.doc()["accessors"][std::size_t(position)]["min"] = boundsOf(mesh.positions, false);
    file.doc()["accessors"][std::size_t(position)]["max"] = boundsOf(mesh.positions, true);
    const int normal = file.addAccessor(normalView, kShort, n, "VEC3", true);
    const int texcoord = file.addAccessor(texcoordView, kFloat, n, "VEC2");
    const int indices = file.addAccessor(indexView, kUnsignedInt, mesh.indices.size(), "SCALAR");
    return {{"attributes", {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", texcoord}}},
            {"indices", indices},
            {"material", 0}};
}

// --- KHR_mesh_quantization -------------------------------------------------------------------

template <typename T> T quantize(float value, float scale) {
    return T(std::lround(double(value) * double(scale)));
}

// Positions as normalized SHORT: q = round(p / h · 32767) with h the sphere's largest
// |coordinate|; the node's scale h undoes it.
json quantizedPrimitive(SceneFile& file, const TexturedMesh& mesh, float& halfExtent) {
    const std::size_t n = mesh.positions.size();
    halfExtent = 0.0f;
    for (const glm::vec3& p : mesh.positions)
        halfExtent = std::max({halfExtent, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    std::vector<std::int16_t> positions, texcoords;
    std::vector<std::int8_t> normals;
    for (std::size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c)
            positions.push_back(quantize<std::int16_t>(mesh.positions[i][c] / halfExtent, 32767));
        positions.push_back(0);
        for (int c = 0; c < 3; ++c)
            normals.push_back(quantize<std::int8_t>(mesh.normals[i][c], 127));
        normals.push_back(0);
        for (int c = 0; c < 2; ++c)
            texcoords.push_back(quantize<std::int16_t>(mesh.texcoords[i][c], 32767));
    }
    std::vector<std::uint16_t> indices(mesh.indices.begin(), mesh.indices.end());
    file.require("KHR_mesh_quantization");
    const int position = file.addAccessor(file.addView(positions.data(), positions.size() * 2, 8),
                                          kShort, n, "VEC3", true);
    file.doc()["accessors"][std::size_t(position)]["min"] = {-1, -1, -1};
    file.doc()["accessors"][std::size_t(position)]["max"] = {1, 1, 1};
    const int normal =
        file.addAccessor(file.addView(normals.data(), normals.size(), 4), kByte, n, "VEC3", true);
    const int texcoord = file.addAccessor(file.addView(texcoords.data(), texcoords.size() * 2, 4),
                                          kShort, n, "VEC2", true);
    const int index = file.addAccessor(file.addView(indices.data(), indices.size() * 2),
                                       kUnsignedShort, indices.size(), "SCALAR");
    return {{"attributes", {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", texcoord}}},
            {"indices", index},
            {"material", 0}};
}

// --- Images ----------------------------------------------------------------------------------

Bytes encodePng(const Rgba8Image& image) {
    Bytes png;
    auto append = [](void* context, void* data, int size) {
        auto* out = static_cast<Bytes*>(context);
        out->insert(out->end(), static_cast<std::uint8_t*>(data),
                    static_cast<std::uint8_t*>(data) + size);
    };
    if (!stbi_write_png_to_func(append, &png, int(image.width), int(image.height), 4,
                                image.rgba.data(), int(image.width * 4)))
        throw std::runtime_error("cannot encode the PNG");
    return png;
}

Bytes encodeLosslessWebp(const Rgba8Image& image) {
    std::uint8_t* out = nullptr;
    const std::size_t size = WebPEncodeLosslessRGBA(image.rgba.data(), int(image.width),
                                                    int(image.height), int(image.width * 4), &out);
    if (size == 0) throw std::runtime_error("cannot encode the WebP");
    Bytes webp(out, out + size);
    WebPFree(out);
    return webp;
}

int addImage(SceneFile& file, const Bytes& bytes, const char* mimeType) {
    return file.append("images", {{"bufferView", file.addView(bytes.data(), bytes.size())},
                                  {"mimeType", mimeType}});
}

json texture(SceneFile& file, ImageCoding coding) {
    const Rgba8Image image = baseColourImage();
    if (coding == ImageCoding::Png)
        return {{"source", addImage(file, encodePng(image), "image/png")}};
    json result;
    if (coding == ImageCoding::WebpOverPngFallback) {
        Rgba8Image black = image;
        std::fill(black.rgba.begin(), black.rgba.end(), std::uint8_t(0));
        result["source"] = addImage(file, encodePng(black), "image/png");
    }
    const int webp = addImage(file, encodeLosslessWebp(image), "image/webp");
    result["extensions"]["EXT_texture_webp"] = {{"source", webp}};
    json& used = file.doc()["extensionsUsed"];
    if (!used.is_array()) used = json::array();
    used.push_back("EXT_texture_webp");
    if (coding == ImageCoding::Webp) file.require("EXT_texture_webp");
    return result;
}

void addSceneAround(SceneFile& file, const json& primitive, const json& sphereNode,
                    ImageCoding image) {
    json& doc = file.doc();
    doc["meshes"] = json::array({{{"primitives", json::array({primitive})}}});
    doc["textures"] = json::array({texture(file, image)});
    doc["materials"] = json::array(
        {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"metallicFactor", 0}}},
          {"extensions", {{"KHR_materials_specular", {{"specularFactor", 0}}}}}}});
    doc["cameras"] =
        json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.01}}}}});
    doc["extensions"]["KHR_lights_punctual"]["lights"] =
        json::array({{{"type", "point"}, {"intensity", 40.0}}});
    doc["nodes"] = json::array({sphereNode,
                                {{"camera", 0}, {"translation", {0.0, 0.3, 4.0}}},
                                {{"translation", {2.0, 3.0, 3.0}},
                                 {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}});
    doc["scenes"] = json::array({{{"nodes", {0, 1, 2}}}});
    doc["scene"] = 0;
    for (const char* used : {"KHR_lights_punctual", "KHR_materials_specular"})
        doc["extensionsUsed"].push_back(used);
}

} // namespace

TexturedMesh texturedSphere() {
    const IndexedMesh sphere = icosphere(2, 1.0f, glm::vec3(0.0f));
    TexturedMesh mesh;
    mesh.positions = sphere.vertices;
    for (const glm::vec3& p : sphere.vertices) {
        const glm::vec3 n = glm::normalize(p);
        mesh.normals.push_back(n);
        // Equirectangular around +Y; a seam is of no concern for these comparisons.
        const float u = std::atan2(n.z, n.x) / (2.0f * float(M_PI)) + 0.5f;
        const float v = std::acos(std::clamp(n.y, -1.0f, 1.0f)) / float(M_PI);
        mesh.texcoords.emplace_back(u, v);
    }
    for (const auto& t : sphere.triangles)
        mesh.indices.insert(mesh.indices.end(), t.begin(), t.end());
    return mesh;
}

Rgba8Image baseColourImage() {
    Rgba8Image image{8, 4, {}};
    for (std::uint32_t y = 0; y < image.height; ++y)
        for (std::uint32_t x = 0; x < image.width; ++x)
            image.rgba.insert(image.rgba.end(),
                              {std::uint8_t(40 + 25 * x), std::uint8_t(60 + 45 * y),
                               std::uint8_t(((x + y) % 2) ? 220 : 90), std::uint8_t(255)});
    return image;
}

void writeTestScene(const std::string& path, GeometryCoding geometry, ImageCoding image) {
    SceneFile file;
    const TexturedMesh mesh = texturedSphere();
    json primitive;
    json sphereNode = {{"mesh", 0}};
    switch (geometry) {
    case GeometryCoding::Floats:
        primitive = floatPrimitive(file, mesh);
        break;
    case GeometryCoding::Draco:
        primitive = dracoPrimitive(file, mesh);
        break;
    case GeometryCoding::Meshopt:
        primitive = meshoptPrimitive(file, mesh);
        break;
    case GeometryCoding::Quantized: {
        float halfExtent = 1.0f;
        primitive = quantizedPrimitive(file, mesh, halfExtent);
        sphereNode["scale"] = {halfExtent, halfExtent, halfExtent};
        break;
    }
    }
    addSceneAround(file, primitive, sphereNode, image);
    file.writeGlb(path);
}

} // namespace vkpt::test
