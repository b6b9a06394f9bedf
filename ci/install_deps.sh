#!/usr/bin/env bash
# install_deps.sh — installs vkpt's build and test dependencies from Debian 12's archive.
# Idempotent: when every package is already installed it touches nothing.
set -euo pipefail

packages=(
    build-essential cmake ninja-build pkg-config ccache
    libvulkan-dev libvulkan-volk-dev mesa-vulkan-drivers vulkan-validationlayers
    glslang-tools glslang-dev spirv-tools
    libglm-dev libstb-dev libtinygltf-dev
    # Compressed glTF: Draco meshes, meshopt buffer views, WebP textures; the JSON pre-pass.
    libdraco-dev libmeshoptimizer-dev libwebp-dev nlohmann-json3-dev
    libgtest-dev
    gnuplot-nox # the trade study's plots (vkpt-study; the CI test label `study` draws them)
    libembree-dev # benchmarks only (embree-ref, traversal_bench): never linked by vkpt or vkpt-ref
    libopenexr-dev # OpenEXR output: render states, AOVs (host/state)
    # Tests only: oiiotool reads the EXR layers as compositors do (label farm); a private Slurm
    # runs the array-job recipe (label slurm); python3-yaml parses the OpenJD template (farm).
    openimageio-tools slurm-wlm munge python3-yaml
    clang-format # ci/format_check.sh: the C++ sources against .clang-format
    clang libclang-rt-dev # the fuzz preset: clang with libFuzzer, ASan and UBSan runtimes
)

missing=()
for package in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
        missing+=("$package")
done

if [ ${#missing[@]} -eq 0 ]; then
    echo "install_deps: all ${#packages[@]} packages present"
    exit 0
fi

echo "install_deps: installing ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
