#!/usr/bin/env bash
# device_bundle.sh — packs the release build for ci/device_check.sh on a GPU machine that has
# none of Debian's packages (a CUDA image, say): the executables it runs (vkpt, the benchmarks,
# every test executable of the labels that use a Vulkan device), stripped, with the shared
# libraries they load (tinygltf, stb, the Vulkan loader; Embree and TBB for the benchmarks
# that compare with it) and the Khronos validation layer.
# Writes build/device-bundle.tar.xz (about 17 MiB); carry it to the GPU machine together with
# the working tree and run `bash ci/device_check.sh` there.
#
# VKPT_BUILD_DIR: the build to pack (default build/release, built when missing).
set -euo pipefail
cd "$(dirname "$0")/.."

build="${VKPT_BUILD_DIR:-build/release}"
[ -x "$build/host/app/vkpt" ] || bash ci/build.sh release
staging=$(mktemp -d)
trap 'rm -rf "$staging"' EXIT
bundle="$staging/device-bundle"
mkdir -p "$bundle/bin" "$bundle/tests" "$bundle/lib" "$bundle/layers"

strip_into() { strip -o "$2/$(basename "$1")" "$1"; }

for program in host/app/vkpt host/app/vkpt-ref; do
    strip_into "$build/$program" "$bundle/bin"
done
for bench in "$build"/tests/bench/*; do
    [ -f "$bench" ] && [ -x "$bench" ] && strip_into "$bench" "$bundle/bin"
done

# Every test executable with a test in a label that runs on the Vulkan device.
ctest --test-dir "$build" -L "gpu|image|extremes" --show-only=json-v1 2>/dev/null |
    python3 -c '
import json, sys
tests = json.load(sys.stdin)["tests"]
for exe in sorted({t["command"][0] for t in tests if "command" in t}):
    if not exe.endswith("cmake"):
        print(exe)' |
    while read -r test; do strip_into "$test" "$bundle/tests"; done

# The shared libraries the executables load that a non-Debian machine may lack, and the
# validation layer with its manifest pointing next to it.
for library in libtinygltf.so.2d libstb.so.0 libvulkan.so.1 libembree3.so.3 libtbb.so.12 \
    libVkLayer_khronos_validation.so; do
    path=$(ldconfig -p | awk -v name="$library" '$1 == name { print $NF; exit }')
    [ -n "$path" ] || { echo "device_bundle: $library not found (bash ci/install_deps.sh)" >&2; exit 1; }
    cp -L "$path" "$bundle/lib/$library"
done
mv "$bundle/lib/libVkLayer_khronos_validation.so" "$bundle/layers/"
sed 's|"library_path": *"[^"]*"|"library_path": "./libVkLayer_khronos_validation.so"|' \
    /usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json \
    >"$bundle/layers/VkLayer_khronos_validation.json"

# The tests find scenes under the source folder they were built in.
sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$build/CMakeCache.txt" >"$bundle/source_dir.txt"
git rev-parse HEAD >"$bundle/commit.txt" 2>/dev/null || true

mkdir -p build
tar -C "$staging" -cJf build/device-bundle.tar.xz device-bundle
echo "device_bundle: wrote build/device-bundle.tar.xz ($(du -h build/device-bundle.tar.xz | cut -f1))"
