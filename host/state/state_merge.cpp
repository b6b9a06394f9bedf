// state_merge.cpp — compatibility checks, then a fold of the parts in a fixed order.
#include "state/state_merge.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <tuple>

#include "common/errors.h"

namespace vkpt {

namespace {

[[noreturn]] void refuse(const StatePart& part, const std::string& reason) {
    throw InputError(part.path + ": " + reason);
}

} // namespace

void checkSameRender(const StatePart& first, const StatePart& part) {
    const StateIdentity& a = first.state.identity;
    const StateIdentity& b = part.state.identity;
    if (b.sceneHash != a.sceneHash)
        refuse(part, "another scene than " + first.path + " (scene hash " + b.sceneHash + ", not " +
                         a.sceneHash + ")");
    if (b.width != a.width || b.height != a.height)
        refuse(part, "image size " + std::to_string(b.width) + "x" + std::to_string(b.height) +
                         " differs from " + first.path + "'s " + std::to_string(a.width) + "x" +
                         std::to_string(a.height));
    if (b.settings != a.settings)
        refuse(part, "settings '" + b.settings + "' differ from " + first.path + "'s '" +
                         a.settings + "'");
    if (b.seed != a.seed)
        refuse(part, "seed " + std::to_string(b.seed) + " differs from " + first.path + "'s seed " +
                         std::to_string(a.seed));
}

namespace {

void checkNoSharedSamples(const StatePart& earlier, const StatePart& part) {
    for (const Region& a : earlier.state.regions)
        for (const Region& b : part.state.regions) {
            if (!a.rect.intersects(b.rect)) continue;
            for (const SampleRange& ra : a.ranges)
                for (const SampleRange& rb : b.ranges)
                    if (ra.overlaps(rb))
                        refuse(part, "its samples " + describeRanges({rb}) + " of pixels " +
                                         describeRect(b.rect) + " are also in " + earlier.path);
        }
}

std::uint32_t firstSample(const RenderState& state) {
    std::uint32_t first = UINT32_MAX;
    for (const Region& r : state.regions)
        for (const SampleRange& range : r.ranges)
            first = std::min(first, range.begin);
    return first;
}

// Regions of one rectangle become one, with their ranges joined.
std::vector<Region> joinedRegions(const std::vector<StatePart>& parts) {
    std::vector<Region> regions;
    for (const StatePart& part : parts)
        for (const Region& region : part.state.regions) {
            auto same = std::find_if(regions.begin(), regions.end(),
                                     [&](const Region& r) { return r.rect == region.rect; });
            if (same == regions.end()) {
                regions.push_back(region);
                continue;
            }
            same->ranges.insert(same->ranges.end(), region.ranges.begin(), region.ranges.end());
            same->ranges = normalizedRanges(same->ranges);
        }
    return regions;
}

void foldPart(RenderState& merged, const RenderState& part) {
    const PixelRect& w = part.window;
    for (std::uint32_t y = w.y0; y < w.y1; ++y)
        for (std::uint32_t x = w.x0; x < w.x1; ++x) {
            PixelRecord& target = merged.at(x, y);
            target = combineRecords(target, part.at(x, y));
            const std::size_t i =
                std::size_t(y - merged.window.y0) * merged.window.width() + (x - merged.window.x0);
            const std::size_t j = std::size_t(y - w.y0) * w.width() + (x - w.x0);
            // Each part's features cover its own samples, as its moments do.
            if (!part.features.empty())
                merged.features[i] = combineFeatures(merged.features[i], part.features[j]);
        }
}

} // namespace

void checkPartsCompatible(const std::vector<StatePart>& parts) {
    for (std::size_t i = 1; i < parts.size(); ++i)
        checkSameRender(parts[0], parts[i]);
    for (std::size_t i = 0; i < parts.size(); ++i)
        for (std::size_t j = i + 1; j < parts.size(); ++j)
            checkNoSharedSamples(parts[i], parts[j]);
}

RenderState mergeStates(std::vector<StatePart> parts) {
    VKPT_ASSERT(!parts.empty(), "merging needs at least one part");
    checkPartsCompatible(parts);
    std::stable_sort(parts.begin(), parts.end(), [](const StatePart& a, const StatePart& b) {
        return std::make_tuple(firstSample(a.state), a.state.window.y0, a.state.window.x0) <
               std::make_tuple(firstSample(b.state), b.state.window.y0, b.state.window.x0);
    });
    RenderState merged;
    merged.identity = parts[0].state.identity;
    merged.origin = {"vkpt-merge", parts[0].state.origin.scene, ""};
    for (const StatePart& part : parts)
        merged.window = boundingRect(merged.window, part.state.window);
    merged.regions = joinedRegions(parts);
    merged.pixels.assign(merged.window.area(), PixelRecord{});
    // AOV layers when any part has them; a part without them adds no feature samples.
    const bool anyFeatures = std::any_of(parts.begin(), parts.end(), [](const StatePart& part) {
        return !part.state.features.empty();
    });
    if (anyFeatures) merged.features.assign(merged.window.area(), FeatureRecord{});
    for (const StatePart& part : parts)
        foldPart(merged, part.state);
    return merged;
}

} // namespace vkpt
