#!/usr/bin/env bash
# frame_costs.sh — what an animation's frame costs beyond its samples (docs/benchmarks.md,
# "Animation frames"): vkpt renders frames 0 to 8 at 24 fps, 64², 1 spp (so that the samples
# cost little beside the rest) of BoxAnimated (node animation), CesiumMan (a skin) and a large
# still set with a small moving box (scenes/generate_static_set.py, 524,288 + 12 triangles), and
# prints per scene the medians over frames 1–8 (frame 0 also starts the device and compiles the
# pipelines) and over RUNS runs (default 3) of: the frame's wall time (from one frame's
# statistics to the next's), that time less its "render" phase (what the frame costs beyond its
# samples), and its phases.
#
#   bash tests/bench/frame_costs.sh VKPT [VKPT ...]   (several executables: run in turn, per run)
set -euo pipefail
cd "$(dirname "$0")/../.."
[ $# -ge 1 ] || { echo "usage: frame_costs.sh VKPT [VKPT ...]" >&2; exit 1; }
runs="${RUNS:-3}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
source ci/lavapipe_env.sh
unset VKPT_VALIDATION
export VKPT_NO_PIPELINE_CACHE=1
python3 scenes/generate_static_set.py "$work/static_set.gltf"
declare -A scenes=([box]=../shared/scenes/BoxAnimated/BoxAnimated.glb
                   [cesium]=../shared/scenes/CesiumMan/CesiumMan.glb
                   [static]="$work/static_set.gltf")
for run in $(seq "$runs"); do
    for program in "$@"; do
        for name in box cesium static; do
            out="$work/$(echo "$program" | tr '/' '_')/$name/$run"
            mkdir -p "$out"
            "$program" --frames 0:8 --fps 24 --spp 1 --res 64 64 --quiet -o "$out/f.####.png" \
                --stats-json "$out/s.####.json" "${scenes[$name]}" > /dev/null 2>&1
        done
    done
done
python3 - "$work" "$@" <<'PY'
import glob, json, statistics, sys
work, programs = sys.argv[1], sys.argv[2:]
names = ['load', 'prepare', 'BVH build', 'BVH collapse', 'bottom-level BVHs', 'top-level BVH',
         'emitters', 'scene hash', 'upload', 'render']
for program in programs:
    print(program)
    for scene in ['box', 'cesium', 'static']:
        walls, beyond, phases = [], [], {n: [] for n in names}
        for run in sorted(glob.glob(f"{work}/{program.replace('/', '_')}/{scene}/*")):
            files = sorted(glob.glob(f'{run}/s.*.json'))
            last = json.load(open(files[0]))['process']['seconds']
            for f in files[1:]:
                d = json.load(open(f))
                total = {}
                for p in d['phases']:
                    total[p['name']] = total.get(p['name'], 0.0) + p['seconds']
                wall = d['process']['seconds'] - last
                last = d['process']['seconds']
                walls.append(wall)
                beyond.append(wall - total.get('render', 0.0))
                for n in names:
                    phases[n].append(total.get(n, 0.0))
        ms = lambda v: 1000.0 * statistics.median(v)
        print(f'  {scene:7s} frame {ms(walls):7.1f} ms, beyond samples {ms(beyond):7.1f} ms | ' +
              ', '.join(f'{n} {ms(phases[n]):.1f}' for n in names if ms(phases[n]) > 0.0))
PY
