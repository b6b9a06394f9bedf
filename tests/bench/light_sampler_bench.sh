#!/usr/bin/env bash
# light_sampler_bench.sh — what the light BVH buys over power sampling (--light-sampler bvh or
# power): for each scene, a high-sample reference (vkpt-ref, light BVH, REF_SPP), then each
# program renders it at SPP with each sampler, RUNS times, as whole processes. Prints one line
# per scene, program and sampler: the relMSE against the reference at equal samples (from
# --stats-json; the same every run, the seed is fixed), the median whole-process seconds
# (--stats-json process.seconds, load to write), relMSE × seconds, and those seconds over
# embree-ref's with the same sampler in the same run (the benchmarks' baseline, tests/bench).
#
#   bash tests/bench/light_sampler_bench.sh [BUILD_DIR] [SCENE ...]
#   (defaults: build/ci; both Cornell boxes, the many-lights scene, DamagedHelmet and
#   EmissiveStrengthTest; 96 × 96 at 64 spp against 2048, depth 16, 3 runs)
# SPP, REF_SPP, RES, RUNS and PROGRAMS ("vkpt vkpt-ref embree-ref") override the defaults.
set -euo pipefail
cd "$(dirname "$0")/../.."
build="${1:-build/ci}"
shift || true
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(scenes/cornell-box.gltf ../shared/scenes/CornellBox/cornellBox.gltf
    scenes/test/many-lights.gltf
    ../shared/scenes/DamagedHelmet/DamagedHelmet.glb
    ../shared/scenes/EmissiveStrengthTest/EmissiveStrengthTest.glb)
runs="${RUNS:-3}"
spp="${SPP:-64}"
ref_spp="${REF_SPP:-2048}"
res="${RES:-96}"
programs="${PROGRAMS:-vkpt vkpt-ref embree-ref}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
source ci/lavapipe_env.sh
unset VKPT_VALIDATION
export VKPT_NO_PIPELINE_CACHE=1 # every vkpt run compiles its pipelines, as a first run does

binary() { [ "$1" = embree-ref ] && echo "$build/tests/bench/embree-ref" || echo "$build/host/app/$1"; }
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
json_number() { grep -o "\"$2\": *[0-9.e+-]*" "$1" | tail -n 1 | sed 's/.*: *//'; }
process_seconds() { grep -A1 '"process": {' "$1" | grep -o '"seconds": *[0-9.e+-]*' | sed 's/.*: *//'; }

# embree-ref first, so that the others' times can be given over its own.
ordered="$(printf '%s\n' $programs | grep -x embree-ref || true) $(printf '%s\n' $programs | grep -vx embree-ref || true)"

echo "light_sampler_bench: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg), ${res}² at $spp spp against $ref_spp, $runs runs"
printf '%-22s %-10s %-6s %11s %9s %13s %10s\n' scene program sampler relMSE "median s" \
    "relMSE × s" "s / embree"
for scene in "${scenes[@]}"; do
    name="$(basename "${scene%.*}")"
    reference="$work/$name.reference.pfm"
    "$(binary vkpt-ref)" -q --spp "$ref_spp" --res "$res" "$res" --seed 1000 -o "$reference" \
        "$scene" >/dev/null 2>&1
    declare -A embree_seconds=()
    for program in $ordered; do
        for sampler in power bvh; do
            times=()
            for run in $(seq "$runs"); do
                stats="$work/$name.$program.$sampler.$run.json"
                "$(binary "$program")" -q --spp "$spp" --res "$res" "$res" --light-sampler "$sampler" \
                    --reference "$reference" --stats-json "$stats" -o "$work/$name.pfm" \
                    "$scene" >/dev/null 2>&1
                times+=("$(process_seconds "$stats")")
            done
            relmse="$(json_number "$stats" relMse)"
            seconds="$(printf '%s\n' "${times[@]}" | median)"
            [ "$program" = embree-ref ] && embree_seconds[$sampler]="$seconds"
            ratio="$(awk -v s="$seconds" -v e="${embree_seconds[$sampler]:-0}" \
                'BEGIN { if (e > 0) printf "%.2f", s / e; else printf "-" }')"
            printf '%-22s %-10s %-6s %11.4g %9.3f %13.4g %10s\n' "$name" "$program" "$sampler" \
                "$relmse" "$seconds" "$(awk -v r="$relmse" -v s="$seconds" 'BEGIN { print r * s }')" \
                "$ratio"
        done
    done
    unset embree_seconds
done
