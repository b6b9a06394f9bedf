#!/usr/bin/env bash
# phase_table.sh — where a whole process's time goes, for vkpt, vkpt-ref and embree-ref side by
# side on the same cores: the Cornell box (256², 64 spp, depth 8, PNG; again with --denoise, whose
# "denoise set-up" and "denoise" phases are the denoiser's time) and the generated
# 1M-triangle room (1024², 1 spp, depth 2: a preview; EXR output, so with the AOVs). For each
# program and scene: the whole process's wall and CPU seconds (/usr/bin/time), and each phase of
# its --stats-json "phases" (load, prepare with BVH build and collapse, device, device set-up with
# pipelines and upload, ray queries, render, write), medians of RUNS runs (default 3); the last
# column is the process's wall time as a multiple of embree-ref's.
#
#   bash tests/bench/phase_table.sh [BUILD_DIR]     (default build/release; built if missing)
# RUNS, PROGRAMS ("vkpt vkpt-ref embree-ref"), SCENES ("cornell cornell-denoise room") override
# the defaults.
set -euo pipefail
cd "$(dirname "$0")/../.."
build="${1:-build/release}"
[ -x "$build/host/app/vkpt" ] || bash ci/build.sh "$(basename "$build")"
runs="${RUNS:-3}"
programs="${PROGRAMS:-vkpt vkpt-ref embree-ref}"
scenes="${SCENES:-cornell cornell-denoise room}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
source ci/lavapipe_env.sh
unset VKPT_VALIDATION

executable() {
    case "$1" in
    embree-ref) echo "$build/tests/bench/embree-ref" ;;
    *) echo "$build/host/app/$1" ;;
    esac
}

# Scene file, then the options of its render.
scene_args() {
    case "$1" in
    cornell) echo "scenes/cornell-box.gltf --spp 64 --res 256 256 --max-depth 8 -o $work/out.png" ;;
    cornell-denoise)
        echo "scenes/cornell-box.gltf --spp 64 --res 256 256 --max-depth 8 --denoise -o $work/out.png" ;;
    room)
        [ -f "$work/room.gltf" ] || "$build/tests/bench/write_room_scene" "$work/room.gltf" > /dev/null
        echo "$work/room.gltf --spp 1 --res 1024 1024 --max-depth 2 -o $work/out.exr" ;;
    esac
}

echo "phase_table: $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)), load $(cut -d' ' -f1-3 /proc/loadavg), medians of $runs runs"
for scene in $scenes; do
    args="$(scene_args "$scene")"
    for program in $programs; do
        exe="$(executable "$program")"
        if [ ! -x "$exe" ]; then
            echo "phase_table: $program not built (needs libembree-dev for embree-ref); skipped" >&2
            continue
        fi
        for ((run = 1; run <= runs; ++run)); do
            echo -ne "  $scene $program run $run/$runs...\r" >&2
            # shellcheck disable=SC2086 # args is a word list
            /usr/bin/time -f '%e %U %S' -o "$work/time_${scene}_${program}_$run.txt" "$exe" \
                --quiet --stats-json "$work/stats_${scene}_${program}_$run.json" $args \
                > /dev/null 2> "$work/log.txt" || {
                echo "phase_table: $program failed on $scene: $(tail -n 1 "$work/log.txt")" >&2
                exit 1
            }
        done
        printf '\r%*s\r' 60 '' >&2
    done
done

python3 - "$work" "$runs" "$scenes" "$programs" <<'PY'
import json, statistics, sys
work, runs, scenes, programs = sys.argv[1], int(sys.argv[2]), sys.argv[3].split(), sys.argv[4].split()

def load(scene, program):
    out = []
    for run in range(1, runs + 1):
        try:
            wall, user, system = open(f"{work}/time_{scene}_{program}_{run}.txt").read().split()[-3:]
            stats = json.load(open(f"{work}/stats_{scene}_{program}_{run}.json"))
        except OSError:
            return None
        out.append((float(wall), float(user) + float(system), stats))
    return out

for scene in scenes:
    rows, names = {}, []
    for program in programs:
        runs_of = load(scene, program)
        if runs_of is None:
            continue
        phases = {}
        for _, _, stats in runs_of:
            for p in stats.get("phases", []):
                name = "  " * p["depth"] + p["name"]
                if name not in names:
                    names.append(name)
                phases.setdefault(name, []).append(p["seconds"])
        rows[program] = (statistics.median(w for w, _, _ in runs_of),
                         statistics.median(c for _, c, _ in runs_of),
                         {k: statistics.median(v) for k, v in phases.items()})
    if not rows:
        continue
    print(f"\n{scene}: seconds (wall; process CPU in the second row)\n")
    print("| phase | " + " | ".join(rows) + " |")
    print("|---|" + "---:|" * len(rows))
    print("| **whole process** | " + " | ".join(f"**{r[0]:.2f}**" for r in rows.values()) + " |")
    print("| process CPU | " + " | ".join(f"{r[1]:.2f}" for r in rows.values()) + " |")
    for name in names:
        cells = [f"{r[2][name]:.3f}" if name in r[2] else "" for r in rows.values()]
        print(f"| {name.replace('  ', '&nbsp;&nbsp;')} | " + " | ".join(cells) + " |")
    if "embree-ref" in rows:
        base = rows["embree-ref"][0]
        print("| ÷ embree-ref (wall) | " + " | ".join(f"{r[0] / base:.2f}×" for r in rows.values()) + " |")
PY
