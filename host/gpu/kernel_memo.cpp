// kernel_memo.cpp — the device's kept pipelines, looked up by their description.
#include "gpu/kernel_memo.h"

#include <algorithm>

namespace vkpt {

namespace {

bool sameBinding(const KernelBinding& a, const KernelBinding& b) {
    return a.binding == b.binding && a.kind == b.kind && a.count == b.count;
}

bool sameConstant(const SpecializationConstant& a, const SpecializationConstant& b) {
    return a.id == b.id && a.value == b.value;
}

// Without constants there is nothing to fold: the module the driver gets is the same.
bool foldsOnHost(const KernelDesc& desc) {
    return desc.foldConstantsOnHost && !desc.specializationConstants.empty();
}

} // namespace

bool sameKernel(const KernelDesc& a, const KernelDesc& b) {
    return a.name == b.name && a.spirv.data() == b.spirv.data() &&
           a.spirv.size() == b.spirv.size() && a.pushConstantSize == b.pushConstantSize &&
           foldsOnHost(a) == foldsOnHost(b) &&
           std::ranges::equal(a.bindings, b.bindings, sameBinding) &&
           std::ranges::equal(a.specializationConstants, b.specializationConstants, sameConstant);
}

std::shared_ptr<const Kernel> KernelMemo::find(const KernelDesc& desc) const {
    std::lock_guard lock(mutex_);
    for (const auto& kernel : kernels_)
        if (sameKernel(kernel->desc(), desc)) return kernel;
    return nullptr;
}

std::shared_ptr<const Kernel> KernelMemo::keep(Kernel kernel) {
    std::lock_guard lock(mutex_);
    for (const auto& kept : kernels_)
        if (sameKernel(kept->desc(), kernel.desc())) return kept;
    kernels_.push_back(std::make_shared<const Kernel>(std::move(kernel)));
    return kernels_.back();
}

void KernelMemo::clear() {
    std::lock_guard lock(mutex_);
    kernels_.clear();
}

std::size_t KernelMemo::size() const {
    std::lock_guard lock(mutex_);
    return kernels_.size();
}

} // namespace vkpt
