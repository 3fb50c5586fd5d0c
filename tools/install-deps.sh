#!/usr/bin/env bash
# Installs marchstudio's build and test dependencies from Debian 12's packages.
# Runs apt-get directly as root, through sudo otherwise.
#   tools/install-deps.sh               what the build and every test need, and
#                                       nanobind in build/python-venv (the Python package)
#   tools/install-deps.sh --build-only  what building marchstudio needs
#                                       (-DBUILD_TESTING=OFF, cpack included)
set -euo pipefail
SUDO=""
if [ "$(id -u)" != "0" ]; then SUDO="sudo"; fi
BUILD=(
  build-essential cmake ninja-build pkg-config   # build-essential brings dpkg-dev: cpack's dpkg-shlibdeps
  python3-glad                      # GL loader generator (glad2), offline specs
  libegl-dev libosmesa6-dev libgl1-mesa-dri libegl-mesa0   # headless GL: EGL + OSMesa, llvmpipe
  libglfw3-dev libglm-dev libimgui-dev   # the viewer: a window and its panel
  libopenimageio-dev
  libpng-dev libopenexr-dev         # io/direct_codec: PNG and EXR without loading OpenImageIO
  libcli11-dev libtomlplusplus-dev nlohmann-json3-dev
  libsndfile1-dev libkissfft-dev    # Shadertoy music inputs: decode (dlopen'd) and the analyser's FFT
  libasound2-dev                    # the viewer plays music inputs through ALSA (dlopen'd; its header only)
  libopenvdb-dev                    # mesh/vdb/: .vdb level sets, in the dlopen'd marchstudio-vdb.so
)
TEST=(
  openimageio-tools
  ffmpeg                            # render --video, and the tests that make video files
  libgtest-dev libgmock-dev
  glslang-tools                     # glslangValidator: shader tests and docs/specialization.md (skipped without)
  xvfb xauth                        # viewer tests get a real X window
  chromium                          # tests/cli/test_test_report.cpp: the test --report page in a real browser
  slurm-wlm munge                   # tests/slurm: a real job array on a localhost cluster
  clang-14 libclang-rt-14-dev       # tests/fuzz: libFuzzer targets (CMakePresets.json "fuzz")
  libtinygltf-dev                   # mesh/: .glb export (glTF 2.0 binary), read back by the unit tests
  python3-openvdb                   # tests read the .vdb back with pyopenvdb (skipped without)
  python3-numpy python3-skimage     # tools/: the mesh baseline script (marching cubes)
  ccache                            # .ci/run compiles through it when present (a rerun in one workspace)
  python3-dev python3-venv python3-pytest   # the Python package: its headers, nanobind's venv, its tests (docs/python.md)
)
case "${1:-}" in
  "") PACKAGES=("${BUILD[@]}" "${TEST[@]}") ;;
  --build-only) PACKAGES=("${BUILD[@]}") ;;
  *) echo "install-deps.sh: unknown argument '$1' (--build-only, or none)" >&2; exit 2 ;;
esac
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${PACKAGES[@]}" >/dev/null
if [ "${1:-}" = "" ]; then
  # The Python package's build needs nanobind, which Debian 12 does not
  # package: from PyPI into a venv under build/ that sees Debian's numpy
  # and pytest; the CMake build finds it there (docs/python.md#install).
  root=$(cd "$(dirname "$0")/.." && pwd)
  [ -x "$root/build/python-venv/bin/python3" ] || /usr/bin/python3 -m venv --system-site-packages "$root/build/python-venv"
  "$root/build/python-venv/bin/pip" install -q --disable-pip-version-check 'nanobind>=2,<4'
fi
echo "marchstudio: dependencies installed"
