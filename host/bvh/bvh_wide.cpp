// bvh_wide.cpp — collapses the binary tree into 8-wide nodes, assigns slots by octant, lays
// the leaves' primitives out per node and quantises the child boxes conservatively.
#include "bvh/bvh_wide.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstring>
#include <span>
#include <utility>

#include "common/errors.h"
#include "common/worker_threads.h"

namespace vkpt {

namespace {

using Kind = WideDraftChild::Kind;

// Below this many wide nodes one thread lays them out faster than it can start others.
constexpr std::size_t kParallelNodeMinimum = 4096;

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
constexpr glm::vec3 octantDirection(std::uint32_t s) {
    return {(s & 1u) ? -1.0f : 1.0f, (s & 2u) ? -1.0f : 1.0f, (s & 4u) ? -1.0f : 1.0f};
}

constexpr std::array<glm::vec3, WIDE_BVH_WIDTH> kOctantDirections = {
    octantDirection(0), octantDirection(1), octantDirection(2), octantDirection(3),
    octantDirection(4), octantDirection(5), octantDirection(6), octantDirection(7)};

// Slot s should hold the child that a ray travelling along octant s's direction reaches
// first: the one whose centre lies lowest along that direction (Ylitie et al. 2017, section
// 3.2, assign the same way with an auction). Greedy: the cheapest (child, slot) pair whose
// child and slot are both free is placed next, ties to the lower child, then the lower slot
// (at most 8 rounds over the free pairs, kept as bit masks; no sort).
std::array<std::uint32_t, WIDE_BVH_WIDTH> assignSlots(const BvhTree& tree, std::uint32_t parent,
                                                      const ChildList& children) {
    const glm::vec3 centre = tree.nodes[parent].bounds.centre();
    std::array<std::array<float, WIDE_BVH_WIDTH>, WIDE_BVH_WIDTH> cost{};
    for (std::uint32_t c = 0; c < children.count; ++c) {
        glm::vec3 offset = tree.nodes[children.nodes[c]].bounds.centre() - centre;
        for (std::uint32_t s = 0; s < WIDE_BVH_WIDTH; ++s)
            cost[c][s] = glm::dot(offset, kOctantDirections[s]);
    }
    std::array<std::uint32_t, WIDE_BVH_WIDTH> slotOfChild{};
    std::uint32_t freeChildren = (1u << children.count) - 1u, freeSlots = 0xffu;
    while (freeChildren != 0) {
        std::uint32_t bestChild = WIDE_BVH_WIDTH, bestSlot = 0;
        for (std::uint32_t cs = freeChildren; cs != 0; cs &= cs - 1u) {
            const auto c = std::uint32_t(std::countr_zero(cs));
            for (std::uint32_t ss = freeSlots; ss != 0; ss &= ss - 1u) {
                const auto s = std::uint32_t(std::countr_zero(ss));
                // The first free pair is taken whatever its cost, so a NaN cost (centres of
                // boxes beyond ±FLT_MAX / 2) still gets a slot.
                if (bestChild == WIDE_BVH_WIDTH || cost[c][s] < cost[bestChild][bestSlot]) {
                    bestChild = c;
                    bestSlot = s;
                }
            }
        }
        freeChildren &= ~(1u << bestChild);
        freeSlots &= ~(1u << bestSlot);
        slotOfChild[bestChild] = bestSlot;
    }
    return slotOfChild;
}

// The node after each binary node's subtree: children follow their parents depth first, the
// right subtree last, so one backward pass gives them all.
std::vector<std::uint32_t> subtreeEnds(const BvhTree& tree) {
    std::vector<std::uint32_t> ends(tree.nodes.size());
    for (std::size_t i = tree.nodes.size(); i-- > 0;) {
        const BvhBuildNode& n = tree.nodes[i];
        ends[i] = n.isLeaf() ? std::uint32_t(i + 1) : ends[n.rightChild];
    }
    return ends;
}

struct CollapseInput {
    const BvhTree& tree;
    CollapseOrder order;
    const std::vector<std::uint32_t>& heights; // Tallest's key; empty for LargestArea
};

// Fills wide node `start` of the draft and, depth first, the nodes it makes. A node's internal
// children are made together, so they are contiguous; nodes are filled depth first, so a
// subtree's nodes (and, laid out in node order, its primitives) lie close together in memory,
// which a walk down one path of a large tree finds in fewer cache lines. An internal child
// whose binary node `defer` accepts is made but not filled, and listed in `deferred`.
template <typename Defer>
void fillDepthFirst(const CollapseInput& in, std::uint32_t start, WideDraft& draft,
                    std::vector<std::uint32_t>& depths, const Defer& defer,
                    std::vector<std::uint32_t>& deferred) {
    std::vector<std::uint32_t> toFill{start};
    while (!toFill.empty()) {
        const std::uint32_t w = toFill.back();
        toFill.pop_back();
        const std::uint32_t binary = draft.nodes[w].binaryNode;
        const ChildList children = openChildren(in.tree, binary, in.order, in.heights);
        const auto slots = assignSlots(in.tree, binary, children);
        std::array<WideDraftChild, WIDE_BVH_WIDTH> placed{};
        for (std::uint32_t c = 0; c < children.count; ++c) {
            const bool leaf = in.tree.nodes[children.nodes[c]].isLeaf();
            placed[slots[c]] = {leaf ? Kind::Leaf : Kind::Internal, children.nodes[c], 0};
        }
        for (WideDraftChild& child : placed) {
            if (child.kind != Kind::Internal) continue;
            child.wideNode = static_cast<std::uint32_t>(draft.nodes.size());
            draft.nodes.push_back({child.binaryNode, w, {}});
            depths.push_back(depths[w] + 1);
            draft.depth = std::max(draft.depth, depths.back());
            if (defer(child.binaryNode)) deferred.push_back(child.wideNode);
        }
        for (auto child = placed.rbegin(); child != placed.rend(); ++child)
            if (child->kind == Kind::Internal && !defer(child->binaryNode))
                toFill.push_back(child->wideNode);
        draft.nodes[w].slots = placed;
    }
}

// A wide subtree collapsed apart: node 0 stands for the block's root in the whole draft.
struct CollapsedBlock {
    WideDraft draft;
    std::uint32_t root = 0; // the root's index in the whole draft
};

CollapsedBlock collapseBlock(const CollapseInput& in, std::uint32_t root, std::uint32_t binary) {
    CollapsedBlock block;
    block.root = root;
    block.draft.nodes.push_back({binary, BVH_END, {}});
    std::vector<std::uint32_t> depths{0}, none;
    fillDepthFirst(
        in, 0, block.draft, depths, [](std::uint32_t) { return false; }, none);
    return block;
}

// Appends a block's nodes after the draft's, its node 0 becoming the root it stands for.
void appendBlock(const CollapsedBlock& block, std::uint32_t rootDepth, WideDraft& draft) {
    const auto base = static_cast<std::uint32_t>(draft.nodes.size()) - 1u;
    auto global = [&](std::uint32_t local) { return local == 0 ? block.root : base + local; };
    auto remapSlots = [&](std::array<WideDraftChild, WIDE_BVH_WIDTH> slots) {
        for (WideDraftChild& child : slots)
            if (child.kind == Kind::Internal) child.wideNode = global(child.wideNode);
        return slots;
    };
    draft.nodes[block.root].slots = remapSlots(block.draft.nodes[0].slots);
    for (std::size_t i = 1; i < block.draft.nodes.size(); ++i) {
        const WideDraftNode& node = block.draft.nodes[i];
        draft.nodes.push_back({node.binaryNode, global(node.parent), remapSlots(node.slots)});
    }
    draft.depth = std::max(draft.depth, rootDepth + block.draft.depth);
}

// Binary subtrees of at most this many nodes are collapsed as blocks, in parallel, and laid
// out after the wide nodes above them, one block after another. The blocks depend on the tree
// alone, so the result does not depend on the thread count; a tree this small is one block
// under its root, laid out as one depth-first fill would.
constexpr std::uint32_t kBlockNodes = 4096;

WideDraft collapseWith(const BvhTree& tree, CollapseOrder order, std::uint32_t threadCount) {
    const std::vector<std::uint32_t> heights =
        order == CollapseOrder::Tallest ? subtreeHeights(tree) : std::vector<std::uint32_t>{};
    const CollapseInput in{tree, order, heights};
    const std::vector<std::uint32_t> ends = subtreeEnds(tree);
    auto isBlock = [&](std::uint32_t binary) { return ends[binary] - binary <= kBlockNodes; };
    WideDraft draft;
    // Each wide node stands for a distinct interior binary node (or the root leaf).
    draft.nodes.reserve(tree.nodes.size() / 2 + 1);
    draft.nodes.push_back({0, BVH_END, {}});
    std::vector<std::uint32_t> depths{0};
    std::vector<std::uint32_t> blockRoots;
    fillDepthFirst(in, 0, draft, depths, isBlock, blockRoots);
    std::vector<CollapsedBlock> blocks(blockRoots.size());
    std::atomic<std::size_t> next{0};
    const std::uint32_t threads = blockRoots.size() > 1 ? resolveThreadCount(threadCount) : 1u;
    runOnWorkers(threads, [&](std::uint32_t) {
        for (std::size_t k = next++; k < blockRoots.size(); k = next++)
            blocks[k] = collapseBlock(in, blockRoots[k], draft.nodes[blockRoots[k]].binaryNode);
    });
    for (const CollapsedBlock& block : blocks)
        appendBlock(block, depths[block.root], draft);
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
// (Multiplying by 1 / scale, a power of two, is exact: the same as dividing, and faster.)
std::uint32_t quantiseLow(float origin, float lo, float scale) {
    double q = std::floor((double(lo) - double(origin)) * (1.0 / double(scale)));
    auto result = static_cast<std::uint32_t>(std::clamp(q, 0.0, double(kQuantisedMax)));
    while (result > 0 && decodeBound(origin, result, scale) > lo)
        --result;
    return result;
}

// The smallest q whose decoded bound is at or above `hi`, or kQuantisedMax + 1 if none fits.
std::uint32_t quantiseHigh(float origin, float hi, float scale) {
    double q = std::ceil((double(hi) - double(origin)) * (1.0 / double(scale)));
    if (!(q <= double(kQuantisedMax))) return kQuantisedMax + 1;
    auto result = static_cast<std::uint32_t>(std::max(q, 0.0));
    while (result <= kQuantisedMax && decodeBound(origin, result, scale) < hi)
        ++result;
    return result;
}

// One axis of a node's children on its grid: the exponent and each child's bounds' steps.
struct QuantisedAxis {
    std::uint32_t exponent = 1;
    std::array<std::uint32_t, WIDE_BVH_WIDTH> lows{};
    std::array<std::uint32_t, WIDE_BVH_WIDTH> highs{};
};

// The smallest biased exponent whose grid of 255 steps from `origin` reaches past every high
// bound, and the bounds' steps on it; the highs found while searching are the ones kept.
QuantisedAxis quantiseAxis(float origin, float extent, std::span<const float> lows,
                           std::span<const float> highs) {
    QuantisedAxis axis;
    std::uint32_t e = 1;
    if (extent > 0.0f) {
        int exponent = int(std::ceil(std::log2(double(extent) / kQuantisedMax)));
        e = std::uint32_t(std::clamp(exponent + 127, 1, 254));
    }
    for (;; ++e) {
        bool fits = true;
        for (std::size_t c = 0; c < highs.size(); ++c) {
            axis.highs[c] = quantiseHigh(origin, highs[c], gridScale(e));
            fits = fits && axis.highs[c] <= kQuantisedMax;
        }
        if (fits || e == 254) break;
    }
    axis.exponent = e;
    for (std::size_t c = 0; c < lows.size(); ++c)
        axis.lows[c] = quantiseLow(origin, lows[c], gridScale(e));
    return axis;
}

void setQuantisedByte(gpu::WideBvhNode& node, std::uint32_t bound, std::uint32_t slot,
                      std::uint32_t value) {
    // bound 0..5: lo.x, lo.y, lo.z, hi.x, hi.y, hi.z; two words each, slot s in word s / 4.
    std::uint32_t word = 2 * bound + slot / 4;
    std::uint32_t& target = node.quantised[word / 4][int(word % 4)];
    const std::uint32_t shift = 8 * (slot % 4);
    target = (target & ~(0xffu << shift)) | (value << shift);
}

void quantiseChildren(const BvhTree& tree, const WideDraftNode& draft, gpu::WideBvhNode& node) {
    std::array<const Aabb*, WIDE_BVH_WIDTH> boxes{};
    std::array<std::uint32_t, WIDE_BVH_WIDTH> slots{};
    std::size_t count = 0;
    Aabb box;
    for (std::uint32_t slot = 0; slot < WIDE_BVH_WIDTH; ++slot) {
        const WideDraftChild& child = draft.slots[slot];
        if (child.kind == Kind::Empty) continue;
        boxes[count] = &tree.nodes[child.binaryNode].bounds;
        slots[count++] = slot;
        box.extend(*boxes[count - 1]);
    }
    if (box.empty()) box = Aabb{glm::vec3(0.0f), glm::vec3(0.0f)};
    node.origin = box.min;
    // An empty slot: lo > hi.
    for (std::uint32_t slot = 0; slot < WIDE_BVH_WIDTH; ++slot)
        for (std::uint32_t axis = 0; axis < 3; ++axis) {
            setQuantisedByte(node, axis, slot, kQuantisedMax);
            setQuantisedByte(node, axis + 3, slot, 0);
        }
    for (int axis = 0; axis < 3; ++axis) {
        std::array<float, WIDE_BVH_WIDTH> lows{}, highs{};
        for (std::size_t c = 0; c < count; ++c) {
            lows[c] = boxes[c]->min[axis];
            highs[c] = boxes[c]->max[axis];
        }
        const QuantisedAxis q = quantiseAxis(box.min[axis], box.max[axis] - box.min[axis],
                                             std::span<const float>(lows.data(), count),
                                             std::span<const float>(highs.data(), count));
        node.slotsAndExponents |= q.exponent << (8 * (axis + 1));
        for (std::size_t c = 0; c < count; ++c) {
            VKPT_ASSERT(q.highs[c] <= kQuantisedMax, "quantised bound within the grid");
            setQuantisedByte(node, std::uint32_t(axis), slots[c], q.lows[c]);
            setQuantisedByte(node, std::uint32_t(axis) + 3, slots[c], q.highs[c]);
        }
    }
}

// Lays each wide node's leaf primitives out in slot order, node after node, and points the
// tree's leaves there: the places come from a prefix sum of the nodes' primitive counts, so
// that slices of the nodes are laid out in parallel (each leaf belongs to one wide node).
void relayoutPrimitives(BvhTree& tree, const WideDraft& draft,
                        std::vector<std::uint32_t>& primitiveBase, std::uint32_t threadCount) {
    auto primitivesOf = [&](const WideDraftNode& node) {
        std::uint32_t count = 0;
        for (const WideDraftChild& child : node.slots)
            if (child.kind == Kind::Leaf) count += tree.nodes[child.binaryNode].primitiveCount;
        return count;
    };
    primitiveBase.assign(draft.nodes.size(), 0);
    forEachSlice(draft.nodes.size(), threadCount,
                 [&](std::size_t begin, std::size_t end, std::uint32_t) {
                     for (std::size_t w = begin; w < end; ++w)
                         primitiveBase[w] = primitivesOf(draft.nodes[w]);
                 });
    std::uint32_t total = 0;
    for (std::uint32_t& base : primitiveBase)
        total += std::exchange(base, total);
    VKPT_ASSERT(total == tree.primitiveOrder.size(), "every primitive in one leaf");
    std::vector<std::uint32_t> order(total);
    forEachSlice(draft.nodes.size(), threadCount,
                 [&](std::size_t begin, std::size_t end, std::uint32_t) {
                     for (std::size_t w = begin; w < end; ++w) {
                         std::uint32_t next = primitiveBase[w];
                         for (const WideDraftChild& child : draft.nodes[w].slots) {
                             if (child.kind != Kind::Leaf) continue;
                             BvhBuildNode& leaf = tree.nodes[child.binaryNode];
                             for (std::uint32_t i = 0; i < leaf.primitiveCount; ++i)
                                 order[next + i] = tree.primitiveOrder[leaf.firstPrimitive + i];
                             leaf.firstPrimitive = next;
                             next += leaf.primitiveCount;
                         }
                     }
                 });
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

WideDraft collapseBvh(const BvhTree& tree, CollapseOrder order, std::uint32_t threadCount) {
    VKPT_ASSERT(!tree.nodes.empty(), "a built tree has a root");
    WideDraft draft = collapseWith(tree, order, threadCount);
    if (draft.depth > WIDE_BVH_MAX_DEPTH && order == CollapseOrder::LargestArea)
        draft = collapseWith(tree, CollapseOrder::Tallest, threadCount);
    VKPT_ASSERT(draft.depth <= WIDE_BVH_MAX_DEPTH, "wide tree within the walk's bit stack");
    return draft;
}

// The layout and the compression, node by node, on slices of the nodes in parallel (the
// result does not depend on the thread count).
std::vector<gpu::WideBvhNode> flattenWideBvh(BvhTree& tree, CollapseOrder order,
                                             std::uint32_t threadCount) {
    const WideDraft draft = collapseBvh(tree, order, threadCount);
    const std::uint32_t threads =
        draft.nodes.size() >= kParallelNodeMinimum ? resolveThreadCount(threadCount) : 1u;
    std::vector<std::uint32_t> primitiveBase;
    relayoutPrimitives(tree, draft, primitiveBase, threads);
    std::vector<gpu::WideBvhNode> nodes(draft.nodes.size());
    forEachSlice(draft.nodes.size(), threads,
                 [&](std::size_t begin, std::size_t end, std::uint32_t) {
                     for (std::size_t w = begin; w < end; ++w)
                         nodes[w] = compressNode(tree, draft.nodes[w], primitiveBase[w]);
                 });
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
