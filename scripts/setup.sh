#!/usr/bin/env bash
# Installs every Debian package glint needs to build, test and run, non-interactively.
# Idempotent: packages already present are left alone, and apt is not touched when nothing is missing.
# CUDA (nvcc) is not a Debian package here; the build uses it when it is found (see README).
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build pkg-config git
  # libraries (third-party code comes only from these packages)
  libglm-dev libstb-dev libtinyobjloader-dev libtinygltf-dev nlohmann-json3-dev
  libcli11-dev libfmt-dev libtbb-dev libembree-dev
  # linear HDR images: glint render --format exr, glint compare on EXR
  libopenexr-dev
  # OpenGL: headless EGL on Mesa llvmpipe, GL loader, windowed viewer
  libegl-dev libopengl-dev libgl-dev libgl1-mesa-dri libegl-mesa0 libepoxy-dev
  libglfw3-dev libimgui-dev
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev
  # the Python module (python/, GLINT_PYTHON) and its tests (pytest, numpy; PIL reads PNGs)
  pybind11-dev python3-dev python3-numpy python3-pytest python3-pil
  # fuzzing (preset fuzz): clang with libFuzzer and its sanitizer runtimes (libclang-rt-dev); the
  # asan preset uses gcc's own (libasan8, libubsan1, part of build-essential)
  clang libclang-rt-dev
  # runtime tools: video encoding, plots, a virtual display for the viewer
  ffmpeg python3 python3-matplotlib xvfb
  # scale-out over ranks (GLINT_MPI, docs/scale-out.md): Open MPI's headers and mpirun
  libopenmpi-dev openmpi-bin
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages already installed"
  exit 0
fi

sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
echo "setup: installing ${#missing[@]} packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup: done"
