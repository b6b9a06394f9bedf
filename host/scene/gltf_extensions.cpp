// gltf_extensions.cpp — the list of extensions vkpt implements and the two checks against it.
#include "scene/gltf_extensions.h"

#include <algorithm>

#include "scene/gltf_document.h"

namespace vkpt::gltf {
namespace {

// Extensions that change what vkpt renders and that it implements. (KHR_implicit_shapes only
// for spheres, gltf_shapes.cpp; KHR_materials_volume without thicknessTexture, which a path
// tracer does not need; KHR_materials_unlit as an emitter, docs/scene-model.md.) The
// compression extensions are decoded while loading: Draco (gltf_draco.cpp), meshopt
// (gltf_meshopt.cpp), quantized attributes (gltf_accessors.cpp) and WebP images (gltf_webp.cpp).
const std::vector<std::string> kSupportedExtensions = {"KHR_materials_emissive_strength",
                                                       "KHR_materials_specular",
                                                       "KHR_texture_transform",
                                                       "KHR_lights_punctual",
                                                       "KHR_implicit_shapes",
                                                       "KHR_materials_transmission",
                                                       "KHR_materials_ior",
                                                       "KHR_materials_volume",
                                                       "KHR_materials_clearcoat",
                                                       "KHR_materials_sheen",
                                                       "KHR_materials_unlit",
                                                       "KHR_materials_anisotropy",
                                                       "KHR_materials_iridescence",
                                                       "KHR_materials_diffuse_transmission",
                                                       "KHR_materials_dispersion",
                                                       "KHR_materials_variants",
                                                       "KHR_draco_mesh_compression",
                                                       "EXT_meshopt_compression",
                                                       "KHR_mesh_quantization",
                                                       "EXT_texture_webp",
                                                       "EXT_mesh_gpu_instancing"};

// Extensions that describe the asset (XMP metadata: its title, creator, licence) and nothing that
// is drawn: an image made without reading them is the image the file describes, so they are not
// reported as ignored. KHR_xmp is the name exporters wrote before KHR_xmp_json_ld was ratified
// (TransmissionTest.glb among the Khronos samples).
const std::vector<std::string> kMetadataExtensions = {"KHR_xmp_json_ld", "KHR_xmp"};

bool isMetadataExtension(const std::string& extension) {
    return std::find(kMetadataExtensions.begin(), kMetadataExtensions.end(), extension) !=
           kMetadataExtensions.end();
}

std::string joinNames(const std::vector<std::string>& names) {
    std::string joined;
    for (const std::string& name : names)
        joined += (joined.empty() ? "" : ", ") + name;
    return joined;
}

void appendOnce(std::vector<std::string>& names, const std::string& name) {
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
}

} // namespace

bool isSupportedExtension(const std::string& extension) {
    return std::find(kSupportedExtensions.begin(), kSupportedExtensions.end(), extension) !=
           kSupportedExtensions.end();
}

// KHR_texture_basisu's KTX2 images have no decoder packaged for Debian 12 (the platform vkpt
// builds on), so the line says what to convert them to.
void checkRequiredExtensions(const std::vector<std::string>& extensionsRequired) {
    const std::vector<std::string> unsupported = ignoredExtensions(extensionsRequired);
    if (unsupported.empty()) return;
    const bool basisu = std::find(unsupported.begin(), unsupported.end(), "KHR_texture_basisu") !=
                        unsupported.end();
    throw GltfProblem(
        std::string(unsupported.size() == 1 ? "required extension " : "required extensions ") +
        joinNames(unsupported) + (unsupported.size() == 1 ? " is" : " are") + " not supported" +
        (basisu ? " (convert the KTX2 textures to PNG, JPEG or WebP)" : ""));
}

std::vector<std::string> ignoredExtensions(const std::vector<std::string>& extensionsUsed) {
    std::vector<std::string> ignored;
    for (const std::string& extension : extensionsUsed) {
        if (!isSupportedExtension(extension) && !isMetadataExtension(extension))
            appendOnce(ignored, extension);
    }
    return ignored;
}

} // namespace vkpt::gltf
