#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# make coverage: Verilator line and toggle coverage of the engine RTL under the
# regression stimulus. Builds a coverage-instrumented model in BUILD_DIR
# (default build/cov; -DMCADSW_COVERAGE=ON), runs the engine tests (faults, invalid
# configurations, small pairs), the random differential regression (N cases,
# default 40, seed 2026) and two bundled pairs through the harness,
# merges the per-run files and reports line and toggle coverage per module.
# Then checks the toggle points left at 0 against tests/coverage/untoggled.txt
# (each listed with its reason; scripts/untoggled_check.awk) and the total
# toggle coverage against MIN_TOGGLE percent (default 90): an unlisted
# point, a stale line or less coverage fails (exit 1).
#   scripts/coverage.sh [BUILD_DIR]     N=<cases> to change the random part
# Outputs BUILD_DIR/coverage/: merged.dat, coverage.info (lcov), annotated/ (sources
# with per-line counts), summary.txt.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/cov}
n=${N:-40}
out=$build/coverage
# The coverage model is built with Debian's Verilator 5.006, not the tool environment's
# 5.052: 5.052's runtime counts the toggles of a signal wider than 64 bits wrongly (its
# VL_COV_TOGGLE_CHG_ST_W credits bit 32 k + j with the changes of bit j of the lower words;
# docs/tool_notes.md 2 has the reproduction), so its toggle figures and this list's
# would be wrong wherever a bus is wide.
vroot=/usr/share/verilator
vcov=/usr/bin/verilator_coverage
[ -f "$vroot/verilator-config.cmake" ] && [ -x "$vcov" ] || {
  echo "coverage: Debian's Verilator missing at $vroot (run scripts/bootstrap.sh)" >&2; exit 2; }
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DMCADSW_COVERAGE=ON \
  -DMCADSW_VERILATOR_ROOT="$vroot" -DMCADSW_BLOCK_BENCHES=none -DMCADSW_CORE_MODEL=OFF > /dev/null
echo "coverage: building the instrumented model ($build)"
cmake --build "$build" --target mcadsw_sim mcadsw_sim_random rtl_engine_test rtl_axi_test -j "$(nproc)" > "$build/coverage_build.log" 2>&1 || {
  tail -30 "$build/coverage_build.log"; echo "coverage: build failed" >&2; exit 1; }
rm -rf "$out"; mkdir -p "$out/runs"
export MCADSW_COVERAGE_DIR=$out/runs
data=$root/data
# The stimulus, longest first, as many at a time as there are cores (each run
# writes its own .dat file into runs/, merged below).
names=("engine tests (faults, invalid configurations)"
       "$n random cases (seed 2026)"
       "AXI tests (bursts, response errors, abort, the register window)"
       "Tsukuba D=16 with random latency, CIF Teddy crop D=64, camera C's raw Teddy rectified (LR)")
logs=(engine_test random axi_test pairs)
stimulus() {
  case $1 in
    0) "$build/bin/rtl_engine_test" ;;
    1) "$build/bin/mcadsw_sim_random" --cases "$n" --seed 2026 ;;
    2) "$build/bin/rtl_axi_test" ;;
    3) "$build/bin/mcadsw_sim" "$data/middlebury/tsukuba/left.png" "$data/middlebury/tsukuba/right.png" -d 16 \
         --random-latency 3 &&
       "$build/bin/mcadsw_sim" "$data/cif/teddy/left.png" "$data/cif/teddy/right.png" -d 64 --crop 60,40,120,60 &&
       "$build/bin/mcadsw_sim" "$data/raw/C/cif/teddy/left.png" "$data/raw/C/cif/teddy/right.png" -d 24 \
         --calib "$data/raw/C/cif/teddy/calib.yml" --step 8 --crop 16,16,96,48 --lr --subpixel ;;
  esac
}
par=$(nproc)
for i in 0 1 2 3; do
  while [ "$(jobs -rp | wc -l)" -ge "$par" ]; do wait -n || true; done
  echo "coverage: ${names[$i]}"
  { rc=0; stimulus "$i" > "$out/${logs[$i]}.log" 2>&1 || rc=$?; echo "$rc" > "$out/${logs[$i]}.rc"; } &
done
wait
failed=0
for i in 0 1 2 3; do
  if [ "$(cat "$out/${logs[$i]}.rc" 2>/dev/null)" != 0 ]; then
    tail -20 "$out/${logs[$i]}.log"
    echo "coverage: ${names[$i]} failed ($out/${logs[$i]}.log)" >&2
    failed=1
  fi
done
[ "$failed" = 0 ] || exit 1

"$vcov" --write "$out/merged.dat" "$out"/runs/*.dat > /dev/null
"$vcov" --write-info "$out/coverage.info" "$out/merged.dat" > /dev/null
"$vcov" --annotate "$out/annotated" "$out/merged.dat" > "$out/annotate.log"
# Points per module and kind from merged.dat: each C line names its page
# (v_line/<module>, v_toggle/<module>, v_branch/<module>) and ends with the count.
awk '
  /^C / {
    n = $NF; page = $0; sub(/.*\001page\002/, "", page); sub(/\001.*/, "", page)
    split(page, p, "/"); kind = p[1]; mod = p[2]
    if (kind == "v_branch") kind = "v_line"          # branches count as lines (--coverage-line)
    tot[mod, kind]++; if (n > 0) hit[mod, kind]++; mods[mod] = 1
    ttot[kind]++; if (n > 0) thit[kind]++
  }
  function pct(h, t) { return t ? sprintf("%5.1f %% (%d/%d)", 100 * h / t, h, t) : "      -" }
  END {
    printf "%-24s %-24s %s\n", "module", "line", "toggle"
    for (m in mods) printf "%-24s %-24s %s\n", m, pct(hit[m, "v_line"], tot[m, "v_line"]), pct(hit[m, "v_toggle"], tot[m, "v_toggle"]) | "sort"
    close("sort")
    printf "%-24s %-24s %s\n", "TOTAL", pct(thit["v_line"], ttot["v_line"]), pct(thit["v_toggle"], ttot["v_toggle"])
    printf "toggle_percent %.1f\n", ttot["v_toggle"] ? 100 * thit["v_toggle"] / ttot["v_toggle"] : 0
  }' "$out/merged.dat" > "$out/summary.txt"
status=0
if [ "$n" = 40 ]; then
  awk -f "$root/scripts/untoggled_check.awk" "$root/tests/coverage/untoggled.txt" "$out/merged.dat" \
    >> "$out/summary.txt" || status=1
else
  echo "untoggled points not checked: tests/coverage/untoggled.txt is for the default stimulus (N=40)" >> "$out/summary.txt"
fi
grep -v '^toggle_percent' "$out/summary.txt"
echo "coverage: annotated sources in $out/annotated, lcov data $out/coverage.info"
min=${MIN_TOGGLE:-90}
toggle=$(awk '/^toggle_percent/ { print $2 }' "$out/summary.txt")
if awk -v t="$toggle" -v m="$min" 'BEGIN { exit !(t + 0 < m + 0) }'; then
  echo "coverage: toggle coverage $toggle % is below $min %" >&2
  status=1
fi
if [ "$status" -ne 0 ]; then
  echo "coverage: FAILED (tests/coverage/untoggled.txt: list each new untoggled point with its reason, delete stale lines)" >&2
fi
exit "$status"
