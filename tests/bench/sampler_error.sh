#!/usr/bin/env bash
# sampler_error.sh — error against a high-sample reference for the two samplers (--sampler sobol,
# independent) on the Cornell box (128², depth 8): relMSE at 16, 64 and 256 spp in each program,
# the mean and range over SEEDS; the ratio independent/sobol; the error the variances estimate
# (what adaptive sampling and --target-error see) against the true one; the median render time
# and its ratio to embree-ref's; and the radially averaged power spectrum of the 16-spp error
# (white noise is flat, blue noise rises with frequency), written to OUT/sampler-spectrum.csv.
#
#   bash tests/bench/sampler_error.sh [BUILD_DIR]     (default build/release; built if missing)
# REFERENCE (a PFM of the same render; made with vkpt-ref, independent numbers, seed 777 and
# REF_SPP samples when not given), REF_SPP (16384), SEEDS ("1 2 3"), SPPS ("16 64 256"),
# PROGRAMS ("vkpt vkpt-ref embree-ref"), OUT (.) override the defaults.
set -euo pipefail
cd "$(dirname "$0")/../.."
build="${1:-build/release}"
[ -x "$build/host/app/vkpt" ] || bash ci/build.sh "$(basename "$build")"
seeds="${SEEDS:-1 2 3}"
spps="${SPPS:-16 64 256}"
programs="${PROGRAMS:-vkpt vkpt-ref embree-ref}"
out="${OUT:-.}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
source ci/lavapipe_env.sh
unset VKPT_VALIDATION
scene=(scenes/cornell-box.gltf --res 128 128 --max-depth 8)

executable() {
    case "$1" in
    embree-ref) echo "$build/tests/bench/embree-ref" ;;
    *) echo "$build/host/app/$1" ;;
    esac
}

reference="${REFERENCE:-}"
if [ -z "$reference" ]; then
    reference="$work/reference.pfm"
    echo "sampler_error: rendering the reference (${REF_SPP:-16384} spp)..." >&2
    "$build/host/app/vkpt-ref" --quiet --sampler independent --seed 777 --spp "${REF_SPP:-16384}" \
        "${scene[@]}" -o "$reference" > /dev/null
fi

echo "sampler_error: $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)), load $(cut -d' ' -f1-3 /proc/loadavg)"
for program in $programs; do
    exe="$(executable "$program")"
    if [ ! -x "$exe" ]; then
        echo "sampler_error: $program not built; skipped" >&2
        continue
    fi
    for sampler in sobol independent; do
        for spp in $spps; do
            for seed in $seeds; do
                echo -ne "  $program $sampler $spp spp seed $seed...\r" >&2
                "$exe" --quiet --sampler "$sampler" --spp "$spp" --seed "$seed" "${scene[@]}" \
                    --reference "$reference" -o "$work/${program}_${sampler}_${spp}_$seed.pfm" \
                    --stats-json "$work/${program}_${sampler}_${spp}_$seed.json" > /dev/null
            done
        done
    done
done
printf '\r%*s\r' 60 '' >&2

python3 - "$work" "$reference" "$out" "$seeds" "$spps" "$programs" <<'PY'
import cmath, json, math, os, statistics, struct, sys
work, reference, out = sys.argv[1], sys.argv[2], sys.argv[3]
seeds, spps, programs = sys.argv[4].split(), sys.argv[5].split(), sys.argv[6].split()

def run(program, sampler, spp, seed):
    path = f"{work}/{program}_{sampler}_{spp}_{seed}.json"
    if not os.path.exists(path):
        return None
    stats = json.load(open(path))
    last = stats["convergence"]["curve"][-1]
    return last["relMse"], last["estimatedRelMse"], last["renderSeconds"]

print("| program | spp | relMSE sobol (range) | relMSE independent (range) | independent / sobol "
      "| estimated / true, sobol | estimated / true, independent | render s sobol / independent "
      "| time vs embree-ref, sobol |")
print("|---|---|---|---|---|---|---|---|---|")
embree = {}
for spp in spps:
    runs = [run("embree-ref", "sobol", spp, s) for s in seeds]
    if all(runs):
        embree[spp] = statistics.median(r[2] for r in runs)
for program in programs:
    for spp in spps:
        cols = {}
        for sampler in ("sobol", "independent"):
            runs = [run(program, sampler, spp, s) for s in seeds]
            if not all(runs):
                break
            rel = [r[0] for r in runs]
            est = statistics.mean(r[1] for r in runs) / statistics.mean(rel)
            cols[sampler] = (statistics.mean(rel), min(rel), max(rel), est,
                             statistics.median(r[2] for r in runs))
        if len(cols) < 2:
            continue
        s, i = cols["sobol"], cols["independent"]
        versus = f"{s[4] / embree[spp]:.2f}×" if spp in embree else "–"
        print(f"| {program} | {spp} | {s[0]:.3e} ({s[1]:.2e}–{s[2]:.2e}) "
              f"| {i[0]:.3e} ({i[1]:.2e}–{i[2]:.2e}) | {i[0] / s[0]:.2f}× | {s[3]:.2f} | {i[3]:.2f} "
              f"| {s[4]:.2f} / {i[4]:.2f} | {versus} |")

# The spectrum: luminance error against the reference, its 2-D DFT (rows, then columns), power
# averaged over rings of equal radius and over the seeds, for the lowest spp and the first program.
def read_pfm(path):
    with open(path, "rb") as f:
        assert f.readline().strip() == b"PF"
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        data = struct.unpack(("<" if scale < 0 else ">") + "f" * (3 * width * height), f.read())
    lum = [0.2126 * data[3 * i] + 0.7152 * data[3 * i + 1] + 0.0722 * data[3 * i + 2]
           for i in range(width * height)]
    return width, height, lum

def dft(values):
    n = len(values)
    twiddle = [cmath.exp(-2j * math.pi * k / n) for k in range(n)]
    return [sum(values[x] * twiddle[(k * x) % n] for x in range(n)) for k in range(n)]

width, height, ref = read_pfm(reference)
spp, program = spps[0], programs[0]
rings = {}
for sampler in ("sobol", "independent"):
    power = [0.0] * (width // 2 + 1)
    counts = [0] * (width // 2 + 1)
    for seed in seeds:
        _, _, img = read_pfm(f"{work}/{program}_{sampler}_{spp}_{seed}.pfm")
        err = [(img[i] - ref[i]) / max(ref[i], 1e-3) for i in range(width * height)]
        rows = [dft(err[y * width:(y + 1) * width]) for y in range(height)]
        cols = [dft([rows[y][x] for y in range(height)]) for x in range(width)]
        for x in range(width):
            for y in range(height):
                fx, fy = min(x, width - x), min(y, height - y)
                r = int(round(math.hypot(fx, fy)))
                if r <= width // 2:
                    power[r] += abs(cols[x][y]) ** 2 / (width * height)
                    counts[r] += 1
    rings[sampler] = [p / c if c else 0.0 for p, c in zip(power, counts)]
path = os.path.join(out, "sampler-spectrum.csv")
with open(path, "w") as f:
    f.write(f"# {program}, Cornell box 128², {spp} spp, depth 8: radially averaged power of the "
             f"relative luminance error, mean over seeds {' '.join(seeds)}\n")
    f.write("frequency,sobol,independent\n")
    for r in range(1, width // 2 + 1):
        f.write(f"{r / width:.5f},{rings['sobol'][r]:.6g},{rings['independent'][r]:.6g}\n")
low = lambda s: statistics.mean(rings[s][1:width // 8])
high = lambda s: statistics.mean(rings[s][3 * width // 8:width // 2 + 1])
print(f"\nspectrum ({program}, {spp} spp): power at the lowest quarter of frequencies / highest "
      f"quarter: sobol {low('sobol') / high('sobol'):.3f}, independent "
      f"{low('independent') / high('independent'):.3f}; written to {path}")
PY
