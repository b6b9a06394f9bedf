#!/usr/bin/env bash
# denoise_bench.sh — seconds to denoise a 1024² state (the denoiser's own time, as vkpt-denoise
# prints it: no device start, no file I/O), on the Vulkan device (lavapipe here) and with --cpu,
# medians of RUNS runs (default 3): wall seconds, and the process's CPU seconds over the cores,
# which is the wall time on an idle machine whatever else loads a shared one. The state is a 4-spp, depth-2 render of the Cornell box,
# made once; the denoiser's work does not depend on the pixels' values.
#
#   bash tests/bench/denoise_bench.sh [BUILD_DIR]     (default build/release; built if missing)
set -euo pipefail
cd "$(dirname "$0")/../.."
build="${1:-build/release}"
[ -x "$build/host/app/vkpt-denoise" ] || bash ci/build.sh "$(basename "$build")"
runs="${RUNS:-3}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
source ci/lavapipe_env.sh
unset VKPT_VALIDATION

"$build/host/app/vkpt" -q --spp 4 --max-depth 2 --res 1024 1024 -o "$work/state.exr" \
    scenes/cornell-box.gltf 2> /dev/null
echo "denoise_bench: $(nproc) cores, LP_NUM_THREADS=${LP_NUM_THREADS:-unset}, load $(cut -d' ' -f1-3 /proc/loadavg), medians of $runs runs"
for where in device cpu; do
    flags=()
    [ "$where" = cpu ] && flags=(--cpu)
    seconds=()
    idle=()
    for ((run = 1; run <= runs; ++run)); do
        line="$("$build/host/app/vkpt-denoise" "${flags[@]}" "$work/state.exr" -o "$work/out.pfm")"
        seconds+=("$(sed -E 's/.* in ([0-9.]+) s \(.*/\1/' <<< "$line")")
        cpu="$(sed -E 's/.* \(([0-9.]+) s of CPU\).*/\1/' <<< "$line")"
        idle+=("$(awk -v c="$cpu" -v n="$(nproc)" 'BEGIN { printf "%.3f", c / n }')")
    done
    middle() { printf '%s\n' "$@" | sort -g | sed -n "$(((runs + 1) / 2))p"; }
    echo "denoise_bench: 1024x1024 on $where: $(middle "${seconds[@]}") s wall," \
        "$(middle "${idle[@]}") s of CPU per core (runs: ${seconds[*]}; ${idle[*]})"
done
