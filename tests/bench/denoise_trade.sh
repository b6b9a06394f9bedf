#!/usr/bin/env bash
# denoise_trade.sh — the measurements of docs/trade/denoise.md: for each scene a high-spp
# reference (vkpt-ref at another seed; its own noise is fitted from the raw errors and
# subtracted, denoise_trade.py), then at each sample count a render to a state (.exr), its raw image
# (vkpt-merge) and its denoised image (vkpt-denoise on the device), with the process CPU time of
# each step; denoise_trade.py turns them into relMSE, N_eq and relMSE × time (CSV on stdout), and
# pictures at PICTURE_SPP into docs/trade/images.
#
#   bash tests/bench/denoise_trade.sh [BUILD_DIR] [WORK_DIR]   (default build/ci, a temp dir)
# SCENES ("name=path ..."), SPPS ("4 16 64 256 1024"), REF_SPP (16384), RES (128), DEPTH (8),
# PICTURE_SPP (16) override the defaults. A reference already in WORK_DIR is reused.
set -euo pipefail
cd "$(dirname "$0")/../.."
build="${1:-build/ci}"
work="${2:-$(mktemp -d)}"
mkdir -p "$work" docs/trade/images
scenes="${SCENES:-cornell=scenes/cornell-box.gltf many-lights=scenes/test/many-lights.gltf}"
spps="${SPPS:-4 16 64 256 1024}"
ref_spp="${REF_SPP:-16384}"
res="${RES:-128}"
depth="${DEPTH:-8}"
picture_spp="${PICTURE_SPP:-16}"
source ci/lavapipe_env.sh
unset VKPT_VALIDATION
app="$build/host/app"
timed() { /usr/bin/time -f '%e %U %S' -o "$1" "${@:2}"; }

for entry in $scenes; do
    name="${entry%%=*}"
    scene="${entry#*=}"
    common=(-q --res "$res" "$res" --max-depth "$depth")
    if [ ! -f "$work/${name}_ref.pfm" ]; then
        echo "denoise_trade: $name: reference at $ref_spp spp..." >&2
        timed "$work/${name}_ref.time" "$app/vkpt-ref" "${common[@]}" --spp "$ref_spp" --seed 7 \
            -o "$work/${name}_ref.exr" "$scene"
        "$app/vkpt-merge" -q -o "$work/${name}_ref.pfm" "$work/${name}_ref.exr"
    fi
    for spp in $spps; do
        echo "denoise_trade: $name: $spp spp" >&2
        timed "$work/${name}_${spp}_render.time" "$app/vkpt-ref" "${common[@]}" --spp "$spp" \
            -o "$work/${name}_${spp}.exr" "$scene"
        "$app/vkpt-merge" -q -o "$work/${name}_${spp}_raw.pfm" "$work/${name}_${spp}.exr"
        line="$(timed "$work/${name}_${spp}_denoise.time" "$app/vkpt-denoise" \
            "$work/${name}_${spp}.exr" -o "$work/${name}_${spp}_denoised.pfm")"
        sed -E 's/.* in ([0-9.]+) s \(.*/\1/' <<< "$line" > "$work/${name}_${spp}_denoise.seconds"
    done
    # shellcheck disable=SC2086 # spps is a word list
    python3 tests/bench/denoise_trade.py table "$work" "$name" $spps
    python3 tests/bench/denoise_trade.py pictures "$work" "$name" "$picture_spp" docs/trade/images
done
