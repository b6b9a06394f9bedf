// prepared_scene_view.cpp — spans over a PreparedScene for the shared code.
#include "prepare/prepared_scene_view.h"

namespace vkpt {

gpu::SceneView makeSceneView(const PreparedScene& scene) {
    gpu::SceneView view{};
    view.primitives = scene.triangles;
    view.normals = scene.normals;
    view.tangents = scene.tangents;
    view.instances = scene.instances;
    view.uvs = scene.uvs;
    view.materials = scene.materials;
    view.textures = scene.textures;
    view.textureTexels = scene.texels;
    view.emitters = scene.emitters;
    view.emitterCdf = scene.emitterCdf;
    view.lightTree = scene.lightTree;
    view.environment = scene.environment;
    view.environmentTexels = scene.environmentTexels;
    view.environmentCdf = scene.environmentCdf;
    // The features the scene's arrays were prepared for, as the kernels are specialised.
    view.features = scene.features.kernelFeatures();
    return view;
}

} // namespace vkpt
