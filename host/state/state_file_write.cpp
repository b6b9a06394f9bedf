// state_file_write.cpp — a state as OpenEXR (the scan-line API of OpenEXR 3): one FLOAT or UINT
// slice per channel, string attributes for the metadata, the crop as the data window inside the
// display window of the whole image. Lossless ZIP compression, so the moments round-trip bit for
// bit.
#include <deque>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>

#include "common/errors.h"
#include "state/atomic_write.h"
#include "state/state_channels.h"
#include "state/state_file.h"

namespace vkpt {

namespace {

using namespace state_channels;

// Every channel of the file: name, type and one value per window pixel. Deques, so that the
// reference addFloat and addUint return stays valid while more channels are added (a vector's
// growth moved the channels away from the references the fillers held: a state with the
// denoised image's three more channels crashed as an .exr --preview wrote it).
struct Channels {
    std::deque<std::pair<std::string, std::vector<float>>> floats;
    std::deque<std::pair<std::string, std::vector<std::uint32_t>>> uints;

    std::vector<float>& addFloat(const std::string& name, std::size_t n) {
        return floats.emplace_back(name, std::vector<float>(n, 0.0f)).second;
    }
    std::vector<std::uint32_t>& addUint(const std::string& name, std::size_t n) {
        return uints.emplace_back(name, std::vector<std::uint32_t>(n, 0)).second;
    }
};

void addImageChannels(const RenderState& state, Channels& c) {
    const std::size_t n = state.pixels.size();
    std::vector<float>* colour[3];
    std::vector<float>* colourLo[3];
    std::vector<float>* shown[3];
    const bool denoised = !state.denoised.empty();
    for (int k = 0; k < 3; ++k) {
        colour[k] = &c.addFloat(denoised ? std::string(kRawPrefix) + kRgb[k] : kRgb[k], n);
        colourLo[k] = &c.addFloat(std::string(kMeanLoPrefix) + kRgb[k], n);
        shown[k] = denoised ? &c.addFloat(kRgb[k], n) : nullptr;
    }
    auto& sampleCount = c.addFloat(kSampleCount, n);
    auto& variance = c.addFloat(kVariance, n);
    for (std::size_t i = 0; i < n; ++i) {
        const PixelRecord& p = state.pixels[i];
        for (int k = 0; k < 3; ++k) {
            const SplitDouble s = splitDouble(p.mean[k]);
            (*colour[k])[i] = s.hi;
            (*colourLo[k])[i] = s.lo;
            if (denoised) (*shown[k])[i] = state.denoised[i][k];
        }
        sampleCount[i] = float(p.count);
        variance[i] = saturated(varianceOfMean(p));
    }
}

void addMomentChannels(const RenderState& state, Channels& c) {
    const std::size_t n = state.pixels.size();
    auto& count = c.addUint(kCount, n);
    auto& taken = c.addUint(kSamplesTaken, n);
    auto& converged = c.addUint(kConverged, n);
    auto& mean = c.addFloat(kLuminanceMean, n);
    auto& meanLo = c.addFloat(kLuminanceMeanLo, n);
    auto& m2 = c.addFloat(kLuminanceM2, n);
    auto& m2Lo = c.addFloat(kLuminanceM2Lo, n);
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

// Each half's mean as hi (the layer a denoiser reads) + lo, so that merges stay exact, and its
// count.
void addHalfChannels(const RenderState& state, Channels& c) {
    const std::size_t n = state.pixels.size();
    for (int h = 0; h < 2; ++h) {
        std::vector<float>* hi[3];
        std::vector<float>* lo[3];
        for (int k = 0; k < 3; ++k) {
            hi[k] = &c.addFloat(std::string(kHalfPrefix[h]) + kRgb[k], n);
            lo[k] = &c.addFloat(std::string(kHalfLoPrefix[h]) + kRgb[k], n);
        }
        auto& count = c.addUint(kHalfCount[h], n);
        for (std::size_t i = 0; i < n; ++i) {
            const HalfEstimate& half = state.pixels[i].halves[h];
            for (int k = 0; k < 3; ++k) {
                const SplitDouble s = splitDouble(half.mean[k]);
                (*hi[k])[i] = s.hi;
                (*lo[k])[i] = s.lo;
            }
            count[i] = half.count;
        }
    }
}

void addFeatureChannels(const RenderState& state, Channels& c) {
    if (state.features.empty()) return;
    const std::size_t n = state.features.size();
    std::vector<float>* albedo[3];
    std::vector<float>* normal[3];
    for (int k = 0; k < 3; ++k) {
        albedo[k] = &c.addFloat(std::string(kAlbedoPrefix) + kRgb[k], n);
        normal[k] = &c.addFloat(std::string(kNormalPrefix) + kXyz[k], n);
    }
    auto& depth = c.addFloat(kDepth, n);
    auto& samples = c.addUint(kFeatureSamples, n);
    for (std::size_t i = 0; i < n; ++i) {
        const FeatureRecord& f = state.features[i];
        for (int k = 0; k < 3; ++k) {
            (*albedo[k])[i] = f.albedo[k];
            (*normal[k])[i] = f.normal[k];
        }
        depth[i] = f.depth;
        samples[i] = f.samples;
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
    // zlib's fastest level: the 1024² preview's state writes in 0.58 s instead of 0.66 s at
    // OpenEXR's default (4), and takes 21.2 MB instead of 20.4 MB (stored: 96 MB).
    header.zipCompressionLevel() = 1;
    const auto text = [&](const char* name, const std::string& value) {
        header.insert(name, Imf::StringAttribute(value));
    };
    text(kFormatAttribute, kStateFormat);
    text(kSceneHashAttribute, state.identity.sceneHash);
    text(kSettingsAttribute, state.identity.settings);
    text(kSeedAttribute, std::to_string(state.identity.seed));
    text(kRegionsAttribute, regionsText(state.regions));
    text(kProgramAttribute, state.origin.program);
    text(kSceneAttribute, state.origin.scene);
    text(kTaskAttribute, state.origin.task);
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
    // ZIP compresses blocks of 16 scan lines independently, so OpenEXR's threads share them.
    Imf::OutputFile file(path.c_str(), header, exrThreads());
    file.setFrameBuffer(frame);
    file.writePixels(int(state.window.height()));
}

} // namespace

void writeStateFile(const RenderState& state, const std::string& path) {
    VKPT_ASSERT(state.pixels.size() == state.window.area() && !state.window.empty(),
                "a state holds one record per window pixel");
    VKPT_ASSERT(state.features.empty() || state.features.size() == state.pixels.size(),
                "features cover the window");
    VKPT_ASSERT(state.denoised.empty() || state.denoised.size() == state.pixels.size(),
                "the denoised image covers the window");
    Channels channels;
    addImageChannels(state, channels);
    addFeatureChannels(state, channels);
    addMomentChannels(state, channels);
    addHalfChannels(state, channels);
    writeAtomically(
        path, [&](const std::string& temporary) { writeChannels(state, channels, temporary); });
}

} // namespace vkpt
