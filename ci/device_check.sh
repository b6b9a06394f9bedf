#!/usr/bin/env bash
# device_check.sh — on a machine with a GPU: the Vulkan test labels with validation on, then the
# benchmarks at sizes that fill a GPU (1080p, the 1M-triangle room, a million paths in flight,
# the instanced field flattened and instanced at 8.5 million and instanced at 103 million placed
# triangles),
# with every figure written to a folder. Uses build/device-bundle.tar.xz when it is there
# (ci/device_bundle.sh packs it on the development machine, for GPU machines without Debian's
# packages), else the release build, building it when missing.
#
#   bash ci/device_check.sh [OUTPUT_DIR]     (default: $OUT/device-check, else build/device-check)
#
# VKPT_DEVICE: index or name of the Vulkan device to test (default: vkpt's choice, a discrete
# GPU first). DEVICE_CHECK_QUICK=1: small sizes, to try the script itself on lavapipe.
set -uo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

out="${1:-${OUT:+$OUT/device-check}}"
out="${out:-build/device-check}"
mkdir -p "$out/tests"
out=$(cd "$out" && pwd)
summary="$out/summary.txt"
: >"$summary"
say() { echo "$*" | tee -a "$summary"; }

# ---- the programs --------------------------------------------------------------------------
if [ -f build/device-bundle.tar.xz ]; then
    tar -C build -xJf build/device-bundle.tar.xz
    bundle="$root/build/device-bundle"
    bin="$bundle/bin"
    tests=("$bundle"/tests/*)
    export LD_LIBRARY_PATH="$bundle/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
    export VK_LAYER_PATH="$bundle/layers"
    # The tests read scenes from the folder they were built in.
    source_dir=$(cat "$bundle/source_dir.txt")
    if [ ! -e "$source_dir" ]; then
        mkdir -p "$(dirname "$source_dir")" && ln -s "$root" "$source_dir"
    fi
    built_from=$(cat "$bundle/commit.txt" 2>/dev/null || echo unknown)
else
    build="${VKPT_BUILD_DIR:-build/release}"
    [ -x "$build/host/app/vkpt" ] || bash ci/build.sh release
    bin="$root/$build/host/app"
    mapfile -t tests < <(find "$build/tests/gpu" "$build/tests/image" "$build/tests/extremes" \
        -maxdepth 1 -type f -executable -name '*_tests' | sort)
    for bench in "$build"/tests/bench/*; do [ -x "$bench" ] && ln -sf "$root/$bench" "$bin/"; done
    built_from=$(git rev-parse HEAD 2>/dev/null || echo unknown)
fi
# NVIDIA's driver in a container often lives here, unknown to the loader.
nvidia_icd=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
if [ -z "${VK_DRIVER_FILES:-}${VK_ICD_FILENAMES:-}" ] && [ -f "$nvidia_icd" ]; then
    export VK_DRIVER_FILES="$nvidia_icd"
fi
device_args=()
[ -n "${VKPT_DEVICE:-}" ] && device_args=(--device "$VKPT_DEVICE")

say "device_check: commit $built_from, $(date -u +%Y-%m-%dT%H:%M:%SZ)"
"$bin/vkpt" --list-devices 2>&1 | tee -a "$summary"
command -v nvidia-smi >/dev/null && nvidia-smi --query-gpu=name,driver_version,memory.total \
    --format=csv,noheader 2>&1 | tee -a "$summary"

# ---- tests with validation -----------------------------------------------------------------
export VKPT_VALIDATION=1
failed=0
for test in "${tests[@]}"; do
    name=$(basename "$test")
    if timeout 900 "$test" --gtest_brief=1 >"$out/tests/$name.log" 2>&1; then
        say "test $name: $(grep -E '^\[  PASSED  \]' "$out/tests/$name.log" | sed 's/^\[  PASSED  \] //')"
    else
        failed=$((failed + 1))
        say "test $name: FAILED (log: tests/$name.log)"
        grep -E '^\[  FAILED  \]' "$out/tests/$name.log" | head -5 | tee -a "$summary"
    fi
done
unset VKPT_VALIDATION
say "tests: ${#tests[@]} executables, $failed failed"

# ---- benchmarks at GPU sizes ---------------------------------------------------------------
if [ "${DEVICE_CHECK_QUICK:-0}" = 1 ]; then
    width=256 height=144 spp=4 room=20000 runs=1 field=16:16 big_field=24:16
else
    width=1920 height=1080 spp=64 room=1000000 runs=3 field=64:32 big_field=112:64
fi
threads=$(nproc)
room_scene="$out/room-$room.gltf"
"$bin/write_room_scene" --triangles "$room" "$room_scene" >>"$out/bench.log" 2>&1 ||
    say "write_room_scene failed (bench.log)"

for scene in scenes/cornell-box.gltf "$room_scene"; do
    [ -f "$scene" ] || continue
    name=$(basename "$scene" .gltf)
    say "vkpt $name ${width}x${height}, $spp spp, per-kernel times and the phases of the process:"
    "$bin/vkpt" "${device_args[@]}" --spp "$spp" --res "$width" "$height" --stats \
        --stats-json "$out/vkpt-$name.json" -o "$out/vkpt-$name.pfm" "$scene" 2>&1 |
        grep -E 'Mrays|rays:|samples:|device:|kernel|pipeline|time:' | tee -a "$summary"
done

# The time to an image of a preview (docs/benchmarks.md, "Time to an image"): one sample of the
# 1M-triangle room at depth 2, written as EXR with its AOVs; the summary's last line is the
# process's phases (load, BVH, device set-up, pipelines, upload, render, write).
if [ -f "$room_scene" ]; then
    say "vkpt $(basename "$room_scene" .gltf) preview ${width}x${height}, 1 spp, depth 2, EXR:"
    "$bin/vkpt" "${device_args[@]}" --spp 1 --max-depth 2 --res "$width" "$height" \
        --stats-json "$out/vkpt-preview.json" -o "$out/vkpt-preview.exr" "$room_scene" 2>&1 |
        grep -E 'Mrays|device:|pipelines|time:' | tee -a "$summary"
fi

# Instancing (docs/scene-model.md, "Instancing"): the field of meshes placed many times,
# flattened against instanced at 8.5 million placed triangles, and instanced at 103 million.
for size in "$field" "$big_field"; do
    grid="${size%%:*}" rings="${size##*:}"
    field_scene="$out/field-$grid-$rings.gltf"
    "$bin/write_instanced_scene" --grid "$grid" --rings "$rings" "$field_scene" \
        >>"$out/bench.log" 2>&1 || say "write_instanced_scene failed (bench.log)"
    modes="off on"
    [ "$size" = "$big_field" ] && modes="on"
    for mode in $modes; do
        say "vkpt field $grid:$rings --instancing $mode ${width}x${height}, $spp spp:"
        "$bin/vkpt" "${device_args[@]}" --instancing "$mode" --spp "$spp" \
            --res "$width" "$height" --stats --stats-json "$out/vkpt-field-$grid-$mode.json" \
            -o "$out/vkpt-field-$grid-$mode.pfm" "$field_scene" 2>&1 |
            grep -E 'triangles|Mrays|device:|kernel|pipeline|time:' | tee -a "$summary"
    done
done

say "gpu_bench (vkpt against vkpt-ref on this machine's CPU):"
"$bin/gpu_bench" "${device_args[@]}" --spp "$spp" --res "$width" "$height" --runs "$runs" \
    scenes/cornell-box.gltf "$room_scene" 2>>"$out/bench.log" | tee -a "$summary"

say "traversal_bench (Mrays/s; 'kernels alone' of incoherent closest hits is the Grays/s figure):"
"$bin/traversal_bench" "${device_args[@]}" --runs "$runs" --res "$width" "$height" \
    --triangles "$room" --threads "$threads" 2>>"$out/bench.log" | tee -a "$summary"

say "device_check: figures in $out"
[ "$failed" -eq 0 ]
