// worker_threads.h — runs one function on several threads and rethrows the first failure on
// the caller's, for the host's data-parallel passes (BVH build and collapse).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <thread>
#include <vector>

namespace vkpt {

// The number of threads to use: `requested`, or one per hardware thread when 0.
inline std::uint32_t resolveThreadCount(std::uint32_t requested) {
    return requested > 0 ? requested : std::max(1u, std::thread::hardware_concurrency());
}

// Calls work(w) for w in [0, threadCount): w = 0 on the calling thread, the others on threads
// started for the call. Returns when all are done; an exception from any is rethrown here
// (the lowest worker's first).
template <typename Work> void runOnWorkers(std::uint32_t threadCount, const Work& work) {
    std::vector<std::exception_ptr> errors(std::max(threadCount, 1u));
    auto guarded = [&](std::uint32_t worker) {
        try {
            work(worker);
        } catch (...) {
            errors[worker] = std::current_exception();
        }
    };
    std::vector<std::thread> threads;
    for (std::uint32_t w = 1; w < threadCount; ++w)
        threads.emplace_back(guarded, w);
    guarded(0);
    for (std::thread& t : threads)
        t.join();
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);
}

// Splits [0, count) into threadCount contiguous slices and calls work(begin, end, worker)
// on each, in parallel.
template <typename Work>
void forEachSlice(std::size_t count, std::uint32_t threadCount, const Work& work) {
    const std::uint32_t workers =
        std::uint32_t(std::clamp<std::size_t>(count, 1, std::max(threadCount, 1u)));
    runOnWorkers(workers,
                 [&](std::uint32_t w) { work(count * w / workers, count * (w + 1) / workers, w); });
}

} // namespace vkpt
