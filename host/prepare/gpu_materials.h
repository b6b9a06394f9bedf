// gpu_materials.h — materials and textures in the layouts the renderers read: gpu::Material
// with its texture slots, gpu::TextureInfo per glTF texture and one array of all texels.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/scene.h"
#include "shared/host_device.h"

namespace vkpt {

std::vector<gpu::Material> makeGpuMaterials(const std::vector<SceneMaterial>& materials);

// The materials' specular lobe extensions (specular textures, anisotropy, iridescence), in the
// same order: the specularLobes array, filled only when features.specularLobes().
std::vector<gpu::SpecularLobeParams>
makeGpuSpecularLobes(const std::vector<SceneMaterial>& materials);

// The materialLobes array: one record per material, for scenes with diffuse transmission or
// dispersion (only their kernels read it).
std::vector<gpu::MaterialLobes> makeGpuMaterialLobes(const std::vector<SceneMaterial>& materials);

struct GpuTextures {
    std::vector<gpu::TextureInfo> textures; // one per Scene::textures entry
    std::vector<std::uint32_t> texels;      // each image once, however many textures use it
};

// Throws InputError when the texels do not fit the 32-bit offsets of gpu::TextureInfo.
GpuTextures makeGpuTextures(const Scene& scene);

} // namespace vkpt
