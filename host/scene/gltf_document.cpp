// gltf_document.cpp — reads the file ourselves, checks the .glb container, then lets tinygltf parse
// the JSON and load buffers; its errors are reworded into one line.
#include "scene/gltf_document.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <new>
#include <optional>
#include <regex>
#include <string_view>
#include <vector>

#include "scene/gltf_extensions.h"
#include "scene/gltf_json_prepass.h"
#include "scene/gltf_meshopt.h"

namespace vkpt::gltf {
namespace {

using Bytes = std::vector<unsigned char>;

constexpr std::size_t kGlbHeaderSize = 12;
constexpr std::size_t kGlbChunkHeaderSize = 8;
constexpr std::uint32_t kGlbChunkJson = 0x4E4F534Au; // "JSON", little-endian
// tinygltf takes the length as an unsigned int.
constexpr std::size_t kMaxFileSize = std::numeric_limits<unsigned int>::max();
// Lines longer than this are cut: a failed data URI would otherwise print megabytes of base64.
constexpr std::size_t kMaxMessageLine = 240;

std::string describeTinyGltfError(const std::string& error, const std::string& baseDir);

[[noreturn]] void failWithErrno(const char* what) {
    throw GltfProblem(std::string(what) + ": " + std::strerror(errno));
}

Bytes readWholeFile(const std::string& path) {
    std::error_code ignored;
    if (std::filesystem::is_directory(path, ignored)) {
        throw GltfProblem("is a directory, not a glTF file");
    }
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                         &std::fclose);
    if (!file) failWithErrno("cannot open the file");
    Bytes bytes;
    unsigned char block[1 << 16];
    while (std::size_t got = std::fread(block, 1, sizeof(block), file.get())) {
        bytes.insert(bytes.end(), block, block + got);
        if (bytes.size() > kMaxFileSize) throw GltfProblem("the file is larger than 4 GiB");
    }
    if (std::ferror(file.get())) failWithErrno("cannot read the file");
    if (bytes.empty()) throw GltfProblem("the file is empty");
    return bytes;
}

std::uint32_t readU32(const Bytes& bytes, std::size_t offset) {
    // The .glb format is little-endian, as is every machine vkpt runs on.
    std::uint32_t value = 0;
    std::memcpy(&value, bytes.data() + offset, sizeof(value));
    return value;
}

bool startsWithGlbMagic(const Bytes& bytes) {
    return bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
}

bool hasGlbExtension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension == ".glb";
}

// tinygltf checks the container too, but its messages do not say what is wrong ("Invalid glTF
// binary."); a truncated download is common enough to deserve a precise one.
void checkGlbChunks(const Bytes& bytes, std::size_t length) {
    std::size_t offset = kGlbHeaderSize;
    for (int chunk = 0; offset < length; ++chunk) {
        if (length - offset < kGlbChunkHeaderSize) {
            throw GltfProblem("truncated .glb: the header of chunk " + std::to_string(chunk) +
                              " is cut off");
        }
        const std::size_t chunkLength = readU32(bytes, offset);
        const std::size_t remaining = length - offset - kGlbChunkHeaderSize;
        if (chunk == 0 && readU32(bytes, offset + 4) != kGlbChunkJson) {
            throw GltfProblem("not a glTF file: the first .glb chunk is not JSON");
        }
        if (chunkLength > remaining) {
            throw GltfProblem("truncated .glb: chunk " + std::to_string(chunk) + " needs " +
                              std::to_string(chunkLength) + " bytes but only " +
                              std::to_string(remaining) + " remain");
        }
        offset += kGlbChunkHeaderSize + chunkLength;
    }
    if (offset == kGlbHeaderSize) throw GltfProblem("truncated .glb: there is no JSON chunk");
}

void checkGlbContainer(const Bytes& bytes) {
    if (bytes.size() < kGlbHeaderSize) {
        throw GltfProblem("truncated .glb: " + std::to_string(bytes.size()) +
                          " bytes, shorter than its 12-byte header");
    }
    const std::uint32_t version = readU32(bytes, 4);
    if (version != 2) {
        throw GltfProblem(".glb version " + std::to_string(version) +
                          " is not supported, only version 2 (glTF 2.0)");
    }
    const std::size_t length = readU32(bytes, 8);
    if (length > bytes.size()) {
        throw GltfProblem("truncated .glb: its header says " + std::to_string(length) +
                          " bytes but the file has " + std::to_string(bytes.size()));
    }
    checkGlbChunks(bytes, length);
}

// tinygltf hands every image's bytes to this callback while it parses: the file of an external
// `uri` and the bytes of a data: URI. They are kept as they are (as_is), undecoded, because which
// images a material uses is known only once the whole document has been read; gltf_images.cpp
// then decodes those and no others. An image in a buffer view (the usual case in a .glb) is
// skipped here: tinygltf passes its bytes before any buffer view has been checked against its
// buffer, so gltf_images.cpp reads them itself after checkBufferViews.
bool keepEncodedImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
    if (image->bufferView >= 0) return true;
    image->image.assign(bytes, bytes + size);
    image->as_is = true;
    return true;
}

// tinygltf looks for an external file beside the glTF and then in the working directory. Only the
// first is right: a .bin missing beside the scene is reported instead of taken from wherever
// vkpt happens to run. userData is the base directory with a trailing '/', or "".
bool fileExistsBesideScene(const std::string& path, void* userData) {
    const auto& prefix = *static_cast<const std::string*>(userData);
    return path.starts_with(prefix) && tinygltf::FileExists(path, nullptr);
}

std::string directoryPrefix(const std::string& baseDir) {
    if (baseDir.empty() || baseDir.back() == '/') return baseDir;
    return baseDir + "/";
}

tinygltf::Model runTinyGltf(const Bytes& bytes, bool binary, const std::string& baseDir) {
    if (bytes.size() > kMaxFileSize) throw GltfProblem("the file is larger than 4 GiB");
    tinygltf::TinyGLTF parser;
    parser.SetImageLoader(&keepEncodedImage, nullptr);
    std::string prefix = directoryPrefix(baseDir);
    parser.SetFsCallbacks({&fileExistsBesideScene, &tinygltf::ExpandFilePath,
                           &tinygltf::ReadWholeFile, &tinygltf::WriteWholeFile, &prefix});
    tinygltf::Model model;
    std::string error;
    std::string warning; // only about image files, which gltf_images.cpp reports if used
    const auto size = static_cast<unsigned int>(bytes.size());
    const bool ok =
        binary ? parser.LoadBinaryFromMemory(&model, &error, &warning, bytes.data(), size, baseDir)
               : parser.LoadASCIIFromString(&model, &error, &warning,
                                            reinterpret_cast<const char*>(bytes.data()), size,
                                            baseDir);
    if (!ok) throw GltfProblem(describeTinyGltfError(error, baseDir));
    return model;
}

std::string trim(const std::string& text) {
    const auto first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos) return "";
    return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::string withoutPrefix(const std::string& text, const std::string& prefix) {
    return !prefix.empty() && text.starts_with(prefix) ? text.substr(prefix.size()) : text;
}

// A file name from the glTF, short enough for a one-line message.
std::string quotedName(const std::string& name) {
    constexpr std::size_t kMaxName = 60;
    return "'" + (name.size() > kMaxName ? name.substr(0, kMaxName) + "..." : name) + "'";
}

std::string describeMissingFile(const std::string& name) {
    // tinygltf takes a data URI that it cannot decode for a file name.
    if (name.starts_with("data:")) return "a buffer's data URI is malformed";
    return "cannot find the buffer file " + quotedName(name);
}

// One line of tinygltf's error text in our words; unknown lines keep theirs.
std::string describeErrorLine(const std::string& line, const std::string& baseDir) {
    static const std::regex jsonError(R"(^\[json\.exception\.([a-z_]+)\.\d+\] (.*)$)");
    static const std::regex notFound(R"(^File not found : (.*)$)");
    static const std::regex sizeMismatch(
        R"(^File size mismatch : (.*), requestedBytes (\d+), but got (\d+)$)");
    static const std::regex binTooShort(R"(^Invalid `byteLength'.*= (\d+), binary size = (\d+)$)");
    std::smatch m;
    if (std::regex_match(line, m, jsonError)) {
        return m.str(1) == "parse_error" ? "not a glTF file: invalid JSON (" + m.str(2) + ")"
                                         : "invalid JSON value (" + m.str(2) + ")";
    }
    if (std::regex_match(line, m, notFound)) return describeMissingFile(m.str(1));
    if (std::regex_match(line, m, sizeMismatch)) {
        return "the buffer file " + quotedName(withoutPrefix(m.str(1), directoryPrefix(baseDir))) +
               " has " + m.str(3) + " bytes but the buffer's byteLength is " + m.str(2);
    }
    if (std::regex_match(line, m, binTooShort)) {
        return "a buffer's byteLength " + m.str(1) + " exceeds the .glb BIN chunk (" + m.str(2) +
               " bytes)";
    }
    if (line.starts_with("Failed to decode 'uri'")) {
        return "a buffer's data URI is not base64 data of its byteLength";
    }
    if (line.starts_with("\"asset\" object not found")) {
        return "not a glTF file: no \"asset\" object";
    }
    if (line.starts_with("Root element is not a JSON object")) {
        return "not a glTF file: the JSON root is not an object";
    }
    if (line.starts_with("JSON string too short")) return "not a glTF file: too short";
    return "invalid glTF: " + line;
}

// tinygltf's error text (several lines in its own words, possibly with a whole data URI in it) as
// one short line in ours. baseDir is stripped from the file paths it names.
std::string describeTinyGltfError(const std::string& error, const std::string& baseDir) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (start <= error.size()) {
        std::size_t end = error.find('\n', start);
        if (end == std::string::npos) end = error.size();
        std::string line = trim(error.substr(start, std::min(end - start, kMaxMessageLine)));
        if (!line.empty()) {
            std::string described = describeErrorLine(line, baseDir);
            if (std::find(parts.begin(), parts.end(), described) == parts.end()) {
                parts.push_back(std::move(described));
            }
        }
        start = end + 1;
    }
    if (parts.empty()) return "tinygltf failed without a message";
    std::string joined = parts.front();
    for (std::size_t i = 1; i < parts.size(); ++i)
        joined += "; " + parts[i];
    return joined;
}

void appendU32(Bytes& bytes, std::uint32_t value) {
    const auto* first = reinterpret_cast<const unsigned char*>(&value);
    bytes.insert(bytes.end(), first, first + sizeof(value));
}

// The .glb's JSON chunk (checkGlbContainer has checked that it is there and whole).
std::string_view glbJson(const Bytes& bytes) {
    const std::size_t length = readU32(bytes, kGlbHeaderSize);
    return {reinterpret_cast<const char*>(bytes.data()) + kGlbHeaderSize + kGlbChunkHeaderSize,
            length};
}

// The .glb with its JSON chunk replaced (padded with spaces to 4 bytes, as the format asks) and
// every other chunk kept.
Bytes replaceGlbJson(const Bytes& bytes, const std::string& json) {
    const std::size_t oldEnd =
        kGlbHeaderSize + kGlbChunkHeaderSize + readU32(bytes, kGlbHeaderSize);
    const std::size_t length = readU32(bytes, 8);
    std::string padded = json;
    padded.resize((padded.size() + 3) / 4 * 4, ' ');
    Bytes rebuilt(bytes.begin(), bytes.begin() + 8);
    appendU32(rebuilt, 0); // the total length, set below
    appendU32(rebuilt, static_cast<std::uint32_t>(padded.size()));
    appendU32(rebuilt, kGlbChunkJson);
    rebuilt.insert(rebuilt.end(), padded.begin(), padded.end());
    rebuilt.insert(rebuilt.end(), bytes.begin() + static_cast<std::ptrdiff_t>(oldEnd),
                   bytes.begin() + static_cast<std::ptrdiff_t>(length));
    const auto total = static_cast<std::uint32_t>(std::min(rebuilt.size(), kMaxFileSize));
    std::memcpy(rebuilt.data() + 8, &total, sizeof(total));
    return rebuilt;
}

// The JSON as tinygltf should see it, after the required extensions have been checked.
std::optional<JsonPrepass> prepass(Bytes& bytes, bool binary) {
    const std::string_view json =
        binary ? glbJson(bytes)
               : std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    std::optional<JsonPrepass> result = prepassJson(json);
    if (!result) return std::nullopt;
    checkRequiredExtensions(result->extensionsRequired);
    if (result->json != json) {
        bytes = binary ? replaceGlbJson(bytes, result->json)
                       : Bytes(result->json.begin(), result->json.end());
    }
    return result;
}

tinygltf::Model parseAndRestore(Bytes bytes, bool binary, const std::string& baseDir) {
    const std::optional<JsonPrepass> prepared = prepass(bytes, binary);
    tinygltf::Model model = runTinyGltf(bytes, binary, baseDir);
    if (prepared) restoreSetAside(*prepared, model);
    decodeMeshoptBufferViews(model);
    return model;
}

} // namespace

tinygltf::Model parseGltfFile(const std::string& path) {
    Bytes bytes = readWholeFile(path);
    const bool binary = startsWithGlbMagic(bytes);
    if (!binary && hasGlbExtension(path)) {
        throw GltfProblem("not a glTF file: a .glb file starts with 'glTF'");
    }
    if (binary) checkGlbContainer(bytes);
    const std::string baseDir = std::filesystem::path(path).parent_path().string();
    try {
        return parseAndRestore(std::move(bytes), binary, baseDir);
    } catch (const GltfProblem&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception& e) {
        // tinygltf 2.7.0 throws on some malformed input (std::vector::at, JSON type errors).
        throw GltfProblem(describeTinyGltfError(e.what(), baseDir));
    }
}

} // namespace vkpt::gltf
