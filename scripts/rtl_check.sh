#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# Checks that every RTL file is accepted by the three tools the project uses.
#   scripts/rtl_check.sh lint      verilator --lint-only -Wall, each module as top
#   scripts/rtl_check.sh yosys     Yosys 0.23 read_verilog -sv + hierarchy + proc
#   scripts/rtl_check.sh iverilog  Icarus Verilog 11, -g2012
#   scripts/rtl_check.sh all       the three
#   scripts/rtl_check.sh board     verilator --lint-only -Wall of the board shells
#                                  (rtl/board/*.sv, each with the SoC under it; the ECP5
#                                  primitives they instantiate from tests/fpga/ecp5_cells_stub.sv)
#   scripts/rtl_check.sh wrapper   the vendor-tool wrapper rtl/mcadsw_axi.v (Verilog-2001, not in
#                                  rtl/mcadsw.f): verilator -Wall with .v files read as IEEE
#                                  1364-2001, Yosys 0.23's plain Verilog parser with mcadsw_top's
#                                  ports as a black box's (hierarchy -check), Icarus elaborating
#                                  the whole IP under it
# A second argument, a package file, replaces rtl/mcadsw_pkg.sv: another
# configuration's (the FPGA target's, build/rtl/fpga/mcadsw_pkg.sv, elaborates the
# branches the default package leaves out); a package with RECT = 0 is checked with the
# file list without the rectifier (scripts/rtl_files.sh --no-rect).
# Exits non-zero on any warning or error. Used by `make lint` and by ctest.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
source "$root/scripts/tools.sh"  # the pinned Verilator first on PATH
alt_pkg=${2:-}
if [ -n "$alt_pkg" ]; then
  [ -f "$alt_pkg" ] || { echo "rtl_check: package $alt_pkg not found" >&2; exit 2; }
  alt_pkg=$(cd "$(dirname "$alt_pkg")" && pwd)/$(basename "$alt_pkg")
fi
cd "$root/rtl"
pkg=mcadsw_pkg.sv
# The packages, read in this order before the modules and never linted as a top: the
# engine's, then the rectifier's (it imports the engine's). rtl/mcadsw.f lists both first.
pkgs=("$pkg" rect/mcadsw_rect_pkg.sv)
# in_list NEEDLE ITEM...: whether NEEDLE is one of the items. Bash alone, no pipe into
# `grep -q`: under pipefail, grep -q leaving at its first match can kill the printf
# feeding it with SIGPIPE, and the pipeline then fails on a match (rtl_check reported
# listed files as "not in rtl/mcadsw.f", 2026-11-26, twice, once in CI).
in_list() {
  local needle=$1 item; shift
  for item in "$@"; do [ "$item" = "$needle" ] && return 0; done
  return 1
}
norect=()
if [ -n "$alt_pkg" ] && grep -qE 'localparam int RECT +=  *0;' "$alt_pkg"; then norect=(--no-rect); fi
list=$("$root/scripts/rtl_files.sh" --no-pkg "${norect[@]}" .) || { echo "rtl_check: scripts/rtl_files.sh failed" >&2; exit 1; }
mapfile -t listed <<< "${list//.\//}"
mods=()
for f in "${listed[@]}"; do
  [ -n "$f" ] || continue
  in_list "$f" "${pkgs[@]}" || mods+=("$f")
done
for p in "${pkgs[@]:1}"; do
  in_list "$p" "${listed[@]}" || { echo "rtl_check: rtl/$p is not in rtl/mcadsw.f" >&2; exit 1; }
done
# The list is the one every tool reads: a source file it does not name is an error
# (rtl/rect/rect.f, the rectifier's own list, which no build or test reads, is not read here;
# rect/mcadsw_rect_none.sv replaces the rect/ modules without the rectifier, and the
# rect/ modules it replaces are not in that list).
for f in *.sv rect/*.sv; do
  [ "$f" = rect/mcadsw_rect_none.sv ] && continue
  [ ${#norect[@]} -gt 0 ] && [ "${f#rect/}" != "$f" ] && continue
  in_list "$f" "${pkgs[@]}" "${mods[@]}" || { echo "rtl_check: rtl/$f is not in rtl/mcadsw.f" >&2; exit 1; }
done
waivers=()
[ -f lint_waivers.vlt ] && waivers=(lint_waivers.vlt)
if [ ${#mods[@]} -eq 0 ]; then echo "rtl_check: no RTL modules"; exit 0; fi
files=("${alt_pkg:-$pkg}" "${pkgs[@]:1}" "${mods[@]}")
what=${alt_pkg:+ (package $alt_pkg${norect:+, without the rectifier})}

# lint_top TOP [FILE...]: verilator -Wall of the RTL (and FILEs) with TOP as the top; fails
# on any warning.
lint_top() {
  local top=$1 out; shift
  out=$(verilator --lint-only -Wall --assert -I. "${waivers[@]}" "${files[@]}" "$@" --top-module "$top" 2>&1) || {
    echo "$out"; echo "rtl_check: verilator lint FAILED for $top" >&2; return 1; }
  if grep -q '%Warning' <<<"$out"; then echo "$out"; return 1; fi
}

# tops_of FILE: the modules a file declares (one, named as the file, but for
# rect/mcadsw_rect_none.sv).
tops_of() { sed -n 's/^module \([a-z_0-9]*\).*/\1/p' "$1"; }

# Each top in its own Verilator process, as many at a time as the machine has cores
# (make lint stays within the pre-stop hook's time); a failing top's messages are
# printed once all have run.
run_lint() {
  local f top tmp running=0 failed=0 jobs
  jobs=$(nproc)
  tmp=$(mktemp -d)
  for f in "${mods[@]}"; do
    for top in $(tops_of "$f"); do
      lint_top "$top" > "$tmp/$top.log" 2>&1 &
      running=$((running + 1))
      if [ "$running" -ge "$jobs" ]; then wait -n || failed=1; running=$((running - 1)); fi
    done
  done
  while [ "$running" -gt 0 ]; do wait -n || failed=1; running=$((running - 1)); done
  for f in "$tmp"/*.log; do [ -s "$f" ] && cat "$f"; done
  rm -rf "$tmp"
  [ "$failed" = 0 ] || return 1
  echo "rtl_check: verilator --lint-only -Wall clean on ${#mods[@]} modules$what"
}

run_yosys() {
  local tops
  # Yosys 0.23 parses a unary operator before a size cast as part of the size:
  # `-(N)'(x)` as a cast to the size -(N) (it read -(13)'(2) as +2), `~N'(x)` as
  # a cast to the size ~N (it read ~12'(3) as 1); both found by gate-level
  # simulation. Verilator and Icarus apply the operator to the cast value, so the
  # netlist would differ from the simulated RTL. Write ~(N'(x)), 0 - N'(x).
  # (A minus at the start of a line continues the expression above: binary.)
  local bad
  bad=$(for f in "${files[@]}"; do   # code only: comments stripped, line numbers kept
          sed 's://.*$::' "$f" |
            grep -nE "((^|[=(,?:+*/&|^~!<>-])[[:space:]]*[~!]|[=(,?:+*/&|^~!<>-][[:space:]]*-)[[:space:]]*([A-Za-z_][A-Za-z_0-9]*|[0-9]+|\([^()]*\))'\(" |
            sed "s|^|$f:|" || true
        done)
  if [ -n "$bad" ]; then
    echo "$bad"
    echo "rtl_check: unary operator before a size cast, -(N)'(x) or ~N'(x), which Yosys 0.23 misreads; write ~(N'(x)) or 0 - N'(x)" >&2
    return 1
  fi
  # One Yosys process: the files are parsed once, then each module is elaborated
  # as the top from that parsed design (design -load), each step announced, so a
  # warning or an error names its module.
  local script="read_verilog -sv ${files[*]}; design -save parsed"
  local n=0
  for f in "${mods[@]}"; do
    for top in $(tops_of "$f"); do
      script+="; design -load parsed; log -stdout rtl_check: elaborating $top; hierarchy -check -top $top; proc"
      n=$((n + 1))
    done
  done
  out=$(yosys -q -p "$script" 2>&1) || {
    echo "$out"; echo "rtl_check: yosys FAILED for $(grep -o 'rtl_check: elaborating [a-z_0-9]*' <<<"$out" | tail -1 | cut -d' ' -f3)" >&2
    return 1; }
  if grep -qi 'warning' <<<"$out"; then
    echo "$out"; echo "rtl_check: yosys warned (the module is the last 'elaborating' line above the warning)" >&2; return 1
  fi
  [ "$(grep -c '^rtl_check: elaborating ' <<<"$out")" = "$n" ] || {
    echo "$out"; echo "rtl_check: yosys did not elaborate every module" >&2; return 1; }
  echo "rtl_check: yosys 0.23 parses and elaborates ${#mods[@]} modules$what"
}

run_iverilog() {
  tmp=$(mktemp); trap 'rm -f "$tmp"' RETURN
  out=$(iverilog -g2012 -Wall -Wno-timescale -I. -o "$tmp" "${files[@]}" 2>&1) || {
    echo "$out"; echo "rtl_check: iverilog FAILED" >&2; return 1; }
  if [ -n "$out" ]; then echo "$out"; echo "rtl_check: iverilog warned" >&2; return 1; fi
  echo "rtl_check: iverilog -g2012 compiles ${#files[@]} files$what"
}

run_board() {
  local n=0 f
  for f in board/*.sv; do
    lint_top "$(basename "${f%.sv}")" "$f" "$root/tests/fpga/ecp5_cells_stub.sv" || return 1
    n=$((n + 1))
  done
  echo "rtl_check: verilator --lint-only -Wall clean on $n board shells$what"
}

run_wrapper() {
  lint_top mcadsw_axi +1364-2001ext+v mcadsw_axi.v || return 1
  local out
  out=$(yosys -q -p "read_verilog -sv ${files[0]} ${files[1]}; read_verilog -sv -lib mcadsw_top.sv; read_verilog mcadsw_axi.v; hierarchy -check -top mcadsw_axi" 2>&1) || {
    echo "$out"; echo "rtl_check: yosys (Verilog-2001 parser) FAILED for mcadsw_axi" >&2; return 1; }
  if grep -qi 'warning' <<<"$out"; then echo "$out"; echo "rtl_check: yosys warned on mcadsw_axi" >&2; return 1; fi
  tmp=$(mktemp); trap 'rm -f "$tmp"' RETURN
  out=$(iverilog -g2012 -Wall -Wno-timescale -I. -s mcadsw_axi -o "$tmp" "${files[@]}" mcadsw_axi.v 2>&1) || {
    echo "$out"; echo "rtl_check: iverilog FAILED for mcadsw_axi" >&2; return 1; }
  if [ -n "$out" ]; then echo "$out"; echo "rtl_check: iverilog warned on mcadsw_axi" >&2; return 1; fi
  echo "rtl_check: the wrapper mcadsw_axi.v clean under verilator -Wall (Verilog-2001), yosys 0.23 read_verilog and iverilog$what"
}

case ${1:-all} in
  lint) run_lint ;;
  yosys) run_yosys ;;
  iverilog) run_iverilog ;;
  board) run_board ;;
  wrapper) run_wrapper ;;
  all) run_lint; run_yosys; run_iverilog; run_wrapper ;;
  *) echo "usage: $0 lint|yosys|iverilog|board|wrapper|all [PACKAGE]" >&2; exit 2 ;;
esac
