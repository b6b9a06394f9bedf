// render_state_test.cpp — the pieces of a distributed render without rendering: task shares,
// Chan's combination against Welford's running moments, the OpenEXR state file read back bit
// for bit (and by a plain OpenEXR reader), and every file and merge that must be refused.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>

#include "../support/test_directory.h"
#include "common/errors.h"
#include "state/atomic_write.h"
#include "state/sample_plan.h"
#include "state/state_file.h"
#include "state/state_merge.h"

namespace vkpt::render_state_test {
namespace {

TEST(TaskShares, AreDisjointAndCoverEverySample) {
    for (std::uint32_t spp : {1u, 7u, 16u, 1000u, 4000000000u})
        for (std::uint32_t n : {1u, 2u, 3u, 7u}) {
            if (n > spp) continue;
            std::uint32_t next = 0;
            for (std::uint32_t k = 0; k < n; ++k) {
                const SampleRange r = taskSampleRange(spp, {k, n});
                EXPECT_EQ(r.begin, next) << spp << " spp, task " << k << "/" << n;
                EXPECT_GE(r.size(), spp / n);
                EXPECT_LE(r.size(), spp / n + 1);
                next = r.end;
            }
            EXPECT_EQ(next, spp);
        }
}

TEST(TaskShares, MalformedTasksAreRefused) {
    for (const char* text : {"", "3", "1/", "/2", "2/2", "0/0", "a/b", "1/2/3", "-1/2"})
        EXPECT_THROW(parseTaskShare(text), InputError) << text;
    EXPECT_EQ(parseTaskShare("6/7").index, 6u);
}

PixelRecord welford(const std::vector<double>& values) {
    PixelRecord r;
    for (double x : values) {
        ++r.count;
        ++r.samplesTaken;
        r.mean += glm::dvec3(x);
        const double delta = x - r.luminanceMean;
        r.luminanceMean += delta / r.count;
        r.luminanceM2 += delta * (x - r.luminanceMean);
    }
    r.mean /= double(std::max(r.count, 1u));
    return r;
}

TEST(PixelRecords, ChanCombinationEqualsOneRunningSum) {
    std::mt19937 random(7);
    std::lognormal_distribution<double> radiance(0.0, 2.0);
    std::vector<double> values(1000);
    for (double& v : values)
        v = radiance(random);
    const PixelRecord all = welford(values);
    for (std::size_t split : {std::size_t(0), std::size_t(1), std::size_t(333), std::size_t(999)}) {
        const PixelRecord a = welford({values.begin(), values.begin() + long(split)});
        const PixelRecord b = welford({values.begin() + long(split), values.end()});
        const PixelRecord c = combineRecords(a, b);
        EXPECT_EQ(c.count, all.count);
        EXPECT_NEAR(c.mean.x, all.mean.x, 1e-13 * all.mean.x);
        EXPECT_NEAR(c.luminanceMean, all.luminanceMean, 1e-13 * all.luminanceMean);
        EXPECT_NEAR(c.luminanceM2, all.luminanceM2, 1e-12 * all.luminanceM2);
    }
}

// The halves of samples [first, first + values.size()): value i has sample index first + i, and
// goes to the half of that index's parity.
PixelRecord withHalves(const std::vector<double>& values, std::uint32_t first) {
    PixelRecord r = welford(values);
    glm::dvec3 sums[2] = {glm::dvec3(0.0), glm::dvec3(0.0)};
    for (std::size_t i = 0; i < values.size(); ++i) {
        const std::uint32_t h = (first + std::uint32_t(i)) & 1u;
        sums[h] += glm::dvec3(values[i]);
        ++r.halves[h].count;
    }
    for (int h = 0; h < 2; ++h)
        r.halves[h].mean =
            r.halves[h].count ? sums[h] / double(r.halves[h].count) : glm::dvec3(0.0);
    return r;
}

// Splits at an odd index too: each part's halves follow the global sample index, so the merged
// halves are the one run's.
TEST(PixelRecords, HalvesCombineToTheOneRunsHalves) {
    std::mt19937 random(11);
    std::lognormal_distribution<double> radiance(0.0, 2.0);
    std::vector<double> values(1001);
    for (double& v : values)
        v = radiance(random);
    const PixelRecord all = withHalves(values, 0);
    EXPECT_EQ(all.halves[0].count, 501u);
    for (std::uint32_t split : {0u, 1u, 333u, 1000u}) {
        const PixelRecord a = withHalves({values.begin(), values.begin() + split}, 0);
        const PixelRecord b = withHalves({values.begin() + split, values.end()}, split);
        const PixelRecord c = combineRecords(a, b);
        for (int h = 0; h < 2; ++h) {
            EXPECT_EQ(c.halves[h].count, all.halves[h].count) << "split " << split;
            EXPECT_NEAR(c.halves[h].mean.x, all.halves[h].mean.x, 1e-13 * all.halves[h].mean.x)
                << "split " << split;
        }
    }
}

FeatureRecord featuresOf(glm::vec3 albedo, glm::vec3 normal, float depth, std::uint32_t samples) {
    FeatureRecord f;
    f.albedo = albedo;
    f.normal = normal;
    f.depth = depth;
    f.samples = samples;
    return f;
}

TEST(FeatureRecords, CombineByTheirSampleCountsAndKeepTheNearestDepth) {
    const FeatureRecord a = featuresOf(glm::vec3(1.0f), glm::vec3(0.0f, 0.0f, 1.0f), 3.0f, 1);
    const FeatureRecord b = featuresOf(glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f), 2.0f, 3);
    const FeatureRecord c = combineFeatures(a, b);
    EXPECT_EQ(c.samples, 4u);
    EXPECT_EQ(c.albedo, glm::vec3(0.25f));
    EXPECT_EQ(c.normal, glm::vec3(0.75f, 0.0f, 0.25f));
    EXPECT_EQ(c.depth, 2.0f);
    // A part without feature samples (no AOVs, or every sample missed) changes nothing but depth.
    const FeatureRecord none;
    EXPECT_EQ(combineFeatures(none, a).albedo, a.albedo);
    EXPECT_EQ(combineFeatures(b, none).normal, b.normal);
    EXPECT_EQ(combineFeatures(b, none).samples, 3u);
    EXPECT_TRUE(std::isinf(combineFeatures(none, none).depth));
}

RenderState sampleState(std::uint32_t seed = 3) {
    RenderState s;
    s.identity = {"0123456789abcdef", "integrator=path", seed, 40, 30};
    s.origin = {"vkpt-ref", "scene.gltf", "1/4"};
    s.window = {5, 7, 21, 18};
    s.regions = {{s.window, {{4, 8}}}};
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> u(0.0, 10.0);
    for (std::size_t i = 0; i < s.window.area(); ++i) {
        PixelRecord p;
        p.mean = glm::dvec3(u(random), u(random), u(random)) / 3.0; // bits beyond a float
        p.luminanceMean = u(random) / 7.0;
        p.luminanceM2 = u(random) / 11.0;
        p.count = 4 - std::uint32_t(i % 2);
        p.samplesTaken = 4;
        p.converged = i % 5 == 0;
        p.halves[0] = {glm::dvec3(u(random), u(random), u(random)) / 3.0, 2};
        p.halves[1] = {glm::dvec3(u(random), u(random), u(random)) / 3.0, p.count - 2};
        s.pixels.push_back(p);
        FeatureRecord f;
        f.albedo = glm::vec3(float(u(random)));
        f.normal = glm::vec3(0.0f, 1.0f, 0.0f);
        f.depth = i % 3 ? float(u(random)) : std::numeric_limits<float>::infinity();
        f.samples = 4;
        s.features.push_back(f);
    }
    return s;
}

class StateFile : public test::TestDirectory {
protected:
    StateFile() : TestDirectory("vkpt_state_file") {}

    // The one-line refusal: InputError starting with the path.
    void expectRefused(const std::string& file, const std::string& reason) {
        try {
            readStateFile(file);
            ADD_FAILURE() << file << " was read";
        } catch (const InputError& error) {
            const std::string message = error.what();
            EXPECT_EQ(message.rfind(file + ": ", 0), 0u) << message;
            EXPECT_NE(message.find(reason), std::string::npos) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    }
};

TEST_F(StateFile, RoundTripsTheMomentsTheFeaturesAndTheMetadata) {
    const RenderState written = sampleState();
    writeStateFile(written, path("part.exr"));
    const RenderState read = readStateFile(path("part.exr"));
    EXPECT_EQ(read.identity, written.identity);
    EXPECT_EQ(read.origin.program, "vkpt-ref");
    EXPECT_EQ(read.origin.task, "1/4");
    EXPECT_EQ(read.window, written.window);
    ASSERT_EQ(read.regions.size(), 1u);
    EXPECT_EQ(read.regions[0].rect, written.window);
    EXPECT_EQ(read.regions[0].ranges, written.regions[0].ranges);
    ASSERT_EQ(read.pixels.size(), written.pixels.size());
    for (std::size_t i = 0; i < read.pixels.size(); ++i) {
        const PixelRecord& a = read.pixels[i];
        const PixelRecord& b = written.pixels[i];
        // Two floats hold about 48 of a double's 53 bits.
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(a.mean[c], b.mean[c], 1e-14 * b.mean[c]);
        EXPECT_NEAR(a.luminanceMean, b.luminanceMean, 1e-14 * b.luminanceMean);
        EXPECT_NEAR(a.luminanceM2, b.luminanceM2, 1e-14 * b.luminanceM2);
        EXPECT_EQ(a.count, b.count);
        EXPECT_EQ(a.samplesTaken, b.samplesTaken);
        EXPECT_EQ(a.converged, b.converged);
        for (int h = 0; h < 2; ++h) {
            EXPECT_EQ(a.halves[h].count, b.halves[h].count);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(a.halves[h].mean[c], b.halves[h].mean[c], 1e-14 * b.halves[h].mean[c]);
        }
        EXPECT_EQ(read.features[i].albedo, written.features[i].albedo);
        EXPECT_EQ(read.features[i].normal, written.features[i].normal);
        EXPECT_EQ(read.features[i].depth, written.features[i].depth);
        EXPECT_EQ(read.features[i].samples, written.features[i].samples);
    }
}

// Any OpenEXR reader sees the image: R, G, B are the means, in the crop's data window; the
// layers half0 and half1 the halves' means.
TEST_F(StateFile, APlainOpenExrReaderSeesTheImage) {
    const RenderState written = sampleState();
    writeStateFile(written, path("part.exr"));
    Imf::InputFile file(path("part.exr").c_str());
    const Imath::Box2i data = file.header().dataWindow();
    EXPECT_EQ(data.min.x, 5);
    EXPECT_EQ(data.max.y, 17);
    EXPECT_EQ(file.header().displayWindow().max.x, 39);
    std::vector<float> red(written.window.area()), oddGreen(written.window.area());
    Imf::FrameBuffer frame;
    frame.insert("R", Imf::Slice::Make(Imf::FLOAT, red.data(), data));
    frame.insert("half1.G", Imf::Slice::Make(Imf::FLOAT, oddGreen.data(), data));
    file.setFrameBuffer(frame);
    file.readPixels(data.min.y, data.max.y);
    for (std::size_t i = 0; i < red.size(); ++i) {
        EXPECT_EQ(red[i], float(written.pixels[i].mean.r));
        EXPECT_EQ(oddGreen[i], float(written.pixels[i].halves[1].mean.g));
    }
}

TEST_F(StateFile, RefusesMissingForeignAndTruncatedFiles) {
    expectRefused(path("missing.exr"), "cannot read: No such file or directory");
    std::ofstream(path("text.exr")) << "not an image\n";
    expectRefused(path("text.exr"), "not a readable OpenEXR render state");
    // An OpenEXR image that vkpt did not write.
    {
        Imf::Header header(8, 8);
        header.channels().insert("R", Imf::Channel(Imf::FLOAT));
        std::vector<float> red(64, 0.5f);
        Imf::FrameBuffer frame;
        frame.insert("R", Imf::Slice::Make(Imf::FLOAT, red.data(), header.dataWindow()));
        Imf::OutputFile out(path("foreign.exr").c_str(), header);
        out.setFrameBuffer(frame);
        out.writePixels(8);
    }
    expectRefused(path("foreign.exr"), "an OpenEXR image without vkpt's metadata");
    RenderState uneven = sampleState();
    ++uneven.pixels[7].halves[1].count; // the halves now hold one sample more than the pixel
    writeStateFile(uneven, path("uneven.exr"));
    expectRefused(path("uneven.exr"), "halves that do not add up to the count");
    writeStateFile(sampleState(), path("whole.exr"));
    std::filesystem::copy_file(path("whole.exr"), path("truncated.exr"));
    std::filesystem::resize_file(path("truncated.exr"),
                                 std::filesystem::file_size(path("whole.exr")) * 2 / 3);
    // OpenEXR notices either in its chunk table ("truncated") or while reading the pixels.
    try {
        readStateFile(path("truncated.exr"));
        ADD_FAILURE() << "a truncated file was read";
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()).rfind(path("truncated.exr") + ": ", 0), 0u);
    }
}

TEST_F(StateFile, AFailedWriteLeavesThePreviousFileWhole) {
    writeStateFile(sampleState(1), path("part.exr"));
    // A writer that dies half-way, as a full disk would make it.
    const auto halfWrite = [](const std::string& temporary) {
        std::ofstream(temporary) << "half a file";
        throw std::runtime_error("No space left on device");
    };
    try {
        writeAtomically(path("part.exr"), halfWrite);
        ADD_FAILURE() << "the failed write was not reported";
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()),
                  path("part.exr") + ": cannot write: No space left on device");
    }
    EXPECT_EQ(readStateFile(path("part.exr")).identity.seed, 1u);
    for (const auto& entry : std::filesystem::directory_iterator(dir_))
        EXPECT_EQ(entry.path().filename().string().find(".partial"), std::string::npos)
            << entry.path();
}

// --- merging ---------------------------------------------------------------------------------

StatePart taskPart(const std::string& name, SampleRange range) {
    RenderState s = sampleState();
    s.regions = {{s.window, {range}}};
    return {name, s};
}

std::string mergeRefusal(std::vector<StatePart> parts) {
    try {
        mergeStates(std::move(parts));
    } catch (const InputError& error) {
        return error.what();
    }
    return "merged";
}

TEST(StateMerge, RefusesPartsOfAnotherRender) {
    const StatePart a = taskPart("a.exr", {0, 4});
    StatePart b = taskPart("b.exr", {4, 8});
    b.state.identity.sceneHash = "fedcba9876543210";
    EXPECT_EQ(mergeRefusal({a, b}).rfind("b.exr: another scene than a.exr", 0), 0u);
    b = taskPart("b.exr", {4, 8});
    b.state.identity.settings = "integrator=direct";
    EXPECT_EQ(mergeRefusal({a, b}).rfind("b.exr: settings 'integrator=direct' differ", 0), 0u);
    b = taskPart("b.exr", {4, 8});
    b.state.identity.seed = 9;
    EXPECT_EQ(mergeRefusal({a, b}).rfind("b.exr: seed 9 differs from a.exr's seed 3", 0), 0u);
    b = taskPart("b.exr", {4, 8});
    b.state.identity.width = 64;
    EXPECT_EQ(mergeRefusal({a, b}).rfind("b.exr: image size 64x30 differs", 0), 0u);
}

TEST(StateMerge, RefusesSamplesTakenTwice) {
    const std::string message = mergeRefusal(
        {taskPart("a.exr", {0, 4}), taskPart("b.exr", {8, 12}), taskPart("c.exr", {3, 8})});
    EXPECT_EQ(message, "c.exr: its samples [3,8) of pixels x 5..21, y 7..18 are also in a.exr");
    // Disjoint rectangles may share sample indices: those are other pixels' samples.
    StatePart left = taskPart("left.exr", {0, 4});
    StatePart right = taskPart("right.exr", {0, 4});
    right.state.window = right.state.regions[0].rect = {21, 7, 30, 18};
    right.state.pixels.resize(right.state.window.area());
    right.state.features.resize(right.state.window.area());
    EXPECT_EQ(mergeRefusal({left, right}), "merged");
}

// Each part's AOVs cover its own samples: the merge weighs them as it weighs the moments, and a
// part saved without AOV layers adds no feature samples.
TEST(StateMerge, FeaturesAverageOverThePartsThatHaveThem) {
    StatePart a = taskPart("a.exr", {0, 4}), b = taskPart("b.exr", {4, 8}),
              c = taskPart("c.exr", {8, 12});
    for (FeatureRecord& f : b.state.features)
        f.albedo = glm::vec3(0.5f) - f.albedo;
    c.state.features.clear();
    const RenderState merged = mergeStates({a, b, c});
    ASSERT_EQ(merged.features.size(), a.state.features.size());
    for (std::size_t i = 0; i < merged.features.size(); ++i) {
        EXPECT_EQ(merged.features[i].samples, 8u);
        EXPECT_NEAR(merged.features[i].albedo.x, 0.25f, 1e-6f);
        EXPECT_EQ(merged.features[i].depth,
                  std::min(a.state.features[i].depth, b.state.features[i].depth));
    }
    StatePart d = taskPart("d.exr", {0, 4});
    d.state.features.clear();
    EXPECT_TRUE(mergeStates({c, d}).features.empty());
}

TEST(StateMerge, TheOrderOfThePartsDoesNotMatter) {
    const StatePart a = taskPart("a.exr", {0, 4}), b = taskPart("b.exr", {4, 8}),
                    c = taskPart("c.exr", {8, 12});
    const RenderState abc = mergeStates({a, b, c});
    const RenderState cab = mergeStates({c, a, b});
    ASSERT_EQ(abc.regions.size(), 1u);
    EXPECT_EQ(abc.regions[0].ranges, (std::vector<SampleRange>{{0, 12}}));
    for (std::size_t i = 0; i < abc.pixels.size(); ++i) {
        EXPECT_EQ(abc.pixels[i].mean, cab.pixels[i].mean);
        EXPECT_EQ(abc.pixels[i].luminanceM2, cab.pixels[i].luminanceM2);
        EXPECT_EQ(abc.pixels[i].count, 3 * a.state.pixels[i].count);
    }
}

} // namespace
} // namespace vkpt::render_state_test
