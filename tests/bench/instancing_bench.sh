#!/usr/bin/env bash
# instancing_bench.sh — what instancing buys and costs: the generated scene of meshes placed many
# times (write_instanced_scene: displaced spheres and boxes on a floor) at growing sizes, each
# rendered as whole processes flattened (--instancing off) and instanced (--instancing on), with
# vkpt (the device) and vkpt-ref. Prints one line per size, program and mode: triangles placed and
# stored, BVH build seconds, render seconds and Mrays/s, peak host memory (the process's maximum
# resident set, /usr/bin/time -v) and, for vkpt, peak device memory (--stats-json
# render.deviceMemoryBytes); medians of RUNS runs (default 3).
#
#   bash tests/bench/instancing_bench.sh [BUILD_DIR] [GRID:RINGS ...]
#   (defaults: build/release, sizes 8:32 16:32 32:32 64:32, 256 × 256 at 16 spp, depth 4)
# SPP, RES, MODES ("off on"), PROGRAMS ("vkpt vkpt-ref") and RUNS override the defaults. A mode
# that needs more memory than the machine has is left out by giving MODES=on.
set -euo pipefail
cd "$(dirname "$0")/../.."
build="${1:-build/release}"
shift || true
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(8:32 16:32 32:32 64:32)
[ -x "$build/host/app/vkpt" ] || bash ci/build.sh "$(basename "$build")"
writer="$(pwd)/$build/tests/bench/write_instanced_scene"
runs="${RUNS:-3}"
spp="${SPP:-16}"
res="${RES:-256}"
modes="${MODES:-off on}"
programs="${PROGRAMS:-vkpt vkpt-ref}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
source ci/lavapipe_env.sh
unset VKPT_VALIDATION

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
json_number() { grep -o "\"$2\": *[0-9.e+-]*" "$1" | head -n 1 | sed 's/.*: *//'; }

echo "instancing_bench: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg), ${res}² at $spp spp, depth 4, $runs runs"
printf '%-10s %-8s %-4s %12s %10s %8s %9s %8s %10s %10s\n' size program mode placed stored \
    "build s" "render s" Mrays/s "host MiB" "device MiB"
for size in "${sizes[@]}"; do
    grid="${size%%:*}" rings="${size##*:}"
    scene="$work/grid${grid}_rings${rings}.gltf"
    "$writer" --grid "$grid" --rings "$rings" "$scene" > /dev/null
    for program in $programs; do
        for mode in $modes; do
            builds=() renders=() rates=() hosts=() devices=()
            for ((run = 1; run <= runs; ++run)); do
                echo -ne "  $size $program $mode run $run/$runs...\r" >&2
                /usr/bin/time -v -o "$work/time.txt" "$build/host/app/$program" --quiet \
                    --instancing "$mode" --spp "$spp" --res "$res" "$res" --max-depth 4 \
                    --stats-json "$work/stats.json" -o "$work/out.pfm" "$scene" \
                    > /dev/null 2> "$work/log.txt"
                builds+=("$(json_number "$work/stats.json" buildSeconds)")
                renders+=("$(json_number "$work/stats.json" seconds)")
                rates+=("$(json_number "$work/stats.json" megaRaysPerSecond)")
                hosts+=("$(awk '/Maximum resident set size/ { print $NF / 1024 }' "$work/time.txt")")
                devices+=("$(json_number "$work/stats.json" deviceMemoryBytes)")
            done
            printf '\r%*s\r' 60 '' >&2
            placed=$(json_number "$work/stats.json" placedTriangles)
            stored=$(json_number "$work/stats.json" triangles)
            device=$(printf '%s\n' "${devices[@]}" | median)
            printf '%-10s %-8s %-4s %12s %10s %8.3f %9.3f %8.2f %10.0f %10s\n' "$size" "$program" \
                "$mode" "$placed" "$stored" "$(printf '%s\n' "${builds[@]}" | median)" \
                "$(printf '%s\n' "${renders[@]}" | median)" \
                "$(printf '%s\n' "${rates[@]}" | median)" \
                "$(printf '%s\n' "${hosts[@]}" | median)" \
                "$([ "$program" = vkpt ] && awk "BEGIN { printf \"%.1f\", $device / 1048576 }" || echo -)"
        done
    done
done
