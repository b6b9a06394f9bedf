// bvh_wide.cpp — collapses the binary tree into 8-wide nodes, assigns slots by octant, lays
// the leaves' primitives out per node and quantises the child boxes conservatively.
#include "bvh/bvh_wide.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <span>

#include "common/errors.h"

namespace vkpt {

namespace {

using Kind = WideDraftChild::Kind;

// Levels below each binary node (0 for a leaf); children follow their parents in the array,
// so one backward pass sees every child before its parent.
std::vector<std::uint32_t> subtreeHeights(const BvhTree& tree) {
    std::vector<std::uint32_t> heights(tree.nodes.size(), 0);
    for (std::size_t i = tree.nodes.size(); i-- > 0;) {
        const BvhBuildNode& n = tree.nodes[i];
        if (!n.isLeaf()) heights[i] = 1 + std::max(heights[n.leftChild], heights[n.rightChild]);
    }
    return heights;
}

bool isNonEmptyLeaf(const BvhBuildNode& n) {
    return n.isLeaf() && n.primitiveCount > 0;
}

// Up to eight binary nodes, held in place: the collapse makes one per wide node, and the
// 1M-triangle trees have about 200,000 of them, so nothing here touches the heap.
struct ChildList {
    std::array<std::uint32_t, WIDE_BVH_WIDTH> nodes{};
    std::uint32_t count = 0;
};

// The binary nodes that become the children of the wide node made of `node`: its two
// children, then repeatedly the chosen interior one replaced by its own two, up to eight.
ChildList openChildren(const BvhTree& tree, std::uint32_t node, CollapseOrder order,
                       const std::vector<std::uint32_t>& heights) {
    const BvhBuildNode& n = tree.nodes[node];
    ChildList children;
    if (n.isLeaf()) {
        if (isNonEmptyLeaf(n)) children.nodes[children.count++] = node;
        return children;
    }
    children.nodes[0] = n.leftChild;
    children.nodes[1] = n.rightChild;
    children.count = 2;
    while (children.count < WIDE_BVH_WIDTH) {
        std::uint32_t best = children.count;
        float bestKey = -1.0f;
        for (std::uint32_t c = 0; c < children.count; ++c) {
            const BvhBuildNode& child = tree.nodes[children.nodes[c]];
            if (child.isLeaf()) continue;
            float key = order == CollapseOrder::LargestArea ? child.bounds.surfaceArea()
                                                            : float(heights[children.nodes[c]]);
            if (key > bestKey) {
                bestKey = key;
                best = c;
            }
        }
        if (best == children.count) break;
        const BvhBuildNode& opened = tree.nodes[children.nodes[best]];
        children.nodes[best] = opened.leftChild;
        children.nodes[children.count++] = opened.rightChild;
    }
    return children;
}

// The direction of octant s: component k is −1 where bit k of s is set.
glm::vec3 octantDirection(std::uint32_t s) {
    return {(s & 1u) ? -1.0f : 1.0f, (s & 2u) ? -1.0f : 1.0f, (s & 4u) ? -1.0f : 1.0f};
}

// Slot s should hold the child that a ray travelling along octant s's direction reaches
// first: the one whose centre lies lowest along that direction (Ylitie et al. 2017, section
// 3.2, assign the same way with an auction). Greedy: the cheapest (child, slot) pair whose
// child and slot are both free is placed next, ties to the lower child, then the lower slot
// (at most 8 rounds over 64 costs, no sort).
std::array<std::uint32_t, WIDE_BVH_WIDTH> assignSlots(const BvhTree& tree, std::uint32_t parent,
                                                      const ChildList& children) {
    const glm::vec3 centre = tree.nodes[parent].bounds.centre();
    std::array<std::array<float, WIDE_BVH_WIDTH>, WIDE_BVH_WIDTH> cost{};
    for (std::uint32_t c = 0; c < children.count; ++c) {
        glm::vec3 offset = tree.nodes[children.nodes[c]].bounds.centre() - centre;
        for (std::uint32_t s = 0; s < WIDE_BVH_WIDTH; ++s)
            cost[c][s] = glm::dot(offset, octantDirection(s));
    }
    std::array<std::uint32_t, WIDE_BVH_WIDTH> slotOfChild{};
    std::array<bool, WIDE_BVH_WIDTH> childPlaced{}, slotTaken{};
    for (std::uint32_t round = 0; round < children.count; ++round) {
        std::uint32_t bestChild = WIDE_BVH_WIDTH, bestSlot = 0;
        for (std::uint32_t c = 0; c < children.count; ++c) {
            if (childPlaced[c]) continue;
            for (std::uint32_t s = 0; s < WIDE_BVH_WIDTH; ++s) {
                if (slotTaken[s]) continue;
                // The first free pair is taken whatever its cost, so a NaN cost (centres of
                // boxes beyond ±FLT_MAX / 2) still gets a slot.
                if (bestChild == WIDE_BVH_WIDTH || cost[c][s] < cost[bestChild][bestSlot]) {
                    bestChild = c;
                    bestSlot = s;
                }
            }
        }
        childPlaced[bestChild] = slotTaken[bestSlot] = true;
        slotOfChild[bestChild] = bestSlot;
    }
    return slotOfChild;
}

WideDraft collapseWith(const BvhTree& tree, CollapseOrder order) {
    const std::vector<std::uint32_t> heights =
        order == CollapseOrder::Tallest ? subtreeHeights(tree) : std::vector<std::uint32_t>{};
    WideDraft draft;
    // Each wide node stands for a distinct interior binary node (or the root leaf).
    draft.nodes.reserve(tree.nodes.size() / 2 + 1);
    draft.nodes.push_back({0, BVH_END, {}});
    std::vector<std::uint32_t> depths{0};
    depths.reserve(draft.nodes.capacity());
    // A node's internal children are made together, so they are contiguous; nodes are filled
    // depth first, so a subtree's nodes (and, laid out in node order, its primitives) lie close
    // together in memory, which a walk down one path of a large tree finds in fewer cache lines.
    std::vector<std::uint32_t> toFill{0};
    while (!toFill.empty()) {
        const std::uint32_t w = toFill.back();
        toFill.pop_back();
        const std::uint32_t binary = draft.nodes[w].binaryNode;
        const ChildList children = openChildren(tree, binary, order, heights);
        const auto slots = assignSlots(tree, binary, children);
        std::array<WideDraftChild, WIDE_BVH_WIDTH> placed{};
        for (std::uint32_t c = 0; c < children.count; ++c) {
            const bool leaf = tree.nodes[children.nodes[c]].isLeaf();
            placed[slots[c]] = {leaf ? Kind::Leaf : Kind::Internal, children.nodes[c], 0};
        }
        for (WideDraftChild& child : placed) {
            if (child.kind != Kind::Internal) continue;
            child.wideNode = static_cast<std::uint32_t>(draft.nodes.size());
            draft.nodes.push_back({child.binaryNode, w, {}});
            depths.push_back(depths[w] + 1);
            draft.depth = std::max(draft.depth, depths.back());
        }
        for (auto child = placed.rbegin(); child != placed.rend(); ++child)
            if (child->kind == Kind::Internal) toFill.push_back(child->wideNode);
        draft.nodes[w].slots = placed;
    }
    return draft;
}

// ---------------------------------------------------------------------------------------------
// Quantisation.

constexpr std::uint32_t kQuantisedMax = 255;

// 2^(e − 127) for a biased exponent e in [1, 254].
float gridScale(std::uint32_t biasedExponent) {
    std::uint32_t bits = biasedExponent << 23;
    float scale;
    std::memcpy(&scale, &bits, sizeof scale);
    return scale;
}

// What the walk computes for a quantised bound: one rounding of an exact product's sum.
float decodeBound(float origin, std::uint32_t q, float scale) {
    return origin + float(q) * scale;
}

// The largest q whose decoded bound is at or below `lo`; the bound's own q if that overshoots.
std::uint32_t quantiseLow(float origin, float lo, float scale) {
    double q = std::floor((double(lo) - double(origin)) / double(scale));
    auto result = static_cast<std::uint32_t>(std::clamp(q, 0.0, double(kQuantisedMax)));
    while (result > 0 && decodeBound(origin, result, scale) > lo)
        --result;
    return result;
}

// The smallest q whose decoded bound is at or above `hi`, or kQuantisedMax + 1 if none fits.
std::uint32_t quantiseHigh(float origin, float hi, float scale) {
    double q = std::ceil((double(hi) - double(origin)) / double(scale));
    if (!(q <= double(kQuantisedMax))) return kQuantisedMax + 1;
    auto result = static_cast<std::uint32_t>(std::max(q, 0.0));
    while (result <= kQuantisedMax && decodeBound(origin, result, scale) < hi)
        ++result;
    return result;
}

// The smallest biased exponent whose grid of 255 steps from `origin` reaches past every bound.
std::uint32_t axisExponent(float origin, float extent, std::span<const float> highs) {
    std::uint32_t e = 1;
    if (extent > 0.0f) {
        int exponent = int(std::ceil(std::log2(double(extent) / kQuantisedMax)));
        e = std::uint32_t(std::clamp(exponent + 127, 1, 254));
    }
    for (; e < 254; ++e) {
        bool fits = true;
        for (float hi : highs)
            fits = fits && quantiseHigh(origin, hi, gridScale(e)) <= kQuantisedMax;
        if (fits) break;
    }
    return e;
}

void setQuantisedByte(gpu::WideBvhNode& node, std::uint32_t bound, std::uint32_t slot,
                      std::uint32_t value) {
    // bound 0..5: lo.x, lo.y, lo.z, hi.x, hi.y, hi.z; two words each, slot s in word s / 4.
    std::uint32_t word = 2 * bound + slot / 4;
    std::uint32_t& target = node.quantised[word / 4][int(word % 4)];
    target |= value << (8 * (slot % 4));
}

void quantiseChildren(const BvhTree& tree, const WideDraftNode& draft, gpu::WideBvhNode& node) {
    Aabb box;
    for (const WideDraftChild& child : draft.slots)
        if (child.kind != Kind::Empty) box.extend(tree.nodes[child.binaryNode].bounds);
    if (box.empty()) box = Aabb{glm::vec3(0.0f), glm::vec3(0.0f)};
    node.origin = box.min;
    std::uint32_t exponents[3];
    for (int axis = 0; axis < 3; ++axis) {
        std::array<float, WIDE_BVH_WIDTH> highs{};
        std::size_t count = 0;
        for (const WideDraftChild& child : draft.slots)
            if (child.kind != Kind::Empty)
                highs[count++] = tree.nodes[child.binaryNode].bounds.max[axis];
        exponents[axis] = axisExponent(box.min[axis], box.max[axis] - box.min[axis],
                                       std::span<const float>(highs.data(), count));
    }
    node.slotsAndExponents |= (exponents[0] << 8) | (exponents[1] << 16) | (exponents[2] << 24);
    for (std::uint32_t slot = 0; slot < WIDE_BVH_WIDTH; ++slot) {
        const WideDraftChild& child = draft.slots[slot];
        for (int axis = 0; axis < 3; ++axis) {
            std::uint32_t lo = kQuantisedMax, hi = 0; // an empty slot: lo > hi
            if (child.kind != Kind::Empty) {
                const Aabb& b = tree.nodes[child.binaryNode].bounds;
                const float scale = gridScale(exponents[axis]);
                lo = quantiseLow(node.origin[axis], b.min[axis], scale);
                hi = quantiseHigh(node.origin[axis], b.max[axis], scale);
                VKPT_ASSERT(hi <= kQuantisedMax, "quantised bound within the grid");
            }
            setQuantisedByte(node, std::uint32_t(axis), slot, lo);
            setQuantisedByte(node, std::uint32_t(axis) + 3, slot, hi);
        }
    }
}

// Appends each wide node's leaf primitives in slot order and points the tree's leaves there.
void relayoutPrimitives(BvhTree& tree, const WideDraft& draft,
                        std::vector<std::uint32_t>& primitiveBase) {
    std::vector<std::uint32_t> order;
    order.reserve(tree.primitiveOrder.size());
    primitiveBase.assign(draft.nodes.size(), 0);
    for (std::size_t w = 0; w < draft.nodes.size(); ++w) {
        primitiveBase[w] = static_cast<std::uint32_t>(order.size());
        for (const WideDraftChild& child : draft.nodes[w].slots) {
            if (child.kind != Kind::Leaf) continue;
            BvhBuildNode& leaf = tree.nodes[child.binaryNode];
            const auto first = static_cast<std::uint32_t>(order.size());
            for (std::uint32_t i = 0; i < leaf.primitiveCount; ++i)
                order.push_back(tree.primitiveOrder[leaf.firstPrimitive + i]);
            leaf.firstPrimitive = first;
        }
    }
    VKPT_ASSERT(order.size() == tree.primitiveOrder.size(), "every primitive in one leaf");
    tree.primitiveOrder = std::move(order);
}

gpu::WideBvhNode compressNode(const BvhTree& tree, const WideDraftNode& draft,
                              std::uint32_t primitiveBase) {
    gpu::WideBvhNode node{};
    node.parent = draft.parent;
    node.primitiveBase = primitiveBase;
    bool firstInternal = true;
    for (std::uint32_t slot = 0; slot < WIDE_BVH_WIDTH; ++slot) {
        const WideDraftChild& child = draft.slots[slot];
        if (child.kind == Kind::Internal) {
            if (firstInternal) node.childBase = child.wideNode;
            VKPT_ASSERT(child.wideNode == node.childBase + std::uint32_t(std::popcount(
                                                               node.slotsAndExponents & 0xffu)),
                        "internal children are contiguous in slot order");
            firstInternal = false;
            node.slotsAndExponents |= 1u << slot;
        } else if (child.kind == Kind::Leaf) {
            const std::uint32_t count = tree.nodes[child.binaryNode].primitiveCount;
            VKPT_ASSERT(count >= 1 && count <= BVH_MAX_LEAF_TRIANGLES, "leaf size fits 4 bits");
            node.leafCounts |= count << (4 * slot);
        }
    }
    quantiseChildren(tree, draft, node);
    return node;
}

} // namespace

WideDraft collapseBvh(const BvhTree& tree, CollapseOrder order) {
    VKPT_ASSERT(!tree.nodes.empty(), "a built tree has a root");
    WideDraft draft = collapseWith(tree, order);
    if (draft.depth > WIDE_BVH_MAX_DEPTH && order == CollapseOrder::LargestArea)
        draft = collapseWith(tree, CollapseOrder::Tallest);
    VKPT_ASSERT(draft.depth <= WIDE_BVH_MAX_DEPTH, "wide tree within the walk's bit stack");
    return draft;
}

std::vector<gpu::WideBvhNode> flattenWideBvh(BvhTree& tree, CollapseOrder order) {
    const WideDraft draft = collapseBvh(tree, order);
    std::vector<std::uint32_t> primitiveBase;
    relayoutPrimitives(tree, draft, primitiveBase);
    std::vector<gpu::WideBvhNode> nodes;
    nodes.reserve(draft.nodes.size());
    for (std::size_t w = 0; w < draft.nodes.size(); ++w)
        nodes.push_back(compressNode(tree, draft.nodes[w], primitiveBase[w]));
    return nodes;
}

std::array<Aabb, WIDE_BVH_WIDTH> decodeChildBoxes(const gpu::WideBvhNode& node) {
    std::array<Aabb, WIDE_BVH_WIDTH> boxes{};
    const std::uint32_t exponents[3] = {(node.slotsAndExponents >> 8) & 0xffu,
                                        (node.slotsAndExponents >> 16) & 0xffu,
                                        node.slotsAndExponents >> 24};
    for (std::uint32_t slot = 0; slot < WIDE_BVH_WIDTH; ++slot) {
        for (int axis = 0; axis < 3; ++axis) {
            auto byte = [&](std::uint32_t bound) {
                std::uint32_t word = 2 * bound + slot / 4;
                return (node.quantised[word / 4][int(word % 4)] >> (8 * (slot % 4))) & 0xffu;
            };
            std::uint32_t lo = byte(std::uint32_t(axis)), hi = byte(std::uint32_t(axis) + 3);
            if (lo > hi) {
                boxes[slot] = Aabb{};
                break;
            }
            const float scale = gridScale(exponents[axis]);
            boxes[slot].min[axis] = decodeBound(node.origin[axis], lo, scale);
            boxes[slot].max[axis] = decodeBound(node.origin[axis], hi, scale);
        }
    }
    return boxes;
}

WideBvhStats computeWideBvhStats(const std::vector<gpu::WideBvhNode>& nodes) {
    WideBvhStats stats;
    stats.nodeCount = static_cast<std::uint32_t>(nodes.size());
    std::vector<std::uint32_t> depth(nodes.size(), 0);
    std::uint64_t occupied = 0;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const gpu::WideBvhNode& n = nodes[i];
        if (n.parent != BVH_END) depth[i] = depth[n.parent] + 1;
        stats.depth = std::max(stats.depth, depth[i]);
        for (std::uint32_t slot = 0; slot < WIDE_BVH_WIDTH; ++slot) {
            const bool leaf = ((n.leafCounts >> (4 * slot)) & 15u) != 0;
            stats.leafCount += leaf ? 1 : 0;
            occupied += (leaf || ((n.slotsAndExponents >> slot) & 1u)) ? 1 : 0;
        }
    }
    stats.childrenPerNode = nodes.empty() ? 0.0 : double(occupied) / double(nodes.size());
    return stats;
}

} // namespace vkpt
