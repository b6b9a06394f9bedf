// state_file_read.cpp — a state file read back: the metadata checked first (a foreign or
// truncated file is refused in one line), then every channel the writer wrote, then what a
// well-formed state promises.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <sstream>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStringAttribute.h>

#include "common/errors.h"
#include "state/state_channels.h"
#include "state/state_file.h"

namespace vkpt {

namespace {

using namespace state_channels;

[[noreturn]] void refuse(const std::string& path, const std::string& reason) {
    throw InputError(path + ": " + reason);
}

std::string textAttribute(const Imf::Header& header, const char* name, const std::string& path) {
    const auto* attribute = header.findTypedAttribute<Imf::StringAttribute>(name);
    if (!attribute) refuse(path, std::string("no ") + name + " attribute (not written by vkpt)");
    return attribute->value();
}

std::uint32_t parseCount(const std::string& text, const char* what, const std::string& path) {
    std::istringstream in(text);
    std::uint64_t value = 0;
    if (!(in >> value) || !in.eof() || value > UINT32_MAX)
        refuse(path, std::string("malformed ") + what + " '" + text + "'");
    return std::uint32_t(value);
}

// "[0,8) [8,16)" after the rectangle's four numbers.
std::vector<SampleRange> parseRanges(std::istringstream& in, const std::string& path) {
    std::vector<SampleRange> ranges;
    std::string word;
    while (in >> word) {
        unsigned long long begin = 0, end = 0;
        char close = 0;
        if (std::sscanf(word.c_str(), "[%llu,%llu%c", &begin, &end, &close) != 3 || close != ')' ||
            end < begin || end > UINT32_MAX)
            refuse(path, "malformed sample range '" + word + "' in vkpt.regions");
        ranges.push_back({std::uint32_t(begin), std::uint32_t(end)});
    }
    return ranges;
}

std::vector<Region> parseRegions(const std::string& text, const std::string& path) {
    std::vector<Region> regions;
    std::istringstream all(text);
    for (std::string item; std::getline(all, item, ';');) {
        std::istringstream in(item);
        Region r;
        if (!(in >> r.rect.x0 >> r.rect.y0 >> r.rect.x1 >> r.rect.y1) || r.rect.empty())
            refuse(path, "malformed region '" + item + "' in vkpt.regions");
        r.ranges = parseRanges(in, path);
        regions.push_back(r);
    }
    return regions;
}

PixelRect rectOf(const Imath::Box2i& b) {
    return {std::uint32_t(b.min.x), std::uint32_t(b.min.y), std::uint32_t(b.max.x + 1),
            std::uint32_t(b.max.y + 1)};
}

void readIdentity(const Imf::Header& header, const std::string& path, RenderState& state) {
    const auto* format = header.findTypedAttribute<Imf::StringAttribute>(kFormatAttribute);
    if (!format) refuse(path, "an OpenEXR image without vkpt's metadata, not a render state");
    if (format->value() != kStateFormat)
        refuse(path, "render state format '" + format->value() + "', this vkpt reads '" +
                         kStateFormat + "'");
    const Imath::Box2i display = header.displayWindow(), data = header.dataWindow();
    if (display.min.x != 0 || display.min.y != 0 || data.min.x < 0 || data.min.y < 0 ||
        data.max.x > display.max.x || data.max.y > display.max.y || data.isEmpty())
        refuse(path, "its data window is not inside a display window from (0, 0)");
    state.identity.width = std::uint32_t(display.max.x + 1);
    state.identity.height = std::uint32_t(display.max.y + 1);
    state.window = rectOf(data);
    state.identity.sceneHash = textAttribute(header, kSceneHashAttribute, path);
    state.identity.settings = textAttribute(header, kSettingsAttribute, path);
    state.identity.seed = parseCount(textAttribute(header, kSeedAttribute, path), "seed", path);
    state.regions = parseRegions(textAttribute(header, kRegionsAttribute, path), path);
    state.origin.program = textAttribute(header, kProgramAttribute, path);
    state.origin.scene = textAttribute(header, kSceneAttribute, path);
    state.origin.task = textAttribute(header, kTaskAttribute, path);
}

template <typename T>
void readInto(const Imf::Header& header, Imf::FrameBuffer& frame, const char* name,
              Imf::PixelType type, std::vector<T>& values, const std::string& path) {
    const Imf::Channel* channel = header.channels().findChannel(name);
    if (!channel) refuse(path, std::string("no channel ") + name);
    if (channel->type != type || channel->xSampling != 1 || channel->ySampling != 1)
        refuse(path, std::string("channel ") + name + " is not of the type vkpt writes");
    frame.insert(name, Imf::Slice::Make(type, values.data(), header.dataWindow()));
}

struct ReadChannels {
    std::vector<float> mean[3], meanLo[3], lumMean, lumMeanLo, m2, m2Lo;
    std::vector<std::uint32_t> count, taken, converged, featureSamples;
    std::vector<float> albedo[3], normal[3], depth;
    std::vector<float> halfMean[2][3], halfMeanLo[2][3];
    std::vector<std::uint32_t> halfCount[2];
    bool hasFeatures = false;

    explicit ReadChannels(std::size_t n) {
        for (int h = 0; h < 2; ++h) {
            halfCount[h].resize(n);
            for (int k = 0; k < 3; ++k) {
                halfMean[h][k].resize(n);
                halfMeanLo[h][k].resize(n);
            }
        }
        for (auto* v : {&lumMean, &lumMeanLo, &m2, &m2Lo, &depth})
            v->resize(n);
        for (auto* v : {&count, &taken, &converged, &featureSamples})
            v->resize(n);
        for (int k = 0; k < 3; ++k)
            for (auto* v : {&mean[k], &meanLo[k], &albedo[k], &normal[k]})
                v->resize(n);
    }
};

void insertSlices(const Imf::Header& header, ReadChannels& r, Imf::FrameBuffer& frame,
                  const std::string& path) {
    // A denoised state keeps its raw mean in raw.*; R, G, B are then the denoised image.
    const bool denoised =
        header.channels().findChannel(std::string(kRawPrefix) + kRgb[0]) != nullptr;
    for (int k = 0; k < 3; ++k) {
        const std::string mean = denoised ? std::string(kRawPrefix) + kRgb[k] : kRgb[k];
        readInto(header, frame, mean.c_str(), Imf::FLOAT, r.mean[k], path);
        readInto(header, frame, (std::string(kMeanLoPrefix) + kRgb[k]).c_str(), Imf::FLOAT,
                 r.meanLo[k], path);
    }
    readInto(header, frame, kCount, Imf::UINT, r.count, path);
    readInto(header, frame, kSamplesTaken, Imf::UINT, r.taken, path);
    readInto(header, frame, kConverged, Imf::UINT, r.converged, path);
    readInto(header, frame, kLuminanceMean, Imf::FLOAT, r.lumMean, path);
    readInto(header, frame, kLuminanceMeanLo, Imf::FLOAT, r.lumMeanLo, path);
    readInto(header, frame, kLuminanceM2, Imf::FLOAT, r.m2, path);
    readInto(header, frame, kLuminanceM2Lo, Imf::FLOAT, r.m2Lo, path);
    for (int h = 0; h < 2; ++h) {
        for (int k = 0; k < 3; ++k) {
            readInto(header, frame, (std::string(kHalfPrefix[h]) + kRgb[k]).c_str(), Imf::FLOAT,
                     r.halfMean[h][k], path);
            readInto(header, frame, (std::string(kHalfLoPrefix[h]) + kRgb[k]).c_str(), Imf::FLOAT,
                     r.halfMeanLo[h][k], path);
        }
        readInto(header, frame, kHalfCount[h], Imf::UINT, r.halfCount[h], path);
    }
    r.hasFeatures = header.channels().findChannel(kDepth) != nullptr;
    if (!r.hasFeatures) return;
    for (int k = 0; k < 3; ++k) {
        readInto(header, frame, (std::string(kAlbedoPrefix) + kRgb[k]).c_str(), Imf::FLOAT,
                 r.albedo[k], path);
        readInto(header, frame, (std::string(kNormalPrefix) + kXyz[k]).c_str(), Imf::FLOAT,
                 r.normal[k], path);
    }
    readInto(header, frame, kDepth, Imf::FLOAT, r.depth, path);
    readInto(header, frame, kFeatureSamples, Imf::UINT, r.featureSamples, path);
}

void fillRecords(const ReadChannels& r, RenderState& state) {
    const std::size_t n = state.window.area();
    state.pixels.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        PixelRecord& p = state.pixels[i];
        for (int k = 0; k < 3; ++k)
            p.mean[k] = joinDouble(r.mean[k][i], r.meanLo[k][i]);
        p.count = r.count[i];
        p.samplesTaken = r.taken[i];
        p.converged = r.converged[i] != 0;
        p.luminanceMean = joinDouble(r.lumMean[i], r.lumMeanLo[i]);
        p.luminanceM2 = joinDouble(r.m2[i], r.m2Lo[i]);
        for (int h = 0; h < 2; ++h) {
            for (int k = 0; k < 3; ++k)
                p.halves[h].mean[k] = joinDouble(r.halfMean[h][k][i], r.halfMeanLo[h][k][i]);
            p.halves[h].count = r.halfCount[h][i];
        }
    }
    if (!r.hasFeatures) return;
    state.features.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        FeatureRecord& f = state.features[i];
        for (int k = 0; k < 3; ++k) {
            f.albedo[k] = r.albedo[k][i];
            f.normal[k] = r.normal[k][i];
        }
        f.depth = r.depth[i];
        f.samples = r.featureSamples[i];
    }
}

// What a well-formed state promises: every region inside the window, counts within the samples
// taken, and a finite, non-negative variance.
void checkConsistent(const RenderState& state, const std::string& path) {
    for (const Region& region : state.regions)
        if (!(boundingRect(region.rect, state.window) == state.window))
            refuse(path, "region " + describeRect(region.rect) + " lies outside the data window");
    for (const PixelRecord& p : state.pixels)
        if (p.count > p.samplesTaken || !(p.luminanceM2 >= 0.0) ||
            p.halves[0].count + std::uint64_t(p.halves[1].count) != p.count)
            refuse(path, "inconsistent pixel moments (a count above the samples taken, a "
                         "negative M2, or halves that do not add up to the count)");
}

RenderState readState(const std::string& path) {
    // Decompression in parallel, as the writer compresses (state_file_write.cpp).
    Imf::InputFile file(path.c_str(), exrThreads());
    RenderState state;
    readIdentity(file.header(), path, state);
    if (!file.isComplete()) refuse(path, "truncated: not every scan line of the image is there");
    ReadChannels channels(state.window.area());
    Imf::FrameBuffer frame;
    insertSlices(file.header(), channels, frame, path);
    file.setFrameBuffer(frame);
    file.readPixels(int(state.window.y0), int(state.window.y1) - 1);
    fillRecords(channels, state);
    checkConsistent(state, path);
    return state;
}

} // namespace

RenderState readStateFile(const std::string& path) {
    errno = 0;
    if (std::FILE* file = std::fopen(path.c_str(), "rb"))
        std::fclose(file);
    else
        refuse(path, std::string("cannot read: ") + std::strerror(errno));
    try {
        return readState(path);
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& error) {
        // OpenEXR's messages: not an image file, a header or pixel data it cannot decode.
        refuse(path, std::string("not a readable OpenEXR render state (") + error.what() + ")");
    }
}

} // namespace vkpt
