#!/usr/bin/env bash
# farm_example.sh — the measured example of docs/distributed.md: the Cornell box rendered as one
# process and as 4 tasks (one after another, and two at a time on the two cores), merged, and
# compared with the one run. Prints medians of RUNS runs (default 3) and the largest difference.
#
#   bash ci/farm_example.sh [vkpt|vkpt-ref] [BUILD_DIR]     (defaults: vkpt, build/release)
# Timings: run it on a quiet machine (validation off), and note the load average it prints.
set -euo pipefail
cd "$(dirname "$0")/.."
program="${1:-vkpt}"
build="${2:-build/release}"
[ -x "$build/host/app/$program" ] || bash ci/build.sh "$(basename "$build")"
renderer="$(pwd)/$build/host/app/$program"
merger="$(pwd)/$build/host/app/vkpt-merge"
scene="$(pwd)/scenes/cornell-box.gltf"
runs="${RUNS:-3}"
args=(--quiet --res 128 128 --spp 256)
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
source ci/lavapipe_env.sh
unset VKPT_VALIDATION

seconds() {
    local t0 t1
    t0=$(date +%s.%N); "$@" > /dev/null 2>&1; t1=$(date +%s.%N)
    awk "BEGIN { print $t1 - $t0 }"
}
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
one_run() { "$renderer" "${args[@]}" -o "$work/one.exr" "$scene"; }
task() { local k=$1; shift; "$renderer" "${args[@]}" "$@" --task "$k/4" -o "$work/part_$k.exr" "$scene"; }
tasks_in_turn() { for k in 0 1 2 3; do task "$k"; done; }
tasks_two_at_a_time() {
    LP_NUM_THREADS=1 task 0 & LP_NUM_THREADS=1 task 1 & wait
    LP_NUM_THREADS=1 task 2 & LP_NUM_THREADS=1 task 3 & wait
}
merge() { "$merger" -q -o "$work/merged.exr" "$work"/part_{0,1,2,3}.exr; }
# vkpt-ref takes its threads from --threads; give each of two parallel tasks one core.
[ "$program" = vkpt-ref ] && tasks_two_at_a_time() {
    task 0 --threads 1 & task 1 --threads 1 & wait
    task 2 --threads 1 & task 3 --threads 1 & wait
}

echo "farm_example: $program, Cornell box 128x128, 256 spp; load average $(cut -d' ' -f1-3 /proc/loadavg)"
for what in one_run tasks_in_turn tasks_two_at_a_time merge; do
    for _ in $(seq "$runs"); do seconds "$what"; done | median | xargs printf "  %-20s %6.2f s (median of $runs)\n" "$what"
done
# The two images as PFM (vkpt-merge of one part writes its image), compared value by value.
"$merger" -q -o "$work/merged.pfm" "$work/merged.exr"
"$merger" -q -o "$work/one.pfm" "$work/one.exr"
python3 - "$work/merged.pfm" "$work/one.pfm" <<'PY'
import struct, sys
def pfm(path):
    data = open(path, "rb").read()
    kind, size, scale, pixels = data.split(b"\n", 3)
    w, h = map(int, size.split())
    order = "<" if float(scale) < 0 else ">"
    return struct.unpack(order + "f" * (3 * w * h), pixels[: 12 * w * h])
a, b = pfm(sys.argv[1]), pfm(sys.argv[2])
differ = sum(x != y for x, y in zip(a, b))
worst = max(abs(x - y) / max(abs(y), 1e-30) for x, y in zip(a, b))
print(f"  merged vs one run: {differ} of {len(a)} values differ, largest relative difference {worst:.3g}")
PY
oiiotool "$work/merged.exr" --ch sampleCount "$work/one.exr" --ch sampleCount --diff --fail 0 |
    grep -q PASS && echo "  sample counts: equal"
echo "  load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
