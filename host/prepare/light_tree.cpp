// light_tree.cpp — the light BVH: each emitter's bounds and cone, their unions, the binned split
// by pbrt-v4's cost, and the node layout shared/light_tree.h walks.
#include "prepare/light_tree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "common/errors.h"
#include "common/math_constants.h"
#include "shared/intersect.h"

namespace vkpt {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr int kBuckets = 12;

// What a set of emitters is bounded by: where they are, the cone of their emission normals
// (axis, θo), how far about each normal they emit (θe) and their power. power 0: no emitters.
struct LightBounds {
    glm::dvec3 min{kInfinity};
    glm::dvec3 max{-kInfinity};
    glm::dvec3 axis{0.0, 0.0, 1.0};
    double cosThetaO = 1.0;
    double cosThetaE = 1.0;
    double power = 0.0;
    bool twoSided = false;
};

struct Item {
    std::uint32_t emitter;
    LightBounds bounds;
    glm::dvec3 centroid;
};

double angleOf(double cosine) {
    return std::acos(std::clamp(cosine, -1.0, 1.0));
}

glm::dvec3 rotateAbout(glm::dvec3 v, glm::dvec3 unitAxis, double angle) {
    // Rodrigues' rotation formula.
    return v * std::cos(angle) + glm::cross(unitAxis, v) * std::sin(angle) +
           unitAxis * glm::dot(unitAxis, v) * (1.0 - std::cos(angle));
}

// The smallest cone holding both (pbrt-v4's DirectionCone Union): the whole sphere when they
// are opposite or together span more than π.
void uniteCones(const LightBounds& a, const LightBounds& b, LightBounds& out) {
    const double thetaA = angleOf(a.cosThetaO);
    const double thetaB = angleOf(b.cosThetaO);
    const double thetaD = angleOf(glm::dot(a.axis, b.axis));
    if (std::min(thetaD + thetaB, kPi) <= thetaA) {
        out.axis = a.axis, out.cosThetaO = a.cosThetaO;
        return;
    }
    if (std::min(thetaD + thetaA, kPi) <= thetaB) {
        out.axis = b.axis, out.cosThetaO = b.cosThetaO;
        return;
    }
    const double thetaO = 0.5 * (thetaA + thetaD + thetaB);
    const glm::dvec3 across = glm::cross(a.axis, b.axis);
    if (thetaO >= kPi || glm::dot(across, across) == 0.0) {
        out.axis = glm::dvec3(0.0, 0.0, 1.0), out.cosThetaO = -1.0;
        return;
    }
    out.axis = glm::normalize(rotateAbout(a.axis, glm::normalize(across), thetaO - thetaA));
    out.cosThetaO = std::cos(thetaO);
}

LightBounds unite(const LightBounds& a, const LightBounds& b) {
    if (a.power == 0.0) return b;
    if (b.power == 0.0) return a;
    LightBounds out;
    out.min = glm::min(a.min, b.min);
    out.max = glm::max(a.max, b.max);
    uniteCones(a, b, out);
    out.cosThetaE = std::min(a.cosThetaE, b.cosThetaE);
    out.power = a.power + b.power;
    out.twoSided = a.twoSided || b.twoSided;
    return out;
}

LightBounds boundsOfEmitter(const gpu::Emitter& emitter, double power,
                            std::span<const gpu::Triangle> primitives,
                            std::span<const gpu::Material> materials) {
    LightBounds b;
    b.power = power;
    b.cosThetaE = 0.0; // every finite emitter here emits over a hemisphere about each normal
    b.cosThetaO = -1.0;
    if (emitter.kind == EMITTER_TRIANGLE) {
        const gpu::Triangle& t = primitives[emitter.primitive];
        b.min = glm::min(glm::dvec3(t.v0), glm::min(glm::dvec3(t.v1), glm::dvec3(t.v2)));
        b.max = glm::max(glm::dvec3(t.v0), glm::max(glm::dvec3(t.v1), glm::dvec3(t.v2)));
        b.axis = glm::dvec3(gpu::unitFaceNormal(t.v0, t.v1, t.v2));
        b.cosThetaO = 1.0;
        b.twoSided = (materials[t.materialIndex].flags & MATERIAL_DOUBLE_SIDED) != 0u;
    } else if (emitter.kind == EMITTER_SPHERE) {
        const gpu::Triangle& s = primitives[emitter.primitive];
        b.min = glm::dvec3(s.v0) - double(s.v1.x);
        b.max = glm::dvec3(s.v0) + double(s.v1.x);
    } else {
        b.min = b.max = glm::dvec3(emitter.position);
        if (emitter.kind == EMITTER_SPOT) {
            // pbrt-v4's SpotLight::Bounds: normals within the inner cone, and emission falling
            // off over the rest of the outer one.
            b.axis = glm::normalize(glm::dvec3(emitter.direction));
            b.cosThetaO = double(emitter.cosInnerCone);
            b.cosThetaE = std::cos(angleOf(emitter.cosOuterCone) - angleOf(emitter.cosInnerCone));
        }
    }
    return b;
}

bool isInfinite(const gpu::Emitter& emitter) {
    return emitter.kind == EMITTER_DIRECTIONAL || emitter.kind == EMITTER_ENVIRONMENT;
}

// pbrt-v4's M_Ω: the solid-angle measure of the directions the cone (θo, θe) can emit into.
double orientationMeasure(const LightBounds& b) {
    const double thetaO = angleOf(b.cosThetaO);
    const double thetaE = angleOf(b.cosThetaE);
    const double thetaW = std::min(thetaO + thetaE, kPi);
    const double sinThetaO = std::sqrt(std::max(0.0, 1.0 - b.cosThetaO * b.cosThetaO));
    return 2.0 * kPi * (1.0 - b.cosThetaO) +
           0.5 * kPi *
               (2.0 * thetaW * sinThetaO - std::cos(thetaO - 2.0 * thetaW) -
                2.0 * thetaO * sinThetaO + b.cosThetaO);
}

double surfaceArea(const LightBounds& b) {
    const glm::dvec3 d = b.max - b.min;
    return 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
}

// pbrt-v4's EvaluateCost: power × M_Ω × surface area, times the node's aspect along the axis
// split (max extent / extent along it), which discourages thin slices of a long node.
double splitCost(const LightBounds& b, double aspect) {
    return b.power * orientationMeasure(b) * aspect * surfaceArea(b);
}

struct Split {
    int axis = -1;
    double position = 0.0; // centroids below it go first
};

Split bestSplit(std::span<const Item> items, const LightBounds& all) {
    glm::dvec3 lo(kInfinity), hi(-kInfinity);
    for (const Item& item : items) {
        lo = glm::min(lo, item.centroid);
        hi = glm::max(hi, item.centroid);
    }
    const glm::dvec3 extent = all.max - all.min;
    const double longest = std::max(extent.x, std::max(extent.y, extent.z));
    Split best;
    double bestCost = kInfinity;
    for (int axis = 0; axis < 3; ++axis) {
        if (!(hi[axis] > lo[axis])) continue;
        const double scale = kBuckets / (hi[axis] - lo[axis]);
        std::array<LightBounds, kBuckets> buckets{};
        for (const Item& item : items) {
            const int b = std::min(int((item.centroid[axis] - lo[axis]) * scale), kBuckets - 1);
            buckets[std::size_t(b)] = unite(buckets[std::size_t(b)], item.bounds);
        }
        const double aspect = extent[axis] > 0.0 ? longest / extent[axis] : 1.0;
        for (int split = 1; split < kBuckets; ++split) {
            LightBounds below, above;
            for (int b = 0; b < split; ++b)
                below = unite(below, buckets[std::size_t(b)]);
            for (int b = split; b < kBuckets; ++b)
                above = unite(above, buckets[std::size_t(b)]);
            if (below.power == 0.0 || above.power == 0.0) continue;
            const double cost = splitCost(below, aspect) + splitCost(above, aspect);
            if (cost < bestCost) {
                bestCost = cost;
                best.axis = axis;
                best.position = lo[axis] + split / scale;
            }
        }
    }
    return best;
}

// Splits items in place and returns the size of the first part, never 0 or all: the best
// bucket split, or halves along the centroids' longest axis when no bucket split divides them.
std::size_t partitionItems(std::span<Item> items, const LightBounds& all) {
    const Split split = bestSplit(items, all);
    if (split.axis >= 0) {
        auto middle = std::partition(items.begin(), items.end(), [&](const Item& item) {
            return item.centroid[split.axis] < split.position;
        });
        const std::size_t count = std::size_t(middle - items.begin());
        if (count > 0 && count < items.size()) return count;
    }
    const std::size_t half = items.size() / 2;
    std::nth_element(items.begin(), items.begin() + std::ptrdiff_t(half), items.end(),
                     [](const Item& a, const Item& b) {
                         if (a.centroid.x != b.centroid.x) return a.centroid.x < b.centroid.x;
                         if (a.centroid.y != b.centroid.y) return a.centroid.y < b.centroid.y;
                         return a.centroid.z < b.centroid.z;
                     });
    return half;
}

gpu::LightTreeNode nodeOf(const LightBounds& b, std::uint32_t flags) {
    gpu::LightTreeNode node{};
    const bool finite = b.min.x <= b.max.x;
    node.boundsMin = finite ? glm::vec3(b.min) : glm::vec3(0.0f);
    node.boundsMax = finite ? glm::vec3(b.max) : glm::vec3(0.0f);
    node.power = float(b.power);
    node.axis = glm::vec3(b.axis);
    node.cosThetaO = float(b.cosThetaO);
    node.cosThetaE = float(b.cosThetaE);
    node.child0 = node.child1 = node.parent = NO_LIGHT_NODE;
    node.flags = flags | (b.twoSided ? LIGHT_NODE_TWO_SIDED : 0u);
    return node;
}

class TreeBuilder {
public:
    explicit TreeBuilder(std::vector<gpu::LightTreeNode>& nodes) : nodes_(nodes) {}

    // The subtree over items, at `slot` when given (the root), else at a new node; one item
    // without a slot is its leaf itself.
    std::uint32_t build(std::span<Item> items, bool byPower, std::uint32_t slot = NO_LIGHT_NODE) {
        if (items.size() == 1 && slot == NO_LIGHT_NODE) return items[0].emitter;
        const std::uint32_t index = place(slot);
        LightBounds all;
        for (const Item& item : items)
            all = unite(all, item.bounds);
        if (items.size() == 1) {
            link(index, all, items[0].emitter, NO_LIGHT_NODE, byPower);
            return index;
        }
        const std::size_t first = byPower ? items.size() / 2 : partitionItems(items, all);
        const std::uint32_t child0 = build(items.first(first), byPower);
        const std::uint32_t child1 = build(items.subspan(first), byPower);
        link(index, all, child0, child1, byPower);
        return index;
    }

    // The root over both kinds: its children are chosen by power, as the power table would.
    void joinAtRoot(std::uint32_t root, std::uint32_t finite, std::uint32_t infinite,
                    double power) {
        LightBounds b;
        b.power = power;
        link(root, b, finite, infinite, true);
    }

private:
    std::uint32_t place(std::uint32_t slot) {
        if (slot != NO_LIGHT_NODE) return slot;
        nodes_.push_back({});
        return std::uint32_t(nodes_.size() - 1);
    }

    void link(std::uint32_t index, const LightBounds& b, std::uint32_t child0, std::uint32_t child1,
              bool byPower) {
        nodes_[index] = nodeOf(b, byPower ? LIGHT_NODE_BY_POWER : 0u);
        nodes_[index].child0 = child0;
        nodes_[index].child1 = child1;
        nodes_[child0].parent = index;
        if (child1 != NO_LIGHT_NODE) nodes_[child1].parent = index;
    }

    std::vector<gpu::LightTreeNode>& nodes_;
};

} // namespace

std::vector<gpu::LightTreeNode> buildLightTree(std::span<const gpu::Emitter> emitters,
                                               std::span<const double> powers,
                                               std::span<const gpu::Triangle> primitives,
                                               std::span<const gpu::Material> materials) {
    VKPT_ASSERT(powers.size() == emitters.size(), "one power per emitter");
    const auto root = std::uint32_t(emitters.size());
    std::vector<gpu::LightTreeNode> nodes(emitters.size() + 1);
    std::vector<Item> finite, infinite;
    double finitePower = 0.0, infinitePower = 0.0;
    for (std::uint32_t i = 0; i < emitters.size(); ++i) {
        const LightBounds b = boundsOfEmitter(emitters[i], powers[i], primitives, materials);
        nodes[i] = nodeOf(b, LIGHT_NODE_LEAF);
        nodes[i].child0 = i;
        if (!(powers[i] > 0.0)) continue;
        const bool far = isInfinite(emitters[i]);
        (far ? infinite : finite).push_back({i, b, 0.5 * (b.min + b.max)});
        (far ? infinitePower : finitePower) += powers[i];
    }
    nodes[root] = nodeOf(LightBounds{}, 0u);
    TreeBuilder builder(nodes);
    if (!finite.empty() && !infinite.empty()) {
        const std::uint32_t f = builder.build(finite, false);
        const std::uint32_t g = builder.build(infinite, true);
        builder.joinAtRoot(root, f, g, finitePower + infinitePower);
    } else if (!finite.empty()) {
        builder.build(finite, false, root);
    } else if (!infinite.empty()) {
        builder.build(infinite, true, root);
    }
    return nodes;
}

} // namespace vkpt
