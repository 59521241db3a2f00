#!/usr/bin/env bash
# Installs the Debian 12 packages sketchlab needs. Idempotent: prints nothing
# and touches nothing when every package is already installed.
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build pkg-config git
  # kernel
  libeigen3-dev nlohmann-json3-dev libyaml-cpp-dev
  # lab: SHA-256 of input files for provenance (OpenSSL libcrypto)
  libssl-dev
  # plugin host (Boost.DLL is header-only but needs Boost.Filesystem)
  libboost-dev libboost-filesystem-dev
  # command line, tests
  libcli11-dev catch2
  # plugins and viewers
  libcgal-dev libopenmesh-dev libnlopt-cxx-dev libtbb-dev libnanoflann-dev
  libvtk9-dev libopenmpi-dev libopenxr-dev libxi-dev
  # distributed runs (`mpirun -n N sketchlab run`, app/mpi_run.hpp): the launcher
  openmpi-bin
  # headless rendering and viewer tests (xdotool drives the real window)
  xvfb xauth xdotool
  # the report's 3D views tested in a real browser (tests/app/report_browser_test.cpp);
  # the viewer script itself is committed built (lab/report_web/README.md)
  chromium
  # shared compiler cache between build directories
  ccache
  # libFuzzer harnesses (fuzz/, scripts/fuzz.sh): clang with its runtimes
  clang libclang-rt-14-dev
  # Python API (python/) and Python correctors (plugins/correctors/python),
  # for Debian's /usr/bin/python3
  python3-dev pybind11-dev python3-numpy python3-pytest python3-matplotlib
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup: installing ${#missing[@]} Debian package(s): ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup: done"
