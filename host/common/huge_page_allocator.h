// huge_page_allocator.h — an allocator for large arrays that a walk reads at random (the CPU
// reference's BVH nodes and triangles): backed by 2 MiB transparent huge pages where Linux
// offers them on request (madvise), so that a walk of a 50 MB tree misses the TLB far less
// often than with 4 KiB pages. Small arrays, and other systems, get ordinary memory.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace vkpt {

inline constexpr std::size_t kHugePageBytes = std::size_t(2) << 20;

template <typename T> class HugePageAllocator {
public:
    using value_type = T;

    HugePageAllocator() = default;
    template <typename U> HugePageAllocator(const HugePageAllocator<U>&) {}

    T* allocate(std::size_t n) {
        const std::size_t bytes = n * sizeof(T);
        if (!useHugePages(bytes)) return static_cast<T*>(::operator new(bytes, alignOf()));
        // Whole huge pages, aligned to one, so that the kernel can map every part with them.
        const std::size_t rounded = (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
        void* p = std::aligned_alloc(kHugePageBytes, rounded);
        if (p == nullptr) throw std::bad_alloc();
#if defined(__linux__)
        madvise(p, rounded, MADV_HUGEPAGE); // a hint: without THP the pages stay 4 KiB
#endif
        return static_cast<T*>(p);
    }

    void deallocate(T* p, std::size_t n) {
        if (useHugePages(n * sizeof(T)))
            std::free(p);
        else
            ::operator delete(p, alignOf());
    }

    template <typename U> bool operator==(const HugePageAllocator<U>&) const {
        return true;
    }

private:
    // Below a few huge pages the TLB is no concern and rounding up would waste memory.
    static bool useHugePages(std::size_t bytes) {
        return bytes >= 4 * kHugePageBytes;
    }
    static std::align_val_t alignOf() {
        return std::align_val_t(alignof(T));
    }
};

} // namespace vkpt
