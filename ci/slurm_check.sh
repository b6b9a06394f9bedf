#!/usr/bin/env bash
# slurm_check.sh — the Slurm recipe (ci/farm/slurm) end to end on this one machine: starts a
# private single-node Slurm (munged with its own key and socket, slurmctld and slurmd on
# 127.0.0.1, no accounting, state and logs in a temporary folder), submits the Cornell box as
# an array job of 4 vkpt tasks plus the dependent merge job, compares the merged image with a
# single run (oiiotool), renders an animation's frames as a second array job (one frame per
# task), and stops every daemon it started, by pid. Needs root (the daemons run
# as root here), Debian's slurm-wlm and munge, and openimageio-tools (ci/install_deps.sh).
#
#   bash ci/slurm_check.sh [BUILD_DIR]      (default build/ci; the CTest label `slurm` runs it)
set -euo pipefail
cd "$(dirname "$0")/.."
build="$(cd "${1:-build/ci}" && pwd)"
recipe="$(pwd)/ci/farm/slurm"
scene="$(pwd)/scenes/cornell-box.gltf"

for tool in munged slurmctld slurmd sbatch scontrol sinfo oiiotool; do
    command -v "$tool" >/dev/null ||
        { echo "slurm_check: $tool is missing; run bash ci/install_deps.sh" >&2; exit 1; }
done
[ "$(id -u)" -eq 0 ] || { echo "slurm_check: needs root (private daemons as root)" >&2; exit 1; }

work="$(mktemp -d "${TMPDIR:-/tmp}/vkpt-slurm.XXXXXX")"
chmod 755 "$work" # munged wants its socket's folder searchable by every client
pids=()
stop_daemons() {
    local pid
    for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
    for pid in "${pids[@]}"; do
        for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
        kill -9 "$pid" 2>/dev/null || true
    done
    wait 2>/dev/null || true
}
show_logs() {
    for log in "$work"/*.log "$work"/*.out "$work"/out/*.log; do
        [ -f "$log" ] && { echo "--- $log"; tail -n 20 "$log"; }
    done
}
finish() {
    local status=$?
    [ "$status" -eq 0 ] || show_logs >&2
    stop_daemons
    rm -rf "$work"
    exit "$status"
}
trap finish EXIT

free_port() { python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'; }

# munge: its own key, socket, pid and seed files; foreground so that $! is its pid.
dd if=/dev/urandom of="$work/munge.key" bs=1024 count=1 status=none
chmod 400 "$work/munge.key"
munged --foreground --force --key-file="$work/munge.key" --socket="$work/munge.sock" \
    --pid-file="$work/munged.pid" --seed-file="$work/munge.seed" \
    --log-file="$work/munged.log" > "$work/munged.out" 2>&1 &
pids+=($!)

mkdir -p "$work/state" "$work/spool" "$work/out"
export SLURM_CONF="$work/slurm.conf"
cat > "$SLURM_CONF" <<CONF
ClusterName=vkptcheck
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$(free_port)
SlurmdPort=$(free_port)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$work/munge.sock
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
NodeName=vkptnode NodeAddr=127.0.0.1 CPUs=$(nproc) RealMemory=1000 State=UNKNOWN
PartitionName=check Nodes=vkptnode Default=YES MaxTime=INFINITE State=UP
CONF

# Munge first: the Slurm daemons authenticate every message through it.
for _ in $(seq 50); do [ -S "$work/munge.sock" ] && break; sleep 0.1; done
slurmctld -D -c -f "$SLURM_CONF" > "$work/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -N vkptnode -f "$SLURM_CONF" > "$work/slurmd.out" 2>&1 &
pids+=($!)

started=$(date +%s)
until sinfo -h -o '%T' 2>/dev/null | grep -qx idle; do
    (( $(date +%s) - started < 60 )) || { echo "slurm_check: the node never became idle" >&2; exit 1; }
    sleep 0.5
done
echo "slurm_check: Slurm up in $(( $(date +%s) - started )) s"

# The recipe, as a user runs it: 4 tasks of a 32×32 Cornell box at 16 spp, then the merge.
source ci/lavapipe_env.sh
export LP_NUM_THREADS=1 # two tasks share the two cores
submitted=$(date +%s)
read -r array merge < <(VKPT="$build/host/app/vkpt" VKPT_MERGE="$build/host/app/vkpt-merge" \
    SCENE="$scene" SPP=16 TASKS=4 OUT_DIR="$work/out" RENDER_ARGS="--res 32 32" \
    CHECKPOINT=30 bash "$recipe/submit.sh")
echo "slurm_check: array job $array, merge job $merge"

job_state() { scontrol show job "$1" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | head -n 1 | cut -d= -f2; }
while true; do
    state=$(job_state "$merge")
    case "$state" in
    COMPLETED) break ;;
    FAILED | CANCELLED | TIMEOUT | NODE_FAIL | OUT_OF_MEMORY)
        echo "slurm_check: merge job $merge ended $state" >&2; exit 1 ;;
    esac
    (( $(date +%s) - submitted < 300 )) || { echo "slurm_check: jobs still $state after 300 s" >&2; exit 1; }
    sleep 0.5
done
echo "slurm_check: array and merge done in $(( $(date +%s) - submitted )) s"

# One run of all 16 samples: the merged image must equal it to float rounding (the device's
# Kahan sums: 1e-6 relative, here at most 1e-5 absolute), with the same sample counts.
"$build/host/app/vkpt" --quiet --spp 16 --res 32 32 -o "$work/single.exr" "$scene" > /dev/null 2>&1
oiiotool "$work/out/merged.exr" --ch R,G,B "$work/single.exr" --ch R,G,B --fail 1e-5 --diff
oiiotool "$work/out/merged.exr" --ch sampleCount "$work/single.exr" --ch sampleCount --fail 0 --diff

# The frames recipe (render_frames.sbatch), as a user runs it: a 4-frame piece of the turntable
# (scenes/turntable.gltf, 16×16 at 4 spp, 4 frames a second) as an array job, one frame per
# task. Every frame must be written, and at one seed only what moves can change a pixel: frames
# 0 and 2 (the object turned by 45°) must differ.
mkdir -p "$work/frames"
frames=$(VKPT="$build/host/app/vkpt" SCENE="$(pwd)/scenes/turntable.gltf" SPP=4 FPS=4 \
    OUT_DIR="$work/frames" RENDER_ARGS="--res 16 16 --seed 1" \
    sbatch --parsable --array=0-3 --output="$work/frames/frame_%a.log" \
    "$recipe/render_frames.sbatch")
frames="${frames%%;*}"
echo "slurm_check: frames array job $frames"
submitted=$(date +%s)
while [ -n "$(squeue --noheader --jobs="$frames" 2>/dev/null)" ]; do
    (( $(date +%s) - submitted < 300 )) ||
        { echo "slurm_check: frame tasks still queued or running after 300 s" >&2; exit 1; }
    sleep 0.5
done
for frame in 0000 0001 0002 0003; do
    [ -s "$work/frames/frame.$frame.png" ] ||
        { echo "slurm_check: frame $frame was not written (frames/frame_*.log)" >&2; exit 1; }
done
if cmp -s "$work/frames/frame.0000.png" "$work/frames/frame.0002.png"; then
    echo "slurm_check: frames 0 and 2 are the same image: nothing moved" >&2
    exit 1
fi
echo "slurm_check: 4 frames in $(( $(date +%s) - submitted )) s"
echo "slurm_check: passed"
