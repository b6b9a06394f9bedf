// embree_ref_main.cpp — embree-ref: vkpt-ref (same options, integrators, sampling and outputs)
// with Embree 3 tracing the rays, the benchmarks' baseline. Embree's BVH build time is
// reported on its own line; the render time in the summary is the render alone.
#include <cstdio>
#include <thread>

#include "app/reference_program.h"
#include "embree/embree_intersectors.h"

int main(int argc, char** argv) {
    vkpt::ReferenceProgram program{
        "embree-ref", [](const vkpt::PreparedScene& scene, const vkpt::RenderSettings& settings) {
            std::uint32_t threads =
                settings.threads ? settings.threads : std::thread::hardware_concurrency();
            auto embree = std::make_unique<vkpt::bench::EmbreeIntersectors>(scene, threads);
            std::fprintf(stderr,
                         "embree-ref: Embree %s BVH (RTC_BUILD_QUALITY_HIGH, %u threads) built "
                         "in %.3f s\n",
                         vkpt::bench::EmbreeIntersectors::version().c_str(), threads,
                         embree->buildSeconds());
            return embree;
        }};
    return vkpt::runReferenceProgram(program, argc, argv);
}
