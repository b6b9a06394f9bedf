// bench_statistics.h — the benchmarks' one summary of repeated runs: the median, which one slow
// run on a shared machine does not move.
#pragma once

#include <algorithm>
#include <vector>

namespace vkpt::bench {

inline double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

} // namespace vkpt::bench
