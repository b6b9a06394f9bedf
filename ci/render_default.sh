#!/usr/bin/env bash
# render_default.sh — from a fresh clone to a picture: installs the dependencies, builds vkpt
# alone in the release configuration (no tests, no benchmarks) and renders the Cornell box at
# 512 samples per pixel with vkpt on the first Vulkan device (a GPU, else Mesa's lavapipe on the
# CPU: about five minutes on 2 cores).
set -euo pipefail
cd "$(dirname "$0")/.."

bash ci/build.sh release vkpt
mkdir -p out
./build/release/host/app/vkpt --spp 512 --output out/cornell-box.png scenes/cornell-box.gltf
echo "render_default: wrote $(pwd)/out/cornell-box.png (sample counts: out/cornell-box_rate.png)"
