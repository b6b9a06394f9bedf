// gltf_cameras.cpp — a glTF camera and its node's world transform to position, forward, up.
#include "scene/gltf_cameras.h"

#include <cmath>
#include <numbers>

#include "scene/gltf_document.h"

namespace vkpt::gltf {
namespace {

const tinygltf::Camera& findCamera(const tinygltf::Model& model, int nodeIndex) {
    const int index = model.nodes[static_cast<std::size_t>(nodeIndex)].camera;
    if (index < 0 || static_cast<std::size_t>(index) >= model.cameras.size()) {
        throw GltfProblem(nodeName(nodeIndex) + ": camera " + std::to_string(index) +
                          " does not exist (the file has " + std::to_string(model.cameras.size()) +
                          " cameras)");
    }
    return model.cameras[static_cast<std::size_t>(index)];
}

float checkedYfov(const tinygltf::Camera& camera, int nodeIndex) {
    const double yfov = camera.perspective.yfov;
    if (!(yfov > 0.0 && yfov < std::numbers::pi)) {
        throw GltfProblem(nodeName(nodeIndex) + ": camera yfov " + std::to_string(yfov) +
                          " is not between 0 and pi");
    }
    return static_cast<float>(yfov);
}

// glTF orthographic cameras: xmag and ymag are the half-width and half-height of the view
// (non-zero; a negative one mirrors, which vkpt does not support), zfar > znear >= 0.
void setOrthographic(SceneCamera& camera, const tinygltf::Camera& gltfCamera, int nodeIndex) {
    const tinygltf::OrthographicCamera& o = gltfCamera.orthographic;
    if (!(o.xmag > 0.0 && o.ymag > 0.0 && std::isfinite(o.xmag) && std::isfinite(o.ymag))) {
        throw GltfProblem(nodeName(nodeIndex) + ": orthographic camera xmag " +
                          std::to_string(o.xmag) + ", ymag " + std::to_string(o.ymag) +
                          " must be positive and finite");
    }
    if (!(o.znear >= 0.0 && o.zfar > o.znear)) {
        throw GltfProblem(nodeName(nodeIndex) + ": orthographic camera znear " +
                          std::to_string(o.znear) + ", zfar " + std::to_string(o.zfar) +
                          " must satisfy zfar > znear >= 0");
    }
    camera.projection = CameraProjection::Orthographic;
    camera.xmag = static_cast<float>(o.xmag);
    camera.ymag = static_cast<float>(o.ymag);
}

glm::dvec3 unitOrThrow(const glm::dvec3& v, int nodeIndex) {
    const double length = glm::length(v);
    if (!(length > 0.0) || !std::isfinite(length)) {
        throw GltfProblem(nodeName(nodeIndex) + ": the camera's transform is degenerate");
    }
    return v / length;
}

// Columns of the world matrix are the images of the local axes. Normalising them removes scale,
// and Gram-Schmidt keeps up orthogonal to forward even under shear.
void setBasis(SceneCamera& camera, const glm::dmat4& world, int nodeIndex) {
    const glm::dvec3 forward = unitOrThrow(-glm::dvec3(world[2]), nodeIndex);
    const glm::dvec3 upAxis = glm::dvec3(world[1]);
    const glm::dvec3 up = unitOrThrow(upAxis - glm::dot(upAxis, forward) * forward, nodeIndex);
    camera.position = glm::vec3(glm::dvec3(world[3]));
    camera.forward = glm::vec3(forward);
    camera.up = glm::vec3(up);
}

} // namespace

SceneCamera placeCamera(const tinygltf::Model& model, int nodeIndex, const glm::dmat4& world) {
    const tinygltf::Camera& gltfCamera = findCamera(model, nodeIndex);
    SceneCamera camera;
    const auto& node = model.nodes[static_cast<std::size_t>(nodeIndex)];
    camera.name = gltfCamera.name.empty() ? node.name : gltfCamera.name;
    if (gltfCamera.type == "orthographic") { // tinygltf allows only the two types
        setOrthographic(camera, gltfCamera, nodeIndex);
    } else {
        camera.yfov = checkedYfov(gltfCamera, nodeIndex);
    }
    setBasis(camera, world, nodeIndex);
    return camera;
}

} // namespace vkpt::gltf
