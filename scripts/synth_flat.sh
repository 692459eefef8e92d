#!/usr/bin/env bash
# make synth FLAT=1: the whole engine flattened in ONE Yosys run (the flow before
# the hierarchical scripts/synth.sh; 40 min and 13.5 GB at DMAX = 64), OSU 0.18 um
# standard cells, on-chip memories kept out of the gate count as black-box macros,
# timing by OpenSTA against constraints/mcadsw.sdc; report next to the paper's Table III.
# Called by scripts/synth.sh when FLAT=1 (which checks DMAX and the tools first).
#
#   FLAT=1 scripts/synth.sh           full configuration (DMAX = 64)
#   FLAT=1 DMAX=16 scripts/synth.sh   reduced configuration
#   OUT=dir                       output directory (default build/synth, or
#                                 build/synth_dmax<N> for a reduced DMAX)
#   SKIP_YOSYS=1                  reuse the netlist of an earlier run: STA and report only
#
# Outputs: yosys.log, memories.txt, area.txt, mcadsw_top_osu018.v, sta.log,
# report.md, summary.json.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dmax=${DMAX:-64}
if [ "$dmax" = 64 ]; then out=${OUT:-$root/build/synth}; else out=${OUT:-$root/build/synth_dmax$dmax}; fi
lib=${LIBERTY:-/usr/share/qflow/tech/osu018/osu018_stdcells.lib}
sdc=$root/constraints/mcadsw.sdc
for tool in yosys sta awk; do
  command -v "$tool" >/dev/null || { echo "synth: '$tool' not found (run scripts/bootstrap.sh)" >&2; exit 2; }
done
[ -f "$lib" ] || { echo "synth: liberty $lib not found (apt install qflow-tech-osu018)" >&2; exit 2; }
mkdir -p "$out"
# No result of an earlier run may pass for this one's (the netlist stays for SKIP_YOSYS=1).
rm -f "$out/summary.json" "$out/report.md"
[ "${SKIP_YOSYS:-0}" = 1 ] || rm -f "$out/mcadsw_top_osu018.v"

period_ns=$(awk '/^set period/ {print $3}' "$sdc")
period_ps=$(awk -v p="$period_ns" 'BEGIN {printf "%d", p * 1000}')
nand2_area=$(awk '/cell *\(NAND2X1\)/ {c=1} c && /area/ {gsub(/[^0-9.]/, "", $0); print; exit}' "$lib")

cd "$root/rtl"
mods=$(ls mcadsw_*.sv | grep -v '^mcadsw_pkg.sv$' | sort | tr '\n' ' ')
start=$(date +%s)
echo "synth: flat Yosys run, DMAX=$dmax, clock ${period_ns} ns, liberty $(basename "$lib") (log: $out/yosys.log)"
cat > "$out/synth.ys" <<YS
read_verilog -sv mcadsw_pkg.sv $mods
read_verilog -lib $root/sim/gls/mcadsw_ram_model.v
chparam -set DMAX $dmax mcadsw_top
hierarchy -check -top mcadsw_top
rename -top mcadsw_top
# One module per paper block (Fig. 16); their sub-modules are flattened into them.
setattr -mod -set keep_hierarchy 1 *mcadsw_census* mcadsw_weight_gen mcadsw_cost_agg *mcadsw_mem_ctrl* *mcadsw_win_reader* *mcadsw_scheduler* *mcadsw_depth_fifo*
synth -run :fine
flatten
# Memories: listed, then replaced by black-box macros.
tee -q -o $out/memories_list.txt select -list t:\$mem_v2
tee -q -o $out/memories_dump.txt dump t:\$mem_v2
techmap -map $root/constraints/macro_map.v t:\$mem_v2
synth -run fine:
dfflibmap -liberty $lib
# -constr (constraints/abc_osu018.constr): ABC models flip-flop outputs and inputs
# as driven by an INVX1, so it builds buffer trees on high-fanout nets; with ideal
# drivers it left a 3000-load select net unbuffered (119 ns slew in OpenSTA).
abc -D $period_ps -constr $root/constraints/abc_osu018.constr -liberty $lib -script $root/constraints/abc_osu018.script
setundef -zero
opt_clean -purge
tee -q -o $out/area.txt stat -liberty $lib
write_verilog -noattr -noexpr -nohex -nodec $out/mcadsw_top_osu018.v
YS
if [ "${SKIP_YOSYS:-0}" = 1 ] && [ -f "$out/mcadsw_top_osu018.v" ]; then
  echo "synth: SKIP_YOSYS=1, reusing $out/mcadsw_top_osu018.v"
else
/usr/bin/time -v yosys -q -l "$out/yosys.log" "$out/synth.ys" 2> "$out/yosys_time.txt" >/dev/null || {
  tail -20 "$out/yosys.log"; echo "synth: yosys failed" >&2; exit 1; }
yosys_s=$(( $(date +%s) - start ))
yosys_mb=$(awk '/Maximum resident/ {printf "%d", $NF / 1024}' "$out/yosys_time.txt")
echo "synth: Yosys done in ${yosys_s} s, peak ${yosys_mb} MB"
echo "$yosys_s $yosys_mb" > "$out/yosys_cost.txt"
fi
read -r yosys_s yosys_mb < "$out/yosys_cost.txt"

# The macros model what the engine's memories use; anything else stops here:
# synchronous read resets, read-port initial values, transparent reads.
if grep -Eq "connect .RD_SRST [^1]*[^']1|connect .RD_SRST .[a-zA-Z]" "$out/memories_dump.txt" ||
   grep -Eq "parameter .RD_TRANSPARENCY_MASK [0-9]+'[01]*1" "$out/memories_dump.txt"; then
  echo "synth: a memory uses a synchronous read reset or a transparent read; MCADSW_RAM does not model it" >&2
  exit 1
fi

# ---- OpenSTA -------------------------------------------------------------------------
"$root/scripts/sta_netlist.sh" "$out/mcadsw_top_osu018.v" "$out" "$lib"
cat > "$out/sta.tcl" <<TCL
set lib $lib
set out $out
set sdc $sdc
source $root/constraints/sta_reports.tcl
TCL
echo "synth: OpenSTA (log: $out/sta.log)"
sta -no_splash -exit "$out/sta.tcl" > "$out/sta.log" 2>&1 || { tail -20 "$out/sta.log"; echo "synth: sta failed" >&2; exit 1; }
# wns: worst negative slack (0 when every path meets the clock); slack: the
# worst path's slack, negative or positive, which sets the achievable clock.
wns=$(awk '/^wns/ {print $2}' "$out/sta.log")
slack=$(awk '/^worst slack/ {print $3}' "$out/sta.log")
[ -n "$wns" ] && [ -n "$slack" ] || { tail -20 "$out/sta.log"; echo "synth: no wns / worst slack in the OpenSTA log" >&2; exit 1; }
crit_start=$(awk '/^Startpoint:/ {sub(/^Startpoint: /, ""); print; exit}' "$out/sta.log")
crit_end=$(awk '/^Endpoint:/ {sub(/^Endpoint: /, ""); print; exit}' "$out/sta.log")
crit_arrival=$(awk '/data arrival time/ {print $1; exit}' "$out/sta.log")

# Violating endpoints per block (the instance path's first component).
awk '/VIOLATED/ { e = $1; b = e; sub(/\..*/, "", b); sub(/\[.*/, "", b); if (b ~ /^_/) b = "top"
                  n[b]++; if (!(b in w) || $(NF - 1) < w[b]) w[b] = $(NF - 1) }
     END { for (b in n) printf "%s %d %s\n", b, n[b], w[b] }' "$out/sta_endpoints.log" |
  sort -k3 -g > "$out/sta_blocks.txt"

# ---- Figures -------------------------------------------------------------------------
# Area per block from `stat -liberty` (each kept module's own cells; sub-modules
# were flattened into their block).
awk -v nand2="$nand2_area" -v dmax="$dmax" '
  function bin2dec(b,   i, v) { v = 0; for (i = 1; i <= length(b); i++) v = v * 2 + substr(b, i, 1); return v }
  /^=== / { mod = $2; next }
  /Chip area for module/ {
    a = $NF; name = mod
    if (name ~ /mcadsw_census/) {
      match(name, /COLS=s32.[01]+/); cols = bin2dec(substr(name, RSTART + 9, RLENGTH - 9))
      blk = (cols == 48) ? "census_left" : "census_right"
    } else if (name ~ /mcadsw_weight_gen/) blk = "weight_generator"
    else if (name ~ /mcadsw_cost_agg/) blk = "cost_aggregator_wta"
    else if (name ~ /mcadsw_mem_ctrl|mcadsw_win_reader/) blk = "memory_controller"
    else if (name ~ /mcadsw_scheduler/) blk = "block_scheduler"
    else if (name ~ /mcadsw_depth_fifo/) blk = "depth_fifo"
    else if (name ~ /mcadsw_top/) blk = "top_registers_counters"
    else blk = "other"
    area[blk] += a
  }
  END { for (b in area) printf "%s %d\n", b, area[b] / nand2 + 0.5 }
' "$out/area.txt" | sort > "$out/blocks.txt"
nand2_total=$(awk '{s += $2} END {print s}' "$out/blocks.txt")

# Memories: module/cell from `select -list`, WIDTH x SIZE from `dump` (same order).
awk '
  FNR == NR { if ($0 ~ /\//) { n++; split($0, p, "/"); mod[n] = p[1]; cell[n] = p[2] } next }
  /cell \$mem_v2/ { m++; name = $3; sub(/^\\/, "", name) }
  /parameter .WIDTH / { w[m] = $3 }
  /parameter .SIZE / { s[m] = $3 }
  END {
    if (m != n) { print "count mismatch " m " " n > "/dev/stderr"; exit 1 }
    for (i = 1; i <= m; i++) printf "%s %s %d %d %d\n", mod[i], cell[i], w[i], s[i], w[i] * s[i]
  }' "$out/memories_list.txt" "$out/memories_dump.txt" > "$out/memories.txt"
mem_bits=$(awk '{s += $5} END {print s + 0}' "$out/memories.txt")
mem_count=$(wc -l < "$out/memories.txt")
mem_kb=$(awk -v b="$mem_bits" 'BEGIN {printf "%.1f", b / 8 / 1024}')
fmax=$(awk -v p="$period_ns" -v w="$slack" 'BEGIN {printf "%.1f", 1000 / (p - w)}')
# Flip-flops of the whole design: the "design hierarchy" totals only (the
# per-module sections before it count the same cells again).
ff_count=$(awk '/^=== design hierarchy ===/ {h = 1} h && /DFFPOSX1|DFFNEGX1|DFFSR/ && NF == 2 {s += $2} END {print s + 0}' "$out/area.txt")

# ---- Report --------------------------------------------------------------------------
sim_json=$root/build/sim/summary.json
cif_cycles=""
if [ -f "$sim_json" ]; then
  cif_cycles=$(tr '{' '\n' < "$sim_json" | awk -F'"cycles": *' '/"case": *"cif_teddy"/ {split($2, a, ","); print a[1]}')
fi
{
  echo "# Synthesis report (\`make synth FLAT=1\`, DMAX = $dmax)"
  echo
  echo "Yosys 0.23 to OSU 0.18 um standard cells (\`$(basename "$lib")\`), abc with buffering"
  echo "(\`constraints/abc_osu018.script\`), OpenSTA against \`constraints/mcadsw.sdc\`. On-chip memories"
  echo "are black-box macros (\`MCADSW_RAM\`, ports from \`sim/gls/mcadsw_ram_model.v\`), counted apart as the paper does."
  echo "Flattened flow (\`FLAT=1\`): one Yosys run of ${yosys_s} s with a peak of ${yosys_mb} MB."
  echo
  echo "| figure | this engine | paper (Table III, UMC 90 nm) |"
  echo "|---|---|---|"
  echo "| gates (NAND2 equivalents, memories excluded) | $nand2_total | 563k |"
  echo "| on-chip memory | $mem_bits bits = $mem_kb kB in $mem_count macros | 21.3 kB |"
  echo "| flip-flops (in the gate count) | $ff_count | |"
  echo "| clock target | $(awk -v p="$period_ns" 'BEGIN {printf "%.1f", 1000 / p}') MHz | 95 MHz |"
  echo "| worst slack (WNS) | $slack ns ($wns ns) | |"
  echo "| achievable clock (1 / (period - slack)) | $fmax MHz | 95 MHz |"
  if [ -n "$cif_cycles" ] && [ "$dmax" = 64 ]; then
    echo "| CIF frame at D = 64 (\`make sim\`) | $cif_cycles cycles = $(awk -v c="$cif_cycles" -v f="$fmax" 'BEGIN {printf "%.1f", f * 1e6 / c}') fps at $fmax MHz, $(awk -v c="$cif_cycles" 'BEGIN {printf "%.1f", 95e6 / c}') fps at 95 MHz | 42 fps at 95 MHz |"
  fi
  echo
  echo "Critical path: from \`$crit_start\` to \`$crit_end\`, arrival $crit_arrival ns"
  echo "(full path in \`sta.log\`). Paths into and out of the memory macros are timed with the"
  echo "assumed macro timing of \`constraints/mcadsw_ram_timing.cfg\` (OSU 0.18 um has no memory compiler):"
  echo "$(awk '/^clk_to_q/ {printf "clocked read %s ns after the clock", $2} /^async_access/ {printf ", asynchronous read %s ns", $2} /^setup/ {printf ", setup %s ns", $2}' "$root/constraints/mcadsw_ram_timing.cfg")."
  echo
  if [ -s "$out/sta_blocks.txt" ]; then
    echo "Endpoints that miss the clock, per block (\`sta_endpoints.log\`; what would close the"
    echo "gap: docs/architecture.md section 10):"
    echo
    echo "| block | violating endpoints | worst slack (ns) |"
    echo "|---|---|---|"
    awk '{printf "| %s | %d | %s |\n", $1, $2, $3}' "$out/sta_blocks.txt"
  else
    echo "Every endpoint meets the clock."
  fi
  echo
  echo "Memory per module (bits):"
  echo
  echo "| module | bits | kB |"
  echo "|---|---|---|"
  awk '{m = $1; sub(/^\$paramod[^\\]*\\/, "", m); sub(/\\.*/, "", m); b[m] += $5}
       END {for (k in b) printf "%s %d\n", k, b[k]}' "$out/memories.txt" | sort -k2 -n -r |
    awk '{printf "| %s | %d | %.1f |\n", $1, $2, $2 / 8192}'
  echo
  if awk -v k="$mem_kb" 'BEGIN {exit !(k > 21.3)}'; then
    echo "The memory exceeds the paper's 21.3 kB: the weight generator's weight buffers hold the"
    echo "weights of a whole block, double-banked, and the census buffers are double-banked; what"
    echo "would close the gap (next-row weights, census buffers refilled row by row):"
    echo "docs/architecture.md section 10."
    echo
  fi
  echo "## Gates per block (Fig. 16)"
  echo
  echo "| block | NAND2 eq | share |"
  echo "|---|---|---|"
  sort -k2 -n -r "$out/blocks.txt" | awk -v t="$nand2_total" '{printf "| %s | %d | %.1f %% |\n", $1, $2, 100 * $2 / t}'
  echo
  echo "## Memories (black-box macros)"
  echo
  echo "| module | memory | width | words | bits |"
  echo "|---|---|---|---|---|"
  awk '{m = $1; sub(/^\$paramod[^\\]*\\/, "", m); printf "| %s | %s | %d | %d | %d |\n", m, $2, $3, $4, $5}' "$out/memories.txt"
} > "$out/report.md"

{
  printf '{"dmax": %d, "flow": "flat", "nand2_eq": %d, "memory_bits": %d, "memory_kB": %s, "wns_ns": %s, "worst_slack_ns": %s, "fmax_mhz": %s, ' \
    "$dmax" "$nand2_total" "$mem_bits" "$mem_kb" "$wns" "$slack" "$fmax"
  printf '"yosys_seconds": %d, "yosys_peak_MB": %d, "per_block": {' "$yosys_s" "$yosys_mb"
  awk 'NR > 1 {printf ", "} {printf "\"%s\": %d", $1, $2}' "$out/blocks.txt"
  printf '}}\n'
} > "$out/summary.json.tmp"
mv "$out/summary.json.tmp" "$out/summary.json"

echo "synth: $nand2_total NAND2 eq (paper 563k), memory $mem_kb kB in $mem_count macros (paper 21.3 kB),"
echo "       worst slack $slack ns (WNS $wns ns) at $(awk -v p="$period_ns" 'BEGIN {printf "%.1f", 1000 / p}') MHz, achievable $fmax MHz (paper 95 MHz)"
echo "synth: report $out/report.md, summary $out/summary.json"
