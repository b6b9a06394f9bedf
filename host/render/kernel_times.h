// kernel_times.h — GPU time per kernel over a whole render (--stats), summed from the
// timestamp intervals of every submission.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/device_stats.h"
#include "gpu/timestamps.h"

namespace vkpt {

class KernelTimeTotals {
public:
    // Adds one submission's intervals, each labelled with its kernel's name.
    void add(const std::vector<KernelTime>& intervals);
    // In the order the kernels first ran.
    const std::vector<KernelTimeTotal>& totals() const { return totals_; }

private:
    std::vector<KernelTimeTotal> totals_;
};

} // namespace vkpt
