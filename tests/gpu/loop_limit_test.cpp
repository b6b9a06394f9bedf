// loop_limit_test.cpp — measures how many loop iterations an invocation really runs. Mesa
// 22.3's lavapipe (llvmpipe) gives its loops one shared iteration budget and silently leaves
// every loop once it is spent; a conforming device runs them all. The figures printed here
// are the ones docs/gpu.md reports, and traversal loops must stay within the budget there.
#include "gpu_test_support.h"
#include "kernel_test_io.h"

#include <cstdio>

namespace vkpt::test::loop_limit_test {
namespace {

using gpu::test::LoopCounts;
using gpu::test::LoopParams;

LoopParams loops(std::uint32_t first, std::uint32_t second, std::uint32_t outer,
                 std::uint32_t inner, std::uint32_t firstInvocation = ALL_INVOCATIONS) {
    return {first, second, outer, inner, firstInvocation, 0, 0, 0};
}

class LoopLimit : public GpuTest {
protected:
    // Runs one workgroup and returns every invocation's counts.
    std::vector<LoopCounts> measure(const LoopParams& params) {
        const Buffer loopCounts =
            makeStorageBuffer("loopCounts", WORKGROUP_SIZE * sizeof(LoopCounts));
        const Kernel kernel = makeKernel("count_loop_iterations", 1, sizeof(LoopParams));
        runKernel(kernel, {&loopCounts}, WORKGROUP_SIZE, pushConstantBytes(params));
        return download<LoopCounts>(context(), loopCounts, WORKGROUP_SIZE);
    }

    // For loops every invocation runs alike: all must report the same counts.
    LoopCounts measureUniform(const LoopParams& params) {
        const std::vector<LoopCounts> counts = measure(params);
        for (const LoopCounts& c : counts) {
            EXPECT_EQ(c.first, counts[0].first);
            EXPECT_EQ(c.second, counts[0].second);
            EXPECT_EQ(c.nested, counts[0].nested);
        }
        std::printf("loops of %u, %u and %u x %u iterations ran %u, %u and %u\n", params.firstLoop,
                    params.secondLoop, params.outerLoop, params.innerLoop, counts[0].first,
                    counts[0].second, counts[0].nested);
        return counts[0];
    }

    bool isLavapipe() { return context().deviceInfo().driverId == VK_DRIVER_ID_MESA_LLVMPIPE; }
};

// What Mesa 22.3.6 lavapipe does, measured by these tests (gallivm's loop limiter,
// LP_MAX_TGSI_LOOP_ITERATIONS = 65535, counts every loop-condition test of the invocation,
// the failing one that ends a loop included). Another Mesa may differ; then this test says so.
constexpr std::uint32_t kLavapipeBudget = 65535;

TEST_F(LoopLimit, SingleLoopOf100000Iterations) {
    const LoopCounts counts = measureUniform(loops(100000, 0, 0, 0));
    if (!isLavapipe()) {
        EXPECT_EQ(counts.first, 100000u);
        return;
    }
    EXPECT_EQ(counts.first, kLavapipeBudget)
        << "lavapipe's loop budget changed: update docs/gpu.md";
}

TEST_F(LoopLimit, SuccessiveLoopsShareOneBudget) {
    const LoopCounts counts = measureUniform(loops(40000, 40000, 0, 0));
    if (!isLavapipe()) {
        EXPECT_EQ(counts.first + counts.second, 80000u);
        return;
    }
    EXPECT_EQ(counts.first, 40000u);
    // The first loop's exit test costs one iteration of the budget.
    EXPECT_EQ(counts.second, kLavapipeBudget - 40000u - 1u);
}

TEST_F(LoopLimit, NestedLoopsShareOneBudget) {
    const LoopCounts counts = measureUniform(loops(0, 0, 400, 400));
    if (!isLavapipe()) {
        EXPECT_EQ(counts.nested, 160000u);
        return;
    }
    EXPECT_LT(counts.nested, kLavapipeBudget);
    EXPECT_GT(counts.nested, kLavapipeBudget - 2 * 400u);
}

// lavapipe runs invocations eight (its subgroup size) to a SIMD vector; is the budget spent
// by one invocation's long loop also gone for its neighbours?
TEST_F(LoopLimit, BudgetOfNeighbouringInvocations) {
    const std::vector<LoopCounts> counts = measure(loops(60000, 10000, 0, 0, 0));
    std::printf("invocation 0 ran 60000 + 10000 iterations as %u + %u; invocations 1, 7, 8 "
                "and 63 ran 0 + 10000 as 0 + %u, %u, %u and %u\n",
                counts[0].first, counts[0].second, counts[1].second, counts[7].second,
                counts[8].second, counts[WORKGROUP_SIZE - 1].second);
    EXPECT_EQ(counts[1].first, 0u);
    if (!isLavapipe()) {
        for (const LoopCounts& c : counts)
            EXPECT_EQ(c.second, 10000u);
        return;
    }
    // Measured: the budget belongs to the SIMD vector, i.e. to subgroupSize invocations
    // together; one slow invocation ends its neighbours' loops too.
    const std::uint32_t vector = context().limits().subgroupSize;
    for (std::uint32_t i = 0; i < WORKGROUP_SIZE; ++i) {
        EXPECT_EQ(counts[i].second, i < vector ? kLavapipeBudget - 60000u - 1u : 10000u) << i;
    }
}

TEST_F(LoopLimit, LoopsWithinTheBudgetRunCompletely) {
    const LoopCounts counts = measureUniform(loops(30000, 30000, 0, 0));
    EXPECT_EQ(counts.first, 30000u);
    EXPECT_EQ(counts.second, 30000u);
}

} // namespace
} // namespace vkpt::test::loop_limit_test
