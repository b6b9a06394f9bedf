// state_merge.h — parts of one render (tasks, crops, checkpoints of either executor) combined
// into one state, exactly: per pixel, Chan et al.'s combination of disjoint sample sets.
#pragma once

#include <string>
#include <vector>

#include "state/render_state.h"

namespace vkpt {

struct StatePart {
    std::string path; // for messages
    RenderState state;
};

// Throws InputError "<path>: <reason>" naming the first part that cannot join the others: another
// scene, other settings, seed or image size, or samples of a pixel that another part already has.
// The result does not depend on the order of the parts (they are combined in the order of their
// first sample index, then of their windows).
RenderState mergeStates(std::vector<StatePart> parts);

// Throws InputError "<part.path>: <reason>" when `part` is of another scene, settings, seed or
// image size than `reference`.
void checkSameRender(const StatePart& reference, const StatePart& part);

// The InputError mergeStates would throw, or nothing when the parts can merge.
void checkPartsCompatible(const std::vector<StatePart>& parts);

} // namespace vkpt
