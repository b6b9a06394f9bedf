// kernel_memo.h — the pipelines a device has made, kept for its life: a render that needs a
// pipeline an earlier render on the same GpuContext made (the same SPIR-V, bindings, push
// constants and specialisation) takes that one instead of compiling it again. A sequence of
// renders in one process — a test's sweep over scenes and settings, an animation's frames —
// then compiles each kernel once per feature set instead of once per render.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "gpu/kernel.h"

namespace vkpt {

// Whether two descriptions make the same pipeline. The SPIR-V is compared by its storage (the
// embedded kernel library holds each build once), the rest (where the constants are folded
// included) by value.
bool sameKernel(const KernelDesc& a, const KernelDesc& b);

class KernelMemo {
public:
    // The kept kernel made from `desc`, or null.
    std::shared_ptr<const Kernel> find(const KernelDesc& desc) const;
    // Keeps `kernel` and hands it back shared; when another thread kept the same pipeline
    // meanwhile, that one (and `kernel` is destroyed).
    std::shared_ptr<const Kernel> keep(Kernel kernel);
    // Destroys every kept pipeline (before the device goes).
    void clear();
    std::size_t size() const;

private:
    mutable std::mutex mutex_;
    // A render needs seven, a test sweep tens: a list beats a hash of the whole description.
    std::vector<std::shared_ptr<const Kernel>> kernels_;
};

} // namespace vkpt
