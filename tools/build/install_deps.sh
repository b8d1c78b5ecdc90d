#!/usr/bin/env bash
# Usage: tools/build/install_deps.sh [--bench]
#
# Installs the Debian packages the project needs, only those that are missing.
#   tools/build/install_deps.sh           what building, running and testing need
#   tools/build/install_deps.sh --bench   that, plus what tools/bench adds (make bench):
#                                         Embree for the embree_peer CPU peer, matplotlib
#                                         for the chart
set -euo pipefail
usage() { awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; }

packages=(
    build-essential cmake pkg-config python3
    libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
    glslang-dev glslang-tools
    libglfw3-dev libglm-dev libstb-dev
    libimgui-dev              # the window's overlay (Dear ImGui with its GLFW and Vulkan backends)
    libtinyexr-dev            # -o out.exr and image_diff's EXR input
    libassimp-dev             # models other than OBJ: PLY, STL, glTF and GLB, FBX, COLLADA, 3DS
    libjpeg-dev               # compare: JPEG decoded, and re-encoded as the image was (libjpeg-turbo)
    googletest libgtest-dev
    xvfb xauth x11-utils x11-apps xdotool
    clang libclang-rt-14-dev  # make check-hardening: libFuzzer and the sanitizer build
    clang-format              # tools/format.sh --check, run by the suite
    python3-skimage           # the SSIM test's independent values (structural_similarity)
    parallel                  # GNU parallel: the farm recipe of docs/batches.md, tested locally
    chromium                  # compare --report: the suite loads the page in headless Chromium
)
# Optional: the benchmark only. Raytracer and the tests never need them.
bench_packages=(libembree-dev python3-matplotlib)

case "${1:-}" in
    "") ;;
    --bench) packages+=("${bench_packages[@]}") ;;
    -h | --help) usage; exit 0 ;;
    *) usage >&2; exit 2 ;;
esac

missing=()
for package in "${packages[@]}"; do
    status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
    [[ $status == "install ok installed" ]] || missing+=("$package")
done
((${#missing[@]} == 0)) && exit 0

echo "Installing missing packages: ${missing[*]}"
sudo=""
[[ $(id -u) -eq 0 ]] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
