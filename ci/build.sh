#!/usr/bin/env bash
# build.sh — configures and builds vkpt with the given CMake preset (default: ci), with every
# core, after making sure the dependencies are installed.
set -euo pipefail
cd "$(dirname "$0")/.."

preset="${1:-ci}"
bash ci/install_deps.sh
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
