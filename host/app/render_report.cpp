// render_report.cpp — the end-of-render summary lines and the --stats-json document.
#include "app/render_report.h"

#include <cstdio>
#include <fstream>

#include "common/errors.h"
#include "common/json_writer.h"

namespace vkpt {

namespace {

const char* integratorName(Integrator integrator) {
    switch (integrator) {
    case Integrator::Path:
        return "path";
    case Integrator::Direct:
        return "direct";
    case Integrator::Normals:
        return "normals";
    }
    return "?";
}

void writeSettings(JsonWriter& json, const RenderSettings& s) {
    json.key("settings").beginObject();
    json.field("scene", s.scenePath).field("output", s.outputPath);
    json.field("width", s.width).field("height", s.height).field("spp", s.samplesPerPixel);
    json.field("maxDepth", s.maxDepth).field("rrStartDepth", s.rrStartDepth).field("seed", s.seed);
    json.field("integrator", integratorName(s.integrator));
    json.field("sampler", s.sampler == Sampler::Sobol ? "sobol" : "independent");
    json.field("lightSampling", s.lightSampling == LightSampling::Light ? "light" : "hemisphere");
    json.field("lightSamples", s.lightSamples);
    json.field("lightSampler", s.lightSampler == LightSampler::Auto  ? "auto"
                               : s.lightSampler == LightSampler::Bvh ? "bvh"
                                                                     : "power");
    json.field("adaptive", s.adaptive.enabled).field("adaptiveBatch", s.adaptive.batchSize);
    json.field("adaptiveTolerance", s.adaptive.tolerance);
    json.field("adaptiveMinSamples", s.adaptive.minSamples);
    json.field("clamp", s.clamp); // 0 = off
    json.field("environment", s.environmentPath).field("general", s.general);
    json.field("instancing", s.instancing == Instancing::Auto ? "auto"
                             : s.instancing == Instancing::On ? "on"
                                                              : "off");
    if (s.animationTime) json.field("time", *s.animationTime);
    json.field("animation", s.animation); // "" all of them
    json.field("variant", s.variant);     // "" = the default materials
    json.endObject();
}

// "process": the whole process's seconds to the report; "phases": each phase in order, with
// its nesting depth (a phase of depth d + 1 is part of the nearest earlier one of depth d).
void writePhases(JsonWriter& json, const RenderReport& r) {
    json.key("process").beginObject();
    json.field("seconds", r.processSeconds).field("cpuSeconds", r.processCpuSeconds);
    json.endObject();
    json.key("phases").beginArray();
    for (const PhaseTime& phase : r.phases) {
        json.beginObject().field("name", phase.name).field("depth", phase.depth);
        json.field("seconds", phase.wallSeconds).field("cpuSeconds", phase.cpuSeconds);
        json.endObject();
    }
    json.endArray();
}

void writeStats(JsonWriter& json, const RenderReport& r) {
    const RenderStats& st = r.stats;
    json.key("render").beginObject();
    json.field("seconds", st.seconds).field("loadSeconds", r.loadSeconds);
    json.field("cpuSeconds", st.cpuSeconds);
    json.key("rays").beginObject();
    json.field("camera", st.rays.camera).field("extension", st.rays.extension);
    json.field("shadow", st.rays.shadow).field("total", st.rays.total());
    json.endObject();
    json.field("megaRaysPerSecond", st.megaRaysPerSecond());
    json.field("nodesVisitedPerRay", st.nodesPerRay());
    json.field("triangleTestsPerRay", st.trianglesPerRay());
    json.field("samplesTaken", st.samplesTaken).field("uniformBudget", st.uniformBudget);
    json.field("nonFiniteSamples", st.nonFiniteSamples);
    json.field("deviceMemoryBytes", r.deviceMemoryBytes);
    json.endObject();
}

void writeBvh(JsonWriter& json, const RenderReport& r) {
    json.key("bvh").beginObject();
    json.field("triangles", r.triangles).field("emitters", r.emitters);
    json.field("placedTriangles", r.placedTriangles).field("instances", r.instances);
    json.field("meshes", r.meshes);
    json.field("nodes", r.bvh.nodeCount).field("leaves", r.bvh.leafCount);
    json.field("maxDepth", r.bvh.maxDepth).field("sahCost", r.bvh.sahCost);
    json.field("buildSeconds", r.bvh.buildSeconds);
    json.endObject();
}

void writeFeatures(JsonWriter& json, const RenderReport& r) {
    const SceneFeatures& f = r.features;
    json.key("features").beginObject();
    json.field("builtFor", r.generalPipelines ? "general" : "scene");
    json.field("diffuseMaterials", f.diffuseMaterials);
    json.field("metallicRoughnessMaterials", f.metallicRoughnessMaterials);
    json.field("baseColorTextures", f.baseColorTextures);
    json.field("metallicRoughnessTextures", f.metallicRoughnessTextures);
    json.field("emissiveTextures", f.emissiveTextures);
    json.field("normalTextures", f.normalTextures);
    json.field("clearcoatMaterials", f.clearcoatMaterials);
    json.field("sheenMaterials", f.sheenMaterials);
    json.field("clearcoatTextures", f.clearcoatTextures).field("sheenTextures", f.sheenTextures);
    json.field("specularTextures", f.specularTextures);
    json.field("anisotropy", f.anisotropy).field("anisotropyTextures", f.anisotropyTextures);
    json.field("iridescence", f.iridescence).field("iridescenceTextures", f.iridescenceTextures);
    json.field("diffuseTransmission", f.diffuseTransmission)
        .field("diffuseTransmissionTextures", f.diffuseTransmissionTextures);
    json.field("dispersion", f.dispersion);
    json.field("textureCoordinates", f.textureCoordinates());
    json.field("alphaMask", f.alphaMask).field("doubleSided", f.doubleSided);
    json.field("transmission", f.transmission);
    json.field("triangles", f.triangles).field("spheres", f.spheres);
    json.field("instances", f.instances);
    json.field("emissiveTriangles", f.emissiveTriangles);
    json.field("emissiveSpheres", f.emissiveSpheres);
    json.field("pointLights", f.pointLights).field("spotLights", f.spotLights);
    json.field("directionalLights", f.directionalLights);
    json.field("environment", f.environment).field("environmentMap", f.environmentMap);
    json.field("emitterCount", f.emitterCount).field("lightTree", f.lightTree);
    json.endObject();
}

void writeDeviceRun(JsonWriter& json, const DeviceRunReport& d) {
    json.key("wavefront").beginObject();
    json.field("passes", d.passes).field("pathSlots", d.slotCount);
    json.field("setupSeconds", d.setupSeconds);
    json.field("truncatedTraversals", d.truncatedTraversals).field("interrupted", d.interrupted);
    json.field("pipelineCreationSeconds", d.pipelineCreationSeconds);
    json.field("pipelinesCreatedEarly", d.pipelinesCreatedEarly);
    json.key("pipelines").beginArray();
    for (const PipelineCreation& p : d.pipelineCreations)
        json.beginObject()
            .field("name", p.kernel)
            .field("spirvBytes", p.spirvBytes)
            .field("seconds", p.seconds)
            .endObject();
    json.endArray();
    json.field("sceneBufferBytes", d.sceneBufferBytes);
    json.key("sceneBuffers").beginArray();
    for (const SceneBufferBytes& b : d.sceneBuffers)
        json.beginObject()
            .field("name", b.name)
            .field("bytes", b.bytes)
            .field("buffers", b.buffers)
            .endObject();
    json.endArray();
    json.key("kernels").beginArray();
    for (const KernelTimeTotal& k : d.kernelTimes) {
        json.beginObject().field("name", k.kernel).field("dispatches", k.dispatches);
        json.field("seconds", k.seconds()).endObject();
    }
    json.endArray();
    json.endObject();
}

void printDeviceRun(const RenderReport& r, const DeviceRunReport& d) {
    std::printf("  device: %u passes of up to %u path slots, setup %.3f s, peak memory %.1f MiB\n",
                d.passes, d.slotCount, d.setupSeconds, double(r.deviceMemoryBytes) / 1048576.0);
    std::printf(
        "  pipelines %.3f s %s; scene buffers %.1f KiB in %zu buffers\n", d.pipelineCreationSeconds,
        d.pipelinesCreatedEarly ? "waited for (created while the scene was prepared)" : "to create",
        double(d.sceneBufferBytes) / 1024.0, d.sceneBuffers.size());
    for (const KernelTimeTotal& k : d.kernelTimes)
        std::printf("  kernel %-20s %9.3f ms in %llu dispatches\n", k.kernel.c_str(),
                    k.seconds() * 1e3, (unsigned long long)k.dispatches);
    // With --stats (kernel times asked for), the pipelines' creation too.
    if (!d.kernelTimes.empty())
        for (const PipelineCreation& p : d.pipelineCreations)
            std::printf("  pipeline %-18s %9.3f ms to create from %.1f KiB of SPIR-V\n",
                        p.kernel.c_str(), p.seconds * 1e3, double(p.spirvBytes) / 1024.0);
    if (d.interrupted) std::printf("  interrupted: the image holds the passes finished so far\n");
}

} // namespace

RenderReport sceneReport(const std::string& program, const RenderSettings& settings,
                         const SceneSetup& setup) {
    RenderReport report;
    report.program = program;
    report.settings = &settings;
    report.bvh = setup.prepared.bvhStats;
    report.triangles = setup.prepared.triangles.size();
    report.placedTriangles = setup.placedTriangles;
    report.instances = setup.instances;
    report.meshes = setup.meshes;
    report.emitters = setup.prepared.emitters.size();
    report.features = setup.prepared.usedFeatures;
    report.generalPipelines = settings.general;
    report.loadSeconds = setup.loadSeconds;
    return report;
}

void printRenderSummary(const RenderReport& r) {
    const RenderStats& st = r.stats;
    std::printf("%s: %s, %ux%u, %.3f s, %.2f Mrays/s on %s\n", r.program.c_str(),
                r.settings->outputPath.c_str(), r.settings->width, r.settings->height, st.seconds,
                st.megaRaysPerSecond(), r.device.c_str());
    std::printf("  rays: %llu camera, %llu extension, %llu shadow; ",
                (unsigned long long)st.rays.camera, (unsigned long long)st.rays.extension,
                (unsigned long long)st.rays.shadow);
    // Every counted walk tests the root box, so no nodes means a traversal that does not count
    // (embree-ref's Embree).
    if (st.nodesVisited > 0 || st.rays.total() == 0)
        std::printf("%.1f nodes and %.1f triangle tests per ray\n", st.nodesPerRay(),
                    st.trianglesPerRay());
    else
        std::printf("traversal work not counted\n");
    double share =
        st.uniformBudget ? 100.0 * double(st.samplesTaken) / double(st.uniformBudget) : 0;
    std::printf("  samples: %llu of a uniform budget of %llu (%.1f %%)",
                (unsigned long long)st.samplesTaken, (unsigned long long)st.uniformBudget, share);
    if (st.nonFiniteSamples)
        std::printf("; %llu non-finite samples discarded", (unsigned long long)st.nonFiniteSamples);
    std::printf("\n");
    if (r.deviceRun) printDeviceRun(r, *r.deviceRun);
    if (r.convergence) printConvergenceSummary(*r.convergence);
    if (!r.phases.empty())
        std::printf("  time: %.2f s in all, %.2f s of CPU: %s\n", r.processSeconds,
                    r.processCpuSeconds, describePhases(r.phases).c_str());
}

void writeStatsJson(const RenderReport& r, const std::string& path) {
    std::ofstream out(path);
    if (!out) throw InputError(path + ": cannot write the statistics file");
    JsonWriter json(out);
    json.beginObject().field("program", r.program).field("device", r.device);
    writeSettings(json, *r.settings);
    writeBvh(json, r);
    writeFeatures(json, r);
    writeStats(json, r);
    if (r.deviceRun) writeDeviceRun(json, *r.deviceRun);
    if (r.convergence) writeConvergenceJson(json, *r.convergence);
    writePhases(json, r);
    json.endObject();
    out << "\n";
    if (!out) throw InputError(path + ": write failed");
}

void writeRenderReport(RenderReport report) {
    report.phases = processPhases().phases();
    report.processSeconds = processPhases().secondsSinceStart();
    report.processCpuSeconds = processCpuSeconds();
    printRenderSummary(report);
    if (!report.settings->statsJsonPath.empty())
        writeStatsJson(report, report.settings->statsJsonPath);
}

} // namespace vkpt
