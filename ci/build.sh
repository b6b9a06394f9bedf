#!/usr/bin/env bash
# build.sh — configures and builds vkpt with the given CMake preset (default: ci), with every
# core, after making sure the dependencies are installed. Targets after the preset build only
# those (and what they need): `bash ci/build.sh release vkpt`.
set -euo pipefail
cd "$(dirname "$0")/.."

preset="${1:-ci}"
shift || true
targets=()
for target in "$@"; do targets+=(--target "$target"); done
bash ci/install_deps.sh
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)" "${targets[@]}"
