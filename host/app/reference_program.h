// reference_program.h — vkpt-ref's whole program (its options, load, BVH build, render,
// outputs and summary) with the ray queries left open: vkpt-ref passes its ordered stack walk,
// the benchmarks' embree-ref passes Embree and is otherwise the same program.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "common/render_settings.h"
#include "prepare/prepared_scene.h"
#include "reference/scene_intersector.h"

namespace vkpt {

struct ReferenceProgram {
    std::string name; // in messages, the summary and --help
    // Called once the scene is prepared, before the render (its time is not render time).
    std::function<std::unique_ptr<IntersectorFactory>(const PreparedScene&, const RenderSettings&)>
        makeIntersectors;
};

// main() of such a program: exit codes of DESIGN's error contract (1 bad input, 3 internal).
int runReferenceProgram(const ReferenceProgram& program, int argc, char** argv);

} // namespace vkpt
