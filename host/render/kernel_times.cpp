// kernel_times.cpp — sums timestamp intervals by label.
#include "render/kernel_times.h"

#include <algorithm>

namespace vkpt {

void KernelTimeTotals::add(const std::vector<KernelTime>& intervals) {
    for (const KernelTime& interval : intervals) {
        auto it = std::find_if(totals_.begin(), totals_.end(), [&](const KernelTimeTotal& t) {
            return t.kernel == interval.label;
        });
        if (it == totals_.end()) it = totals_.insert(totals_.end(), {interval.label, 0, 0});
        it->dispatches += 1;
        it->nanoseconds += interval.nanoseconds;
    }
}

} // namespace vkpt
