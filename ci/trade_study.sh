#!/usr/bin/env bash
# trade_study.sh — the speed-against-accuracy study published in docs/trade/: vkpt-study on the
# Cornell box (128×128, up to 4096 spp) and on the largest shared scene, TransmissionTest
# (96×96, up to 2048 spp), writing CSV, Markdown tables and SVG plots into docs/trade/.
# References are made once and cached outside the repository ($XDG_CACHE_HOME/vkpt, else
# ~/.cache/vkpt). On the project's 2-core VM with lavapipe: about 20 minutes for the Cornell
# box and 22 for TransmissionTest, each about 5 more when its references are made.
#
#   bash ci/trade_study.sh [cornell|transmission|all] [vkpt-study options...]
#
# VKPT_BUILD_DIR: a build with vkpt-study (default build/release, built when missing).
# The study times renders: validation stays off, and nothing else should run meanwhile.
set -euo pipefail
cd "$(dirname "$0")/.."

which="${1:-all}"
[ $# -gt 0 ] && shift
build="${VKPT_BUILD_DIR:-build/release}"
study="$build/tests/study/vkpt-study"

if ! command -v gnuplot >/dev/null; then
    echo "trade_study: gnuplot is not installed; bash ci/install_deps.sh installs it (gnuplot-nox)" >&2
    exit 1
fi
[ -x "$study" ] || bash ci/build.sh release

unset VKPT_VALIDATION
export LP_NUM_THREADS="${LP_NUM_THREADS:-$(nproc)}"
transmission=../shared/scenes/TransmissionTest/TransmissionTest.glb

if [ "$which" = cornell ] || [ "$which" = all ]; then
    "$study" --res 128 128 --spp 4096 --side-spp 1024 --reference-spp 16384 \
        --name cornell-box -o docs/trade "$@" scenes/cornell-box.gltf
fi
if [ "$which" = transmission ] || [ "$which" = all ]; then
    [ -f "$transmission" ] || { echo "trade_study: $transmission is missing" >&2; exit 1; }
    "$study" --res 96 96 --spp 2048 --side-spp 512 --reference-spp 16384 \
        --name transmission-test -o docs/trade "$@" "$transmission"
fi
