#!/usr/bin/env bash
# test.sh — the whole test suite from a fresh clone: dependencies, build, then every CTest
# label (unit, cli, render, gpu, image) on lavapipe with validation on.
set -euo pipefail
cd "$(dirname "$0")/.."

bash ci/build.sh ci
source ci/lavapipe_env.sh
ctest --preset ci "$@"
