#!/usr/bin/env bash
# test.sh — the whole test suite from a fresh clone: dependencies, build, the format check
# (ci/format_check.sh), then every CTest label (unit, cli, render, gpu, image, extremes, farm,
# slurm, study) on lavapipe with validation on; then the fuzz build (clang, preset fuzz) and its
# short fuzz run over the glTF loader (label fuzz, about a minute). Last, whether it all left
# the checkout as it found it (ci/check_clean_tree.sh): tests write only into their own folders.
# At the end, pass or fail, it prints where the time went: the builds, the tests and the ten
# slowest tests (docs/testing.md says how to look into one).
set -euo pipefail
cd "$(dirname "$0")/.."

# The checkout's state before the run and the tests' timings, kept outside it.
scratch=$(mktemp -d)
git status --porcelain --untracked-files=all >"$scratch/status_before"
declare -A seconds=()
timed() { # timed NAME COMMAND...: runs the command and records its wall seconds under NAME
    local name=$1 start=$SECONDS
    shift
    "$@" || { seconds[$name]=$((SECONDS - start)); return 1; }
    seconds[$name]=$((SECONDS - start))
}
report_times() {
    local line="test.sh: time:"
    for name in build format tests fuzz-build fuzz-tests; do
        [ -n "${seconds[$name]:-}" ] && line+=" $name ${seconds[$name]} s,"
    done
    echo "${line%,}; ${SECONDS} s in all"
    [ -s "$scratch/tests.xml" ] && python3 ci/test_times.py "$scratch/tests.xml" 10
    return 0
}
finish() {
    local status=$?
    report_times || true
    bash ci/check_clean_tree.sh "$scratch/status_before" || status=1
    rm -rf "$scratch"
    exit "$status"
}
trap finish EXIT

timed build bash ci/build.sh ci
timed format bash ci/format_check.sh
source ci/lavapipe_env.sh
# Tests write only into their own folders: the programs they run leave the user's pipeline cache
# (~/.cache/vkpt) alone; tests/gpu/pipeline_cache_test.cpp covers the cache with its own files.
export VKPT_NO_PIPELINE_CACHE=1
# The kernels folded for their constants are kept for the run in one folder of its own, which the
# test processes share (gpu/folded_spirv_cache.h): a feature set is folded once, not once per
# process that renders it.
export VKPT_KERNEL_CACHE_DIR="$scratch/kernels"
# ctest starts the tests it knows to be long first, from the timings of the folder's last run; a
# fresh folder has none, so seed them from ci/test_costs.txt (an earlier run's, made by
# `ci/test_times.py JUNIT --costs`): otherwise a long test that starts last leaves a core idle.
costs=build/ci/Testing/Temporary/CTestCostData.txt
if [ ! -s "$costs" ]; then
    mkdir -p "$(dirname "$costs")"
    { awk 'NF == 2 { print $1, 1, $2 }' ci/test_costs.txt; echo ---; } >"$costs"
fi
timed tests ctest --preset ci --output-junit "$scratch/tests.xml" "$@"
timed fuzz-build bash ci/build.sh fuzz
timed fuzz-tests ctest --preset fuzz
