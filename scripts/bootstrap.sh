#!/usr/bin/env bash
# Installs the Debian packages this project needs, and only those that are missing.
# Idempotent: when everything is present it prints one line and returns in well under a second.
# Uses sudo only when not root. Called first by `make test`, `make sim` and .ci/run.
set -euo pipefail

# package            why
PACKAGES=(
  g++                # C++17 compiler for the reference, CLI, tests and Verilator models
  cmake              # build system (source of truth)
  ninja-build        # CMake generator
  pkg-config
  python3            # the synthesis and FPGA flow driver (flow/synth.py, standard library only)
  libopencv-dev      # image I/O, YUV conversion, colormaps, StereoSGBM baselines
  libgtest-dev       # GoogleTest
  googletest
  libbenchmark-dev   # Google Benchmark
  verilator          # RTL lint and simulation (5.006 on bookworm)
  iverilog           # second (4-state) simulator, parse check
  yosys              # synthesis (0.23 on bookworm)
  opensta            # static timing
  qflow-tech-osu018  # OSU 0.18 um standard cells for gate count and timing
  gtkwave            # waveform viewer for `make wave` (and fst2vcd, headless)
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "bootstrap: all ${#PACKAGES[@]} required packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "bootstrap: need root or sudo to install: ${missing[*]}" >&2; exit 1
  fi
fi

echo "bootstrap: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get -o DPkg::Lock::Timeout=600 update -qq
$SUDO apt-get -o DPkg::Lock::Timeout=600 install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "bootstrap: done"
