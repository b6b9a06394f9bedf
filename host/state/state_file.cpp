// state_file.cpp — OpenEXR (the scan-line API of OpenEXR 3): one FLOAT or UINT slice per
// channel, string attributes for the metadata, the crop as the data window inside the display
// window of the whole image. Lossless ZIP compression, so the moments round-trip bit for bit.
#include "state/state_file.h"

#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>

#include "common/errors.h"
#include "state/atomic_write.h"

namespace vkpt {

namespace {

// A double as two floats, hi + lo: hi is the float nearest the value, lo the float nearest
// the rest, together about 48 bits of the double's 53 (Dekker's double-float).
struct SplitDouble {
    float hi = 0.0f;
    float lo = 0.0f;
};

float saturated(double value) {
    if (std::isnan(value)) return 0.0f;
    return float(std::fmax(-double(FLT_MAX), std::fmin(value, double(FLT_MAX))));
}

SplitDouble splitDouble(double value) {
    SplitDouble s;
    s.hi = saturated(value);
    s.lo = saturated(value - double(s.hi));
    return s;
}

double joinDouble(float hi, float lo) {
    return double(hi) + double(lo);
}

// Every channel of the file: name, type and one value per window pixel.
struct Channels {
    std::vector<std::pair<std::string, std::vector<float>>> floats;
    std::vector<std::pair<std::string, std::vector<std::uint32_t>>> uints;

    std::vector<float>& addFloat(const std::string& name, std::size_t n) {
        return floats.emplace_back(name, std::vector<float>(n, 0.0f)).second;
    }
    std::vector<std::uint32_t>& addUint(const std::string& name, std::size_t n) {
        return uints.emplace_back(name, std::vector<std::uint32_t>(n, 0)).second;
    }
};

constexpr const char* kRgb[3] = {"R", "G", "B"};
constexpr const char* kXyz[3] = {"X", "Y", "Z"};

void addImageChannels(const RenderState& state, Channels& c) {
    const std::size_t n = state.pixels.size();
    std::vector<float>* colour[3];
    std::vector<float>* colourLo[3];
    for (int k = 0; k < 3; ++k) {
        colour[k] = &c.addFloat(kRgb[k], n);
        colourLo[k] = &c.addFloat(std::string("vkpt.meanLo.") + kRgb[k], n);
    }
    auto& sampleCount = c.addFloat("sampleCount", n);
    auto& variance = c.addFloat("variance", n);
    for (std::size_t i = 0; i < n; ++i) {
        const PixelRecord& p = state.pixels[i];
        for (int k = 0; k < 3; ++k) {
            const SplitDouble s = splitDouble(p.mean[k]);
            (*colour[k])[i] = s.hi;
            (*colourLo[k])[i] = s.lo;
        }
        sampleCount[i] = float(p.count);
        variance[i] = saturated(varianceOfMean(p));
    }
}

void addMomentChannels(const RenderState& state, Channels& c) {
    const std::size_t n = state.pixels.size();
    auto& count = c.addUint("vkpt.count", n);
    auto& taken = c.addUint("vkpt.samplesTaken", n);
    auto& converged = c.addUint("vkpt.converged", n);
    auto& mean = c.addFloat("vkpt.luminanceMean", n);
    auto& meanLo = c.addFloat("vkpt.luminanceMeanLo", n);
    auto& m2 = c.addFloat("vkpt.luminanceM2", n);
    auto& m2Lo = c.addFloat("vkpt.luminanceM2Lo", n);
    for (std::size_t i = 0; i < n; ++i) {
        const PixelRecord& p = state.pixels[i];
        count[i] = p.count;
        taken[i] = p.samplesTaken;
        converged[i] = p.converged ? 1u : 0u;
        const SplitDouble m = splitDouble(p.luminanceMean), v = splitDouble(p.luminanceM2);
        mean[i] = m.hi;
        meanLo[i] = m.lo;
        m2[i] = v.hi;
        m2Lo[i] = v.lo;
    }
}

void addFeatureChannels(const RenderState& state, Channels& c) {
    if (state.features.empty()) return;
    const std::size_t n = state.features.size();
    std::vector<float>* albedo[3];
    std::vector<float>* normal[3];
    for (int k = 0; k < 3; ++k) {
        albedo[k] = &c.addFloat(std::string("albedo.") + kRgb[k], n);
        normal[k] = &c.addFloat(std::string("normal.") + kXyz[k], n);
    }
    auto& depth = c.addFloat("Z", n);
    for (std::size_t i = 0; i < n; ++i) {
        const FeatureRecord& f = state.features[i];
        for (int k = 0; k < 3; ++k) {
            (*albedo[k])[i] = f.albedo[k];
            (*normal[k])[i] = f.normal[k];
        }
        depth[i] = f.depth;
    }
}

std::string regionsText(const std::vector<Region>& regions) {
    std::string text;
    for (const Region& r : regions) {
        if (!text.empty()) text += "; ";
        text += std::to_string(r.rect.x0) + " " + std::to_string(r.rect.y0) + " " +
                std::to_string(r.rect.x1) + " " + std::to_string(r.rect.y1) + " " +
                describeRanges(r.ranges);
    }
    return text;
}

Imath::Box2i box(const PixelRect& r) {
    return Imath::Box2i(Imath::V2i(int(r.x0), int(r.y0)), Imath::V2i(int(r.x1) - 1, int(r.y1) - 1));
}

Imf::Header makeHeader(const RenderState& state) {
    Imf::Header header(box(fullFrame(state.identity.width, state.identity.height)),
                       box(state.window));
    header.compression() = Imf::ZIP_COMPRESSION;
    const auto text = [&](const char* name, const std::string& value) {
        header.insert(name, Imf::StringAttribute(value));
    };
    text("vkpt.format", kStateFormat);
    text("vkpt.sceneHash", state.identity.sceneHash);
    text("vkpt.settings", state.identity.settings);
    text("vkpt.seed", std::to_string(state.identity.seed));
    text("vkpt.regions", regionsText(state.regions));
    text("vkpt.program", state.origin.program);
    text("vkpt.scene", state.origin.scene);
    text("vkpt.task", state.origin.task);
    return header;
}

void writeChannels(const RenderState& state, Channels& channels, const std::string& path) {
    Imf::Header header = makeHeader(state);
    Imf::FrameBuffer frame;
    const Imath::Box2i window = box(state.window);
    for (auto& [name, values] : channels.floats) {
        header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        frame.insert(name, Imf::Slice::Make(Imf::FLOAT, values.data(), window));
    }
    for (auto& [name, values] : channels.uints) {
        header.channels().insert(name, Imf::Channel(Imf::UINT));
        frame.insert(name, Imf::Slice::Make(Imf::UINT, values.data(), window));
    }
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(int(state.window.height()));
}

// --- reading -------------------------------------------------------------------------------

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
    const auto* format = header.findTypedAttribute<Imf::StringAttribute>("vkpt.format");
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
    state.identity.sceneHash = textAttribute(header, "vkpt.sceneHash", path);
    state.identity.settings = textAttribute(header, "vkpt.settings", path);
    state.identity.seed = parseCount(textAttribute(header, "vkpt.seed", path), "seed", path);
    state.regions = parseRegions(textAttribute(header, "vkpt.regions", path), path);
    state.origin.program = textAttribute(header, "vkpt.program", path);
    state.origin.scene = textAttribute(header, "vkpt.scene", path);
    state.origin.task = textAttribute(header, "vkpt.task", path);
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
    std::vector<std::uint32_t> count, taken, converged;
    std::vector<float> albedo[3], normal[3], depth;
    bool hasFeatures = false;

    explicit ReadChannels(std::size_t n) {
        for (auto* v : {&lumMean, &lumMeanLo, &m2, &m2Lo, &depth})
            v->resize(n);
        for (auto* v : {&count, &taken, &converged})
            v->resize(n);
        for (int k = 0; k < 3; ++k)
            for (auto* v : {&mean[k], &meanLo[k], &albedo[k], &normal[k]})
                v->resize(n);
    }
};

void insertSlices(const Imf::Header& header, ReadChannels& r, Imf::FrameBuffer& frame,
                  const std::string& path) {
    for (int k = 0; k < 3; ++k) {
        readInto(header, frame, kRgb[k], Imf::FLOAT, r.mean[k], path);
        readInto(header, frame, (std::string("vkpt.meanLo.") + kRgb[k]).c_str(), Imf::FLOAT,
                 r.meanLo[k], path);
    }
    readInto(header, frame, "vkpt.count", Imf::UINT, r.count, path);
    readInto(header, frame, "vkpt.samplesTaken", Imf::UINT, r.taken, path);
    readInto(header, frame, "vkpt.converged", Imf::UINT, r.converged, path);
    readInto(header, frame, "vkpt.luminanceMean", Imf::FLOAT, r.lumMean, path);
    readInto(header, frame, "vkpt.luminanceMeanLo", Imf::FLOAT, r.lumMeanLo, path);
    readInto(header, frame, "vkpt.luminanceM2", Imf::FLOAT, r.m2, path);
    readInto(header, frame, "vkpt.luminanceM2Lo", Imf::FLOAT, r.m2Lo, path);
    r.hasFeatures = header.channels().findChannel("Z") != nullptr;
    if (!r.hasFeatures) return;
    for (int k = 0; k < 3; ++k) {
        readInto(header, frame, (std::string("albedo.") + kRgb[k]).c_str(), Imf::FLOAT, r.albedo[k],
                 path);
        readInto(header, frame, (std::string("normal.") + kXyz[k]).c_str(), Imf::FLOAT, r.normal[k],
                 path);
    }
    readInto(header, frame, "Z", Imf::FLOAT, r.depth, path);
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
    }
}

// What a well-formed state promises: every region inside the window, counts within the samples
// taken, and a finite, non-negative variance.
void checkConsistent(const RenderState& state, const std::string& path) {
    for (const Region& region : state.regions)
        if (!(boundingRect(region.rect, state.window) == state.window))
            refuse(path, "region " + describeRect(region.rect) + " lies outside the data window");
    for (const PixelRecord& p : state.pixels)
        if (p.count > p.samplesTaken || !(p.luminanceM2 >= 0.0))
            refuse(path, "inconsistent pixel moments (a count above the samples taken, or a "
                         "negative M2)");
}

RenderState readState(const std::string& path) {
    Imf::InputFile file(path.c_str());
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

void writeStateFile(const RenderState& state, const std::string& path) {
    VKPT_ASSERT(state.pixels.size() == state.window.area() && !state.window.empty(),
                "a state holds one record per window pixel");
    VKPT_ASSERT(state.features.empty() || state.features.size() == state.pixels.size(),
                "features cover the window");
    Channels channels;
    addImageChannels(state, channels);
    addFeatureChannels(state, channels);
    addMomentChannels(state, channels);
    writeAtomically(
        path, [&](const std::string& temporary) { writeChannels(state, channels, temporary); });
}

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
