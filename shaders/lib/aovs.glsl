// aovs.glsl — whether this render records the AOVs (shared/sample_features.h): a specialisation
// constant the host sets when an output or a saved state needs them, so that a render that
// writes only a colour image compiles the feature stores out and never binds their buffers.
#ifndef VKPT_AOVS_GLSL
#define VKPT_AOVS_GLSL

#include "lib/wavefront.h"

layout(constant_id = SPEC_AOVS) const bool renderAovs = false;

#endif // VKPT_AOVS_GLSL
