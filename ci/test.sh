#!/usr/bin/env bash
# test.sh — the whole test suite from a fresh clone: dependencies, build, the format check
# (ci/format_check.sh), then every CTest label (unit, cli, render, gpu, image, extremes, farm,
# slurm, study) on lavapipe with validation on; then the fuzz build (clang, preset fuzz) and its
# short fuzz run over the glTF loader (label fuzz, about a minute). Last, whether it all left
# the checkout as it found it (ci/check_clean_tree.sh): tests write only into their own folders.
set -euo pipefail
cd "$(dirname "$0")/.."

# The checkout's state before the run, kept outside it; checked at exit, failed run or not.
status_before=$(mktemp)
git status --porcelain --untracked-files=all >"$status_before"
finish() {
    local status=$?
    bash ci/check_clean_tree.sh "$status_before" || status=1
    rm -f "$status_before"
    exit "$status"
}
trap finish EXIT

bash ci/build.sh ci
bash ci/format_check.sh
source ci/lavapipe_env.sh
# Tests write only into their own folders: the programs they run leave the user's pipeline cache
# (~/.cache/vkpt) alone; tests/gpu/pipeline_cache_test.cpp covers the cache with its own files.
export VKPT_NO_PIPELINE_CACHE=1
ctest --preset ci "$@"
bash ci/build.sh fuzz
ctest --preset fuzz
