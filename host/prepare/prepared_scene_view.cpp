// prepared_scene_view.cpp — spans over a PreparedScene for the shared code.
#include "prepare/prepared_scene_view.h"

namespace vkpt {

gpu::SceneView makeSceneView(const PreparedScene& scene) {
    gpu::SceneView view{};
#define VKPT_VIEW_OF_SCENE_ARRAY(name, Type, binding, number, access, split, member, reader,       \
                                 accessor)                                                         \
    view.member = scene.member;
    VKPT_SCENE_ARRAYS(VKPT_VIEW_OF_SCENE_ARRAY)
#undef VKPT_VIEW_OF_SCENE_ARRAY
    view.environment = scene.environment;
    // The features the scene's arrays were prepared for, as the kernels are specialised.
    view.features = scene.features.kernelFeatures();
    return view;
}

} // namespace vkpt
