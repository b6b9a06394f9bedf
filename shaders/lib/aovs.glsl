// aovs.glsl — whether this render records the AOVs (shared/sample_features.h): a push constant
// (PassParams.recordAovs), not a specialisation constant, so that a render with AOVs and one
// without share their pipelines: a denoised render compiles no kernel a colour render of the
// scene has compiled. A render without them binds stand-ins for their buffers
// (render/work_buffers.cpp) that its kernels never touch. On a GPU the test is a uniform branch;
// lavapipe runs the few AOV stores masked off (docs/gpu.md, "lavapipe runs both sides of a
// branch").
#ifndef VKPT_AOVS_GLSL
#define VKPT_AOVS_GLSL

#include "lib/frame.glsl"

bool renderAovs() {
    return passParams.recordAovs != 0u;
}

#endif // VKPT_AOVS_GLSL
