// layout_round_trip_test.cpp — the GLSL (std430) and C++ layouts of every struct in
// shared/host_device.h and of the wavefront records in lib/wavefront.h agree byte for byte: the
// device reads each field of C++-written structs and writes it out as words in declaration order,
// and writes each field of structs from words; both must match the C++ bytes exactly. Every word is
// distinct, so a swapped or shifted field cannot go unnoticed.
#include "gpu_test_support.h"
#include "kernel_test_io.h"

#include <cstring>

namespace vkpt::test::layout_round_trip_test {
namespace {

using namespace vkpt::gpu;

// Float fields get distinct normal numbers (no NaN or denormal a device could canonicalise or
// flush); uint fields get distinct patterns with high bits set.
class Values {
public:
    float f() { return 1000.0f + static_cast<float>(next_++) * 0.25f; }
    uint u() { return 0xA5000000u | next_++; }
    vec3 v3() { return {f(), f(), f()}; }
    vec4 v4() { return {f(), f(), f(), f()}; }
    uvec4 u4() { return {u(), u(), u(), u()}; }

private:
    uint next_ = 1;
};

struct SharedStructs {
    std::vector<WideBvhNode> bvhNodes;
    std::vector<Triangle> triangles;
    std::vector<TriangleNormals> triangleNormals;
    std::vector<Material> materials;
    std::vector<TextureInfo> textures;
    std::vector<Emitter> emitters;
    std::vector<EnvironmentParams> environments;
    std::vector<Camera> cameras;
    std::vector<FrameParams> frames;
    std::vector<PathState> pathStates;
    std::vector<ShadowRay> shadowRays;
    std::vector<PixelState> pixelStates;
    std::vector<LightTreeNode> lightTreeNodes;
    std::vector<SpecularLobeParams> specularLobes;
    std::vector<MaterialLobes> materialLobes;
};

TextureSlot makeTextureSlot(Values& x) {
    return {x.v3(), x.u(), x.v3(), x.u()};
}

Camera makeCamera(Values& x) {
    return {x.v3(), x.f(), x.v3(), x.f(), x.v3(), x.u(), x.v3(), x.u(), x.u(), x.f(), x.u(), x.u()};
}

EnvironmentParams makeEnvironment(Values& x) {
    return {x.v3(), x.u(), x.u(), x.u(), x.u(), x.u()};
}

// camera, seed ... adaptiveMinSamples, adaptiveTolerance, adaptiveDarkFloor, slotCount,
// pixelCount, samplerSetup, sampleClamp, environment.
FrameParams makeFrameParams(Values& x) {
    return {makeCamera(x), x.u(), x.u(), x.u(), x.u(), x.u(), x.u(), x.u(), x.u(),
            x.u(),         x.u(), x.f(), x.f(), x.u(), x.u(), x.u(), x.f(), makeEnvironment(x)};
}

// Field by field in declaration order (designated initialisers would let a field be missed).
SharedStructs makeStructs() {
    Values x;
    SharedStructs s;
    for (uint i = 0; i < LAYOUT_COUNT; ++i) {
        WideBvhNode node{x.u(), x.u(), x.u(), x.u(), x.v3(), x.u(), {}};
        for (uvec4& q : node.quantised)
            q = x.u4();
        s.bvhNodes.push_back(node);
        s.triangles.push_back({x.v3(), x.u(), x.v3(), x.u(), x.v3(), x.u()});
        s.triangleNormals.push_back({x.v4(), x.v4(), x.v4()});
        Material m{};
        m.baseColor = x.v4();
        m.emission = x.v3();
        m.flags = x.u();
        m.metallic = x.f();
        m.roughness = x.f();
        m.alphaCutoff = x.f();
        m.alphaMode = x.u();
        m.specularColor = x.v3();
        m.specular = x.f();
        m.baseColorTexture = makeTextureSlot(x);
        m.metallicRoughnessTexture = makeTextureSlot(x);
        m.emissiveTexture = makeTextureSlot(x);
        m.normalTexture = makeTextureSlot(x);
        m.normalScale = x.f();
        m.normalUnused0 = x.u();
        m.normalUnused1 = x.u();
        m.normalUnused2 = x.u();
        m.transmission = x.f();
        m.ior = x.f();
        m.iorF0 = x.f();
        m.thickness = x.f();
        m.attenuationCoefficient = x.v3();
        m.unusedVolume = x.u();
        m.transmissionTexture = makeTextureSlot(x);
        m.sheenColor = x.v3();
        m.sheenRoughness = x.f();
        m.clearcoat = x.f();
        m.clearcoatRoughness = x.f();
        m.clearcoatNormalScale = x.f();
        m.layersUnused = x.u();
        m.clearcoatTexture = makeTextureSlot(x);
        m.clearcoatRoughnessTexture = makeTextureSlot(x);
        m.clearcoatNormalTexture = makeTextureSlot(x);
        m.sheenColorTexture = makeTextureSlot(x);
        m.sheenRoughnessTexture = makeTextureSlot(x);
        s.materials.push_back(m);
        s.textures.push_back({x.u(), x.u(), x.u(), x.u()});
        s.emitters.push_back(
            {x.v3(), x.u(), x.v3(), x.u(), x.v3(), x.f(), x.f(), x.f(), x.f(), x.f()});
        s.environments.push_back(makeEnvironment(x));
        s.cameras.push_back(makeCamera(x));
        s.frames.push_back(makeFrameParams(x));
        s.pathStates.push_back({x.v3(), x.u(), x.v3(), x.u(), x.v3(), x.f(), x.v3(), x.f()});
        s.shadowRays.push_back({x.v3(), x.u(), x.v3(), x.f(), x.v3(), x.f()});
        s.pixelStates.push_back({x.v3(), x.u(), x.v3(), x.u(), x.f(), x.f(), x.u(), x.u(), x.v3(),
                                 x.u(), x.v3(), x.u()});
        s.lightTreeNodes.push_back(
            {x.v3(), x.f(), x.v3(), x.f(), x.v3(), x.f(), x.u(), x.u(), x.u(), x.u()});
        SpecularLobeParams lobes{};
        lobes.specularTexture = makeTextureSlot(x);
        lobes.specularColorTexture = makeTextureSlot(x);
        lobes.anisotropyStrength = x.f();
        lobes.anisotropyRotationCos = x.f();
        lobes.anisotropyRotationSin = x.f();
        lobes.anisotropyUnused = x.u();
        lobes.anisotropyTexture = makeTextureSlot(x);
        lobes.iridescence = x.f();
        lobes.iridescenceIor = x.f();
        lobes.iridescenceThicknessMinimum = x.f();
        lobes.iridescenceThicknessMaximum = x.f();
        lobes.iridescenceTexture = makeTextureSlot(x);
        lobes.iridescenceThicknessTexture = makeTextureSlot(x);
        s.specularLobes.push_back(lobes);
        s.materialLobes.push_back(
            {x.v3(), x.f(), x.f(), x.u(), x.u(), x.u(), makeTextureSlot(x), makeTextureSlot(x)});
    }
    return s;
}

template <typename T> void appendWords(std::vector<uint>& words, const std::vector<T>& structs) {
    const std::size_t start = words.size();
    words.resize(start + structs.size() * sizeof(T) / sizeof(uint));
    std::memcpy(words.data() + start, structs.data(), structs.size() * sizeof(T));
}

// The C++ bytes as words, region by region as kernel_test_io.h lays them out.
std::vector<uint> flatten(const SharedStructs& s) {
    std::vector<uint> words;
    appendWords(words, s.bvhNodes);
    appendWords(words, s.triangles);
    appendWords(words, s.triangleNormals);
    appendWords(words, s.materials);
    appendWords(words, s.textures);
    appendWords(words, s.emitters);
    appendWords(words, s.environments);
    appendWords(words, s.cameras);
    appendWords(words, s.frames);
    appendWords(words, s.pathStates);
    appendWords(words, s.shadowRays);
    appendWords(words, s.pixelStates);
    appendWords(words, s.lightTreeNodes);
    appendWords(words, s.specularLobes);
    appendWords(words, s.materialLobes);
    return words;
}

template <typename T>
void expectSameBytes(const std::vector<T>& device, const std::vector<T>& cpu, const char* name) {
    std::vector<uint> deviceWords;
    std::vector<uint> cpuWords;
    appendWords(deviceWords, device);
    appendWords(cpuWords, cpu);
    ASSERT_EQ(deviceWords.size(), cpuWords.size()) << name;
    for (std::size_t i = 0; i < cpuWords.size(); ++i) {
        EXPECT_EQ(deviceWords[i], cpuWords[i]) << name << " word " << i;
    }
}

class LayoutRoundTrip : public GpuTest {
protected:
    template <typename T> Buffer structBuffer(const char* name, const std::vector<T>& values) {
        return makeStorageBuffer(name, std::span<const T>(values));
    }
};

TEST_F(LayoutRoundTrip, DeviceReadsEveryFieldAtItsCppOffset) {
    const SharedStructs s = makeStructs();
    const Buffer bvhNodes = structBuffer("bvhNodes", s.bvhNodes);
    const Buffer triangles = structBuffer("triangles", s.triangles);
    const Buffer triangleNormals = structBuffer("triangleNormals", s.triangleNormals);
    const Buffer materials = structBuffer("materials", s.materials);
    const Buffer textures = structBuffer("textures", s.textures);
    const Buffer emitters = structBuffer("emitters", s.emitters);
    const Buffer environments = structBuffer("environments", s.environments);
    const Buffer cameras = structBuffer("cameras", s.cameras);
    const Buffer words = makeStorageBuffer("words", LAYOUT_TOTAL_WORDS * sizeof(uint));
    const Buffer frames = structBuffer("frames", s.frames);
    const Buffer pathStates = structBuffer("pathStates", s.pathStates);
    const Buffer shadowRays = structBuffer("shadowRays", s.shadowRays);
    const Buffer pixelStates = structBuffer("pixelStates", s.pixelStates);
    const Buffer lightTreeNodes = structBuffer("lightTreeNodes", s.lightTreeNodes);
    const Buffer specularLobes = structBuffer("specularLobes", s.specularLobes);
    const Buffer materialLobes = structBuffer("materialLobes", s.materialLobes);
    const Kernel kernel = makeKernel("read_layouts", LAYOUT_BUFFER_COUNT, 0);
    runKernel(kernel,
              {&bvhNodes, &triangles, &triangleNormals, &materials, &textures, &emitters,
               &environments, &cameras, &words, &frames, &pathStates, &shadowRays, &pixelStates,
               &lightTreeNodes, &specularLobes, &materialLobes},
              LAYOUT_COUNT);

    const std::vector<uint> expected = flatten(s);
    ASSERT_EQ(expected.size(), LAYOUT_TOTAL_WORDS);
    const std::vector<uint> device = download<uint>(context(), words, LAYOUT_TOTAL_WORDS);
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(device[i], expected[i]) << "word " << i;
    }
}

TEST_F(LayoutRoundTrip, DeviceWritesEveryFieldAtItsCppOffset) {
    const SharedStructs s = makeStructs();
    const std::vector<uint> flat = flatten(s);
    const Buffer words = makeStorageBuffer("words", std::span<const uint>(flat));
    const Buffer bvhNodes = makeStorageBuffer("bvhNodes", LAYOUT_COUNT * sizeof(WideBvhNode));
    const Buffer triangles = makeStorageBuffer("triangles", LAYOUT_COUNT * sizeof(Triangle));
    const Buffer triangleNormals =
        makeStorageBuffer("triangleNormals", LAYOUT_COUNT * sizeof(TriangleNormals));
    const Buffer materials = makeStorageBuffer("materials", LAYOUT_COUNT * sizeof(Material));
    const Buffer textures = makeStorageBuffer("textures", LAYOUT_COUNT * sizeof(TextureInfo));
    const Buffer emitters = makeStorageBuffer("emitters", LAYOUT_COUNT * sizeof(Emitter));
    const Buffer environments =
        makeStorageBuffer("environments", LAYOUT_COUNT * sizeof(EnvironmentParams));
    const Buffer cameras = makeStorageBuffer("cameras", LAYOUT_COUNT * sizeof(Camera));
    const Buffer frames = makeStorageBuffer("frames", LAYOUT_COUNT * sizeof(FrameParams));
    const Buffer pathStates = makeStorageBuffer("pathStates", LAYOUT_COUNT * sizeof(PathState));
    const Buffer shadowRays = makeStorageBuffer("shadowRays", LAYOUT_COUNT * sizeof(ShadowRay));
    const Buffer pixelStates = makeStorageBuffer("pixelStates", LAYOUT_COUNT * sizeof(PixelState));
    const Buffer lightTreeNodes =
        makeStorageBuffer("lightTreeNodes", LAYOUT_COUNT * sizeof(LightTreeNode));
    const Buffer specularLobes =
        makeStorageBuffer("specularLobes", LAYOUT_COUNT * sizeof(SpecularLobeParams));
    const Buffer materialLobes =
        makeStorageBuffer("materialLobes", LAYOUT_COUNT * sizeof(MaterialLobes));
    const Kernel kernel = makeKernel("write_layouts", LAYOUT_BUFFER_COUNT, 0);
    runKernel(kernel,
              {&bvhNodes, &triangles, &triangleNormals, &materials, &textures, &emitters,
               &environments, &cameras, &words, &frames, &pathStates, &shadowRays, &pixelStates,
               &lightTreeNodes, &specularLobes, &materialLobes},
              LAYOUT_COUNT);

    expectSameBytes(download<WideBvhNode>(context(), bvhNodes, LAYOUT_COUNT), s.bvhNodes,
                    "bvhNodes");
    expectSameBytes(download<Triangle>(context(), triangles, LAYOUT_COUNT), s.triangles,
                    "triangles");
    expectSameBytes(download<TriangleNormals>(context(), triangleNormals, LAYOUT_COUNT),
                    s.triangleNormals, "triangleNormals");
    expectSameBytes(download<Material>(context(), materials, LAYOUT_COUNT), s.materials,
                    "materials");
    expectSameBytes(download<TextureInfo>(context(), textures, LAYOUT_COUNT), s.textures,
                    "textures");
    expectSameBytes(download<Emitter>(context(), emitters, LAYOUT_COUNT), s.emitters, "emitters");
    expectSameBytes(download<EnvironmentParams>(context(), environments, LAYOUT_COUNT),
                    s.environments, "environments");
    expectSameBytes(download<Camera>(context(), cameras, LAYOUT_COUNT), s.cameras, "cameras");
    expectSameBytes(download<FrameParams>(context(), frames, LAYOUT_COUNT), s.frames, "frames");
    expectSameBytes(download<PathState>(context(), pathStates, LAYOUT_COUNT), s.pathStates,
                    "pathStates");
    expectSameBytes(download<ShadowRay>(context(), shadowRays, LAYOUT_COUNT), s.shadowRays,
                    "shadowRays");
    expectSameBytes(download<LightTreeNode>(context(), lightTreeNodes, LAYOUT_COUNT),
                    s.lightTreeNodes, "lightTreeNodes");
    expectSameBytes(download<SpecularLobeParams>(context(), specularLobes, LAYOUT_COUNT),
                    s.specularLobes, "specularLobes");
    expectSameBytes(download<PixelState>(context(), pixelStates, LAYOUT_COUNT), s.pixelStates,
                    "pixelStates");
    expectSameBytes(download<MaterialLobes>(context(), materialLobes, LAYOUT_COUNT),
                    s.materialLobes, "materialLobes");
}

} // namespace
} // namespace vkpt::test::layout_round_trip_test
