#!/usr/bin/env bash
# make fpga: an FPGA estimate of the engine (issue 19). Yosys synth_xilinx for a
# 7-series part maps mcadsw_top (the engine behind its AXI4-Lite registers; an
# IP core, so no I/O buffers or clock buffer)
# to LUTs, flip-flops, block RAMs (RAMB18E1 / RAMB36E1), LUT RAMs and DSP48E1s;
# the counts go to build/fpga/summary.json and report.md with whether they fit an
# XC7Z020 and an XC7A100T. No timing: nextpnr-xilinx is not packaged (place and
# route would be needed for a clock figure).
#
#   scripts/fpga.sh                     DMAX = 64, PAR = 1, build/fpga
#   DMAX=128 PAR=4 scripts/fpga.sh      another configuration, build/fpga_dmax128_par4
#   TOP=mcadsw_regs OUT=dir             another module (a quick check of the flow)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
die() { echo "fpga: $*" >&2; exit 2; }

dmax=${DMAX:-64}
par=${PAR:-1}
top=${TOP:-mcadsw_top}
# No result of an earlier run may pass for this one's: with OUT given, its summary
# goes before anything is checked.
[ -z "${OUT:-}" ] || rm -f "$OUT/summary.json" "$OUT/report.md"
[[ "$dmax" =~ ^[0-9]{1,3}$ ]] && [ "$((10#$dmax))" -ge 1 ] && [ "$((10#$dmax))" -le 128 ] ||
  die "DMAX='$dmax' is not supported: an integer from 1 to 128"
dmax=$((10#$dmax))
[[ "$par" =~ ^[124]$ ]] || die "PAR='$par' is not supported: 1, 2 or 4"
[ $((dmax % par)) -eq 0 ] || die "DMAX=$dmax is not a multiple of PAR=$par"
if [ -n "${OUT:-}" ]; then out=$OUT
elif [ "$dmax" = 64 ] && [ "$par" = 1 ]; then out=$root/build/fpga
else out=$root/build/fpga_dmax${dmax}_par$par; fi
mkdir -p "$out"
out=$(cd "$out" && pwd)
rm -f "$out/summary.json" "$out/report.md"
command -v yosys >/dev/null || die "yosys not found (run scripts/bootstrap.sh, or make fpga, which runs it)"

# The RTL with a package for this configuration (as the CMake build makes it).
rtl=$out/rtl
rm -rf "$rtl"; mkdir -p "$rtl"
cp $("$root/scripts/rtl_files.sh") "$rtl"/
"$root/scripts/rtl_pkg_dmax.sh" "$dmax" "$root/rtl/mcadsw_pkg.sv" "$rtl/mcadsw_pkg.sv" "$par"
mods=$("$root/scripts/rtl_files.sh" --no-pkg . | sed 's|^\./||' | tr '\n' ' ')

cat > "$out/fpga.ys" <<YS
read_verilog -sv -D SYNTHESIS $rtl/mcadsw_pkg.sv $(for m in $mods; do printf '%s ' "$rtl/$m"; done)
hierarchy -check -top $top
synth_xilinx -family xc7 -top $top -noiopad -noclkbuf
tee -o $out/stat.txt stat
YS
echo "fpga: synth_xilinx -family xc7 of $top (DMAX=$dmax, PAR=$par); log $out/yosys.log"
t0=$(date +%s)
if ! yosys -q -l "$out/yosys.log" "$out/fpga.ys" > /dev/null 2> "$out/yosys.err"; then
  grep -m3 ERROR "$out/yosys.log" "$out/yosys.err" >&2 || tail -5 "$out/yosys.err" >&2
  die "synth_xilinx failed (log $out/yosys.log)"
fi
secs=$(( $(date +%s) - t0 ))

# Cell counts of the design (synth_xilinx flattens it: the last "=== ... ===" block).
awk '/^=== .* ===$/ {delete c; n = 0} NF == 2 && $1 ~ /^[A-Z][A-Z0-9_]+$/ && $2 ~ /^[0-9]+$/ {c[$1] = $2; n++}
     END {for (k in c) print k, c[k]}' "$out/stat.txt" | sort > "$out/cells.txt"
[ -s "$out/cells.txt" ] || die "no cell counts in $out/stat.txt"

# LUTs: logic LUTs (an INV is a LUT1) plus the LUTs memories and shift registers
# occupy (7-series: a RAM64M / RAM32M is 4 LUTs, RAMxxX1D 2 or 4, RAMxxX1S 1 to 4, an SRL one).
read -r lut_logic lut_mem ff bram36 bram18 dsp carry < <(awk '
  $1 ~ /^LUT[1-6]$/ || $1 == "INV" {ll += $2}
  $1 == "RAM32M" || $1 == "RAM64M" || $1 == "RAM128X1D" || $1 == "RAM256X1S" {lm += 4 * $2}
  $1 == "RAM32X1D" || $1 == "RAM64X1D" || $1 == "RAM128X1S" {lm += 2 * $2}
  $1 == "RAM32X1S" || $1 == "RAM64X1S" || $1 == "SRL16E" || $1 == "SRLC32E" {lm += $2}
  $1 ~ /^FD[CPRS]E$/ {ff += $2}
  $1 == "RAMB36E1" {b36 += $2}
  $1 == "RAMB18E1" {b18 += $2}
  $1 == "DSP48E1" {dsp += $2}
  $1 == "CARRY4" {cy += $2}
  END {printf "%d %d %d %d %d %d %d\n", ll, lm, ff, b36, b18, dsp, cy}' "$out/cells.txt")
lut=$((lut_logic + lut_mem))
bram=$(awk -v a="$bram36" -v b="$bram18" 'BEGIN {printf "%.1f", a + b / 2}')

# Device capacities (Xilinx DS190 / DS180): LUTs, flip-flops, 36 Kb block RAMs, DSP48E1s.
fits() {  # name luts ffs bram36 dsps
  awk -v l="$lut" -v f="$ff" -v b="$bram" -v d="$dsp" -v L="$2" -v F="$3" -v B="$4" -v D="$5" -v n="$1" 'BEGIN {
    ok = (l <= L && f <= F && b <= B && d <= D)
    printf "%s|%s|%.0f %% LUT, %.0f %% FF, %.0f %% BRAM, %.0f %% DSP\n", n, ok ? "yes" : "no", 100 * l / L, 100 * f / F, 100 * b / B, 100 * d / D }'
}
z020=$(fits XC7Z020 53200 106400 140 220)
a100=$(fits XC7A100T 63400 126800 135 240)
fit_json() { IFS='|' read -r n ok use <<<"$1"; printf '"%s": {"fits": %s, "use": "%s"}' "$n" "$([ "$ok" = yes ] && echo true || echo false)" "$use"; }

{
  printf '{"top": "%s", "dmax": %d, "par": %d, "family": "xc7", "lut": %d, "lut_logic": %d, "lut_memory": %d, ' \
    "$top" "$dmax" "$par" "$lut" "$lut_logic" "$lut_mem"
  printf '"ff": %d, "bram36_equivalent": %s, "ramb36e1": %d, "ramb18e1": %d, "dsp48e1": %d, "carry4": %d, ' \
    "$ff" "$bram" "$bram36" "$bram18" "$dsp" "$carry"
  printf '"yosys_seconds": %d, %s, %s}\n' "$secs" "$(fit_json "$z020")" "$(fit_json "$a100")"
} > "$out/summary.json"
{
  echo "# FPGA estimate (\`make fpga\`, $top, DMAX = $dmax, PAR = $par)"
  echo
  echo "Yosys \`synth_xilinx -family xc7\` ($secs s); no place and route, so no clock figure."
  echo
  echo "| resource | count |"
  echo "|---|---|"
  echo "| LUTs (logic + memory / shift registers) | $lut ($lut_logic + $lut_mem) |"
  echo "| flip-flops | $ff |"
  echo "| block RAM (36 Kb equivalents) | $bram ($bram36 RAMB36E1, $bram18 RAMB18E1) |"
  echo "| DSP48E1 | $dsp |"
  echo
  echo "| device | fits | use |"
  echo "|---|---|---|"
  for f in "$z020" "$a100"; do IFS='|' read -r n ok use <<<"$f"; echo "| $n | $ok | $use |"; done
} > "$out/report.md"
cat "$out/report.md"
echo "fpga: summary $out/summary.json"
