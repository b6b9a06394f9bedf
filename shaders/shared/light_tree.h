// light_tree.h — choosing an emitter from the light BVH (host/prepare/light_tree.h builds it),
// for both executors: a walk from the root that picks each child in proportion to an importance
// bounding what the emitters below can send to the shading point, and the pmf of a given
// emitter, recomputed along its parent links, that MIS needs when a BSDF ray finds it. The
// importance is Conty Estevez and Kulla's ("Importance Sampling of Many Lights with Adaptive
// Tree Splitting", 2018) in pbrt-v4's form (section 12.6.3, LightBounds::Importance), without
// the receiver's cos θi term: the pmf of a BSDF-found emitter is evaluated from the previous
// vertex, whose normal the device path state does not keep. Reaches the scene through
// scene_view.h.
#ifndef VKPT_LIGHT_TREE_H
#define VKPT_LIGHT_TREE_H

#include "host_device.h"
#include "scene_view.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// cos(max(0, a − b)) and sin(max(0, a − b)) from the sines and cosines of a, b in [0, π]
// (pbrt-v4's cosSubClamped and sinSubClamped).
VKPT_FN float cosOfClampedDifference(float sinA, float cosA, float sinB, float cosB) {
    return cosA > cosB ? 1.0f : cosA * cosB + sinA * sinB;
}

VKPT_FN float sinOfClampedDifference(float sinA, float cosA, float sinB, float cosB) {
    return cosA > cosB ? 0.0f : sinA * cosB - cosA * sinB;
}

VKPT_FN float sinFromCos(float c) {
    return sqrt(max(0.0f, 1.0f - c * c));
}

// The cosine of the smallest angle θ' between an emission direction of the node's cone and the
// direction to p, over every point of the node's bounds: θ' = max(0, θw − θo − θb), with θw the
// angle between the axis and the direction from the bounds' centre to p and θb the half-angle
// the bounding sphere subtends at p (the whole sphere when p is inside it).
VKPT_FN float lightNodeCosThetaPrime(LightTreeNode node, vec3 p) {
    vec3 fromCenter = p - 0.5f * (node.boundsMin + node.boundsMax);
    vec3 diagonal = node.boundsMax - node.boundsMin;
    float radiusSquared = 0.25f * dot(diagonal, diagonal);
    float distanceSquared = dot(fromCenter, fromCenter);
    if (!(distanceSquared > radiusSquared)) return 1.0f;
    float cosThetaW = dot(node.axis, fromCenter / sqrt(distanceSquared));
    if ((node.flags & LIGHT_NODE_TWO_SIDED) != 0u) cosThetaW = abs(cosThetaW);
    float sinThetaW = sinFromCos(cosThetaW);
    float sinThetaB = sqrt(radiusSquared / distanceSquared);
    float cosThetaB = sinFromCos(sinThetaB);
    float sinThetaO = sinFromCos(node.cosThetaO);
    float cosThetaX = cosOfClampedDifference(sinThetaW, cosThetaW, sinThetaO, node.cosThetaO);
    float sinThetaX = sinOfClampedDifference(sinThetaW, cosThetaW, sinThetaO, node.cosThetaO);
    return cosOfClampedDifference(sinThetaX, cosThetaX, sinThetaB, cosThetaB);
}

// Power × cos θ' / d², 0 where no emission direction of the node can reach p (θ' ≥ θe). As in
// pbrt-v4 the squared distance is held above half the bounds' diagonal, so that a point in or
// near a large node does not see it as unboundedly important; the last floor keeps a point
// light's own position finite.
VKPT_FN float lightNodeImportance(LightTreeNode node, vec3 p) {
    float cosThetaPrime = lightNodeCosThetaPrime(node, p);
    if (cosThetaPrime <= node.cosThetaE) return 0.0f;
    vec3 fromCenter = p - 0.5f * (node.boundsMin + node.boundsMax);
    float distanceSquared =
        max(dot(fromCenter, fromCenter), 0.5f * length(node.boundsMax - node.boundsMin));
    return node.power * cosThetaPrime / max(distanceSquared, 1e-30f);
}

// The weight with which `parent` chooses its child `child` at p: its importance, or its power
// alone under a node that chooses by power (infinite lights, and the split between them and the
// rest at the root).
VKPT_FN float lightChildWeight(LightTreeNode parent, uint child, vec3 p VKPT_SCENE_PARAM) {
    if (child == NO_LIGHT_NODE) return 0.0f;
    LightTreeNode node = sceneLightTreeNode(child VKPT_SCENE_ARG);
    if ((parent.flags & LIGHT_NODE_BY_POWER) != 0u) return node.power;
    return lightNodeImportance(node, p);
}

// The probability of the first child from the two weights; the second child's is 1 minus it,
// written the same way by the sampler and by the pmf so that the two agree.
VKPT_FN float firstChildProbability(float weight0, float weight1) {
    return weight0 / (weight0 + weight1);
}

struct LightTreeChoice {
    uint emitter; // NO_EMITTER: every emitter has importance 0 at the point
    float probability;
};

// Walks from the root, each step choosing a child with u and rescaling u to the chosen
// interval for the next step, held below 1 (0.99999994 is the float before 1), as pbrt-v4's
// BVHLightSampler::Sample does.
VKPT_FN LightTreeChoice chooseFromLightTree(vec3 p, float u VKPT_SCENE_PARAM) {
    LightTreeChoice choice;
    choice.emitter = NO_EMITTER;
    choice.probability = 0.0f;
    LightTreeNode node = sceneLightTreeNode(sceneEmitterCount(VKPT_SCENE_ARG_ONLY) VKPT_SCENE_ARG);
    float probability = 1.0f;
    while ((node.flags & LIGHT_NODE_LEAF) == 0u) {
        float weight0 = lightChildWeight(node, node.child0, p VKPT_SCENE_ARG);
        float weight1 = lightChildWeight(node, node.child1, p VKPT_SCENE_ARG);
        if (!(weight0 + weight1 > 0.0f)) return choice;
        float p0 = firstChildProbability(weight0, weight1);
        uint next = node.child0;
        if (u < p0) {
            u = min(u / p0, 0.99999994f);
            probability *= p0;
        } else {
            u = min((u - p0) / (1.0f - p0), 0.99999994f);
            probability *= 1.0f - p0;
            next = node.child1;
        }
        node = sceneLightTreeNode(next VKPT_SCENE_ARG);
    }
    choice.emitter = node.child0;
    choice.probability = probability;
    return choice;
}

// The probability with which chooseFromLightTree picks `emitter` at p: the product of the
// choices along its parent links, 0 for an emitter outside the tree (zero power).
VKPT_FN float lightTreePmf(uint emitter, vec3 p VKPT_SCENE_PARAM) {
    uint index = emitter;
    LightTreeNode node = sceneLightTreeNode(index VKPT_SCENE_ARG);
    if (node.parent == NO_LIGHT_NODE) return 0.0f;
    float probability = 1.0f;
    while (node.parent != NO_LIGHT_NODE) {
        uint parentIndex = node.parent;
        LightTreeNode parent = sceneLightTreeNode(parentIndex VKPT_SCENE_ARG);
        float weight0 = lightChildWeight(parent, parent.child0, p VKPT_SCENE_ARG);
        float weight1 = lightChildWeight(parent, parent.child1, p VKPT_SCENE_ARG);
        if (!(weight0 + weight1 > 0.0f)) return 0.0f;
        float p0 = firstChildProbability(weight0, weight1);
        probability *= index == parent.child0 ? p0 : 1.0f - p0;
        index = parentIndex;
        node = parent;
    }
    return probability;
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_LIGHT_TREE_H
