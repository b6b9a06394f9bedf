#!/usr/bin/env bash
# render_default.sh — from a fresh clone to a picture: installs the dependencies, builds the
# release configuration and renders the Cornell box at 512 samples per pixel.
set -euo pipefail
cd "$(dirname "$0")/.."

bash ci/build.sh release
mkdir -p out
./build/release/host/app/vkpt-ref --spp 512 --output out/cornell-box.png scenes/cornell-box.gltf
echo "render_default: wrote $(pwd)/out/cornell-box.png (sample counts: out/cornell-box_rate.png)"
