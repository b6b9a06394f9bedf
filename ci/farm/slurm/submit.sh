#!/usr/bin/env bash
# submit.sh — submits a vkpt render to Slurm as an array job of TASKS tasks and a merge job that
# waits for all of them (afterok); prints the two job ids. See docs/distributed.md.
#
#   VKPT=/opt/vkpt/bin/vkpt VKPT_MERGE=/opt/vkpt/bin/vkpt-merge \
#   SCENE=/shared/scene.glb SPP=4096 TASKS=16 OUT_DIR=/shared/render \
#   RENDER_ARGS="--res 3840 2160" bash ci/farm/slurm/submit.sh [extra sbatch options...]
#
# Extra arguments go to both sbatch calls (--partition, --time, --gres=gpu:1 for the tasks...).
# The job environment is this one (sbatch's default --export=ALL), so the variables above reach
# the jobs; OUT_DIR must be on a file system every node sees.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
: "${VKPT:?}" "${VKPT_MERGE:?}" "${SCENE:?}" "${SPP:?}" "${TASKS:?}" "${OUT_DIR:?}"
mkdir -p "$OUT_DIR"
export VKPT VKPT_MERGE SCENE SPP TASKS OUT_DIR

array=$(sbatch --parsable --array="0-$((TASKS - 1))" --output="$OUT_DIR/task_%a.log" "$@" \
    "$here/render_task.sbatch")
array="${array%%;*}" # "id;cluster" on multi-cluster set-ups
merge=$(sbatch --parsable --dependency="afterok:$array" --kill-on-invalid-dep=yes \
    --output="$OUT_DIR/merge.log" "$@" "$here/merge_parts.sbatch")
echo "$array ${merge%%;*}"
