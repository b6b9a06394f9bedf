// vkpt_ref_main.cpp — vkpt-ref, the CPU reference renderer: load, build, render, write, with
// rays traced by the reference's ordered stack walk.
#include "app/reference_program.h"
#include "reference/stack_intersector.h"

int main(int argc, char** argv) {
    vkpt::ReferenceProgram program{
        "vkpt-ref", [](const vkpt::PreparedScene& scene, const vkpt::RenderSettings&) {
            return std::make_unique<vkpt::StackIntersectors>(scene);
        }};
    return vkpt::runReferenceProgram(program, argc, argv);
}
