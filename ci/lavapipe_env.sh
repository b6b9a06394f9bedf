#!/usr/bin/env bash
# lavapipe_env.sh — sourced before GPU tests: Mesa's CPU Vulkan driver, the Khronos validation
# layer on, and any validation message made fatal by vkpt's messenger.
export VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json
export VK_DRIVER_FILES=$VK_ICD_FILENAMES
export VKPT_VALIDATION=1
# lavapipe runs compute shaders on this many threads; leave one core to the test runner.
export LP_NUM_THREADS="${LP_NUM_THREADS:-$(nproc)}"
