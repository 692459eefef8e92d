#!/usr/bin/env bash
# make synth: the engine through Yosys 0.23 to OSU 0.18 um standard cells, block
# by block, on-chip memories kept out of the gate count as black-box macros
# (MCADSW_RAM), timing by OpenSTA against constraints/mcadsw.sdc on the assembled
# netlist; report next to the paper's Table III and Fig. 16.
#
#   scripts/synth.sh              full configuration (DMAX = 64)
#   DMAX=16 scripts/synth.sh      reduced configuration (build/synth_dmax16)
#   PAR=2 scripts/synth.sh        2 disparities a step (1, 2, 4; issue 18), in
#                                 build/synth_dmax<N>_par<P>
#   OUT=dir                       output directory (default build/synth, or
#                                 build/synth_dmax<N> for another DMAX)
#   SYNTH_JOBS=n                  Yosys processes at a time (default 2)
#   SYNTH_MEM_MB=n                expected peak of the blocks running together (default 7500)
#   RTL_DIR=dir, YOSYS=binary     other sources / Yosys executable (tests/synth/bad_input.sh)
#
# Flow: (1) one cheap Yosys run elaborates the design with chparam DMAX
# (hierarchy -check -top mcadsw_engine) and writes it as RTLIL; scripts/synth_elab.awk
# lists the blocks (each distinct module the top instantiates, i.e. each
# parameterisation) and renames them mcadsw_<instance>; (2) scripts/synth_block.sh
# synthesises each block with its sub-modules flattened into it, and the top's own
# logic with the blocks as black boxes, two Yosys processes at a time, longest first;
# a block whose stamp (a hash of its source files, the package, its parameters,
# the flow files and the Yosys version) is unchanged is not synthesised again;
# (3) the block netlists are concatenated into mcadsw_engine_osu018.v (the netlist
# scripts/gls.sh simulates); (4) scripts/sta_netlist.sh and OpenSTA time it;
# (5) report.md and summary.json, written last (deleted at the start).
#
# Outputs in OUT: elab.log, blocks/<block>/{yosys.log,netlist.v,area.txt,memories.txt,registers.txt,stamp},
# blocks.txt, memories.txt, registers.txt, mcadsw_engine_osu018.v, sta.log, sta_endpoints.log,
# report.md, summary.json.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
t_start=$(date +%s)
die() { echo "synth: $*" >&2; exit 2; }

rtl=${RTL_DIR:-$root/rtl}
rtl=$(cd "$rtl" 2>/dev/null && pwd) || die "RTL directory '${RTL_DIR:-$root/rtl}' not found"
[ -f "$rtl/mcadsw_pkg.sv" ] || die "no mcadsw_pkg.sv in $rtl"

# ---- Configuration checks (before anything is written) ----------------------------------
# DMAX: the top's disparity range. The cost aggregator, the disparity width
# (DISP_BITS) and the census read column are sized for the package's DMAX, so the
# top supports 1 .. mcadsw_pkg::DMAX (64) with the package as it is; a DMAX up
# to 128 is synthesised from a copy of the RTL whose package has that DMAX and
# its DISP_BITS (as a CMake build with MCADSW_DMAX makes it, CMakeLists.txt).
pkg_dmax=$(awk '/localparam int DMAX / {v = $5; gsub(/[^0-9]/, "", v); print v}' "$rtl/mcadsw_pkg.sv")
[[ "$pkg_dmax" =~ ^[0-9]+$ ]] || die "cannot read DMAX from $rtl/mcadsw_pkg.sv"
dmax=${DMAX:-64}
par=${PAR:-1}
dmax_ok=0
dmax_limit=$(( pkg_dmax > 128 ? pkg_dmax : 128 ))
if [[ "$dmax" =~ ^[0-9]{1,6}$ ]] && [ "$((10#$dmax))" -ge 1 ] && [ "$((10#$dmax))" -le "$dmax_limit" ]; then
  dmax=$((10#$dmax)); dmax_ok=1
fi
# No result of an earlier run may pass for this one's: summary, report and
# assembled netlist go first (in OUT, or the default directory of a valid DMAX)
# and are written again only when everything succeeded.
out=""
if [ -n "${OUT:-}" ]; then out=$OUT
elif [ "$dmax_ok" = 1 ]; then
  if [ "$par" != 1 ] && [[ "$par" =~ ^[124]$ ]]; then out=$root/build/synth_dmax${dmax}_par$par
  elif [ "$dmax" = 64 ]; then out=$root/build/synth; else out=$root/build/synth_dmax$dmax; fi
fi
if [ -n "$out" ] && [ -d "$out" ]; then
  rm -f "$out/summary.json" "$out/report.md" "$out/mcadsw_engine_osu018.v" "$out/mcadsw_engine_sta.v" \
        "$out/sta.log" "$out/sta_endpoints.log"
fi
[ "$dmax_ok" = 1 ] ||
  die "DMAX='$dmax' is not supported: an integer from 1 to $dmax_limit (up to mcadsw_pkg::DMAX = $pkg_dmax with the package as it is, above it from a package made for that DMAX)"
# PAR, the disparities a step: a parameter of the top (chparam), DMAX a multiple of it.
[[ "$par" =~ ^[124]$ ]] || die "PAR='$par' is not supported: 1, 2 or 4"
[ $((dmax % par)) -eq 0 ] || die "DMAX=$dmax is not a multiple of PAR=$par"
jobs=${SYNTH_JOBS:-2}
[[ "$jobs" =~ ^[1-9][0-9]*$ ]] || die "SYNTH_JOBS='$jobs' is not a positive integer"
mem_budget=${SYNTH_MEM_MB:-7500}
[[ "$mem_budget" =~ ^[0-9]+$ ]] || die "SYNTH_MEM_MB='$mem_budget' is not a number of MB"
lib=${LIBERTY:-/usr/share/qflow/tech/osu018/osu018_stdcells.lib}
yosys_bin=${YOSYS:-yosys}
for tool in "$yosys_bin" sta awk sha256sum; do
  command -v "$tool" >/dev/null || die "'$tool' not found in PATH (run scripts/bootstrap.sh, or make synth, which runs it)"
done
[ -f "$lib" ] || die "liberty $lib not found (apt install qflow-tech-osu018)"

mkdir -p "$out/blocks"
out=$(cd "$out" && pwd)

# Above the package's DMAX: the RTL with a package for this DMAX.
if [ "$dmax" -gt "$pkg_dmax" ]; then
  stage=$out/rtl
  rm -rf "$stage"; mkdir -p "$stage"
  cp $("$root/scripts/rtl_files.sh" "$rtl") "$stage"/
  "$root/scripts/rtl_pkg_dmax.sh" "$dmax" "$rtl/mcadsw_pkg.sv" "$stage/mcadsw_pkg.sv" ||
    die "could not make the package for DMAX = $dmax"
  echo "synth: DMAX = $dmax above the package's $pkg_dmax: RTL with a package for it in $stage"
  rtl=$stage
fi

sdc=$root/constraints/mcadsw.sdc
period_ns=$(awk '/^set period/ {print $3}' "$sdc")
period_ps=$(awk -v p="$period_ns" 'BEGIN {printf "%d", p * 1000}')
clock_mhz=$(awk -v p="$period_ns" 'BEGIN {printf "%.1f", 1000 / p}')
nand2_area=$(awk '/cell *\(NAND2X1\)/ {c=1} c && /area/ {gsub(/[^0-9.]/, "", $0); print; exit}' "$lib")
have_time=0; [ -x /usr/bin/time ] && have_time=1
timed() {   # timed FILE cmd...: run cmd, its peak memory in FILE (GNU time) when available
  local f=$1; shift
  if [ "$have_time" = 1 ]; then /usr/bin/time -v -o "$f" "$@"; else : > "$f"; "$@"; fi
}
peak_mb() { awk '/Maximum resident/ {printf "%d", $NF / 1024; f = 1} END {if (!f) print 0}' "$1" 2>/dev/null || echo 0; }

# ---- Memory of everything this run starts, sampled every second ------------------------
sampler_pid=""
mem_sampler() {
  local max=0 cur
  while :; do
    cur=$(ps -eo pid=,ppid=,rss= 2>/dev/null | awk -v root="$$" '
      { par[$1] = $2; rss[$1] = $3 }
      END { for (p in par) { q = p; for (i = 0; i < 64 && q > 1; i++) { if (q == root) { s += rss[p]; break } q = par[q] } }
            printf "%d", s / 1024 }')
    if [ "${cur:-0}" -gt "$max" ]; then max=$cur; echo "$max" > "$out/mem_peak_sum.txt"; fi
    sleep 1
  done
}
declare -A running=()   # pid (= process group) of a running block -> label
cleanup() {
  local p
  for p in "${!running[@]}"; do kill -TERM -- "-$p" "$p" 2>/dev/null || true; done
  [ -n "$sampler_pid" ] && kill "$sampler_pid" 2>/dev/null || true
  return 0
}
trap cleanup EXIT
trap 'exit 130' INT TERM
echo 0 > "$out/mem_peak_sum.txt"
mem_sampler &
sampler_pid=$!

# ---- (1) Elaboration ----------------------------------------------------------------------
cd "$rtl"
mods=$("$root/scripts/rtl_files.sh" --no-pkg . | sed 's|^\./||' | tr '\n' ' ')
cat > "$out/elab.ys" <<YS
read_verilog -sv mcadsw_pkg.sv $mods
read_verilog -lib $root/sim/gls/mcadsw_ram_model.v
chparam -set DMAX $dmax mcadsw_engine
chparam -set PAR $par mcadsw_engine
hierarchy -check -top mcadsw_engine
write_rtlil $out/elab_raw.il
YS
echo "synth: DMAX=$dmax, PAR=$par, clock ${period_ns} ns, liberty $(basename "$lib"); elaborating (log: $out/elab.log)"
if ! timed "$out/elab_time.txt" "$yosys_bin" -q -l "$out/elab.log" "$out/elab.ys" > /dev/null 2> "$out/elab.err"; then
  { tail -8 "$out/elab.log" 2>/dev/null || cat "$out/elab.err"; } | sed 's/^/  | /' >&2
  err=$(grep -h -m1 "ERROR" "$out/elab.log" "$out/elab.err" 2>/dev/null | awk 'NR == 1' || true)
  # The block(s) of the failing file, from the last successful elaboration's list.
  efile=$(echo "$err" | grep -o '^[A-Za-z0-9_./-]*\.sv' || true)
  eblocks=""
  if [ -n "$efile" ] && [ -f "$out/blocks.txt" ]; then
    eblocks=$(awk -v f="$(basename "$efile")" '{n = split($5, a, ","); for (i = 1; i <= n; i++) if (a[i] == f) print $1}' "$out/blocks.txt" | tr '\n' ' ' | sed 's/ $//')
  fi
  echo "synth: elaboration of mcadsw_engine failed${eblocks:+ in block $eblocks}: ${err:-see the log} (DMAX=$dmax, PAR=$par, sources $rtl; log: $out/elab.log)" >&2
  exit 1
fi
rm -f "$out"/blocks/*.sig "$out/blocks.txt"
awk -v dir="$out/blocks" -f "$root/scripts/synth_elab.awk" "$out/elab_raw.il" "$out/elab_raw.il" > "$out/elab.il" || {
  echo "synth: could not list the blocks of the elaborated design ($out/elab_raw.il)" >&2; exit 1; }
rm -f "$out/elab_raw.il"
mv "$out/blocks/blocks.txt" "$out/blocks.txt"
nblocks=$(wc -l < "$out/blocks.txt")
block_modules=$(awk '$1 != "top" {print $2}' "$out/blocks.txt" | tr '\n' ' ')

# ---- (2) Blocks -----------------------------------------------------------------------------
# Stamp: everything a block's netlist depends on. Sources: the files of the
# block's module and sub-modules (src attributes of the elaborated design) and
# the package; parameters and module names: <block>.sig (for the top also the
# ports of the blocks it instantiates); flow: the block script, the files it
# reads (macro map, ABC script and constraints, the SDC's clock period, liberty,
# macro ports) and the Yosys version.
flow_files=("$root/scripts/synth_block.sh" "$root/scripts/synth_elab.awk" "$root/constraints/macro_map.v"
            "$root/constraints/abc_osu018.constr" "$root/constraints/abc_osu018.script" "$sdc"
            "$lib" "$root/sim/gls/mcadsw_ram_model.v")
yosys_version=$("$yosys_bin" -V 2>&1 | awk 'NR == 1')
stamp_of() {   # label files
  local label=$1 files=$2 f
  {
    echo "yosys: $yosys_version; period_ps $period_ps"
    cat "$out/blocks/$label.sig"
    for f in $(echo "$files" | tr ',' '\n' | sort -u) mcadsw_pkg.sv; do
      [ "$f" = "-" ] && continue
      echo "== $f"; cat "$rtl/$f" 2>/dev/null || echo "(missing)"
    done
    for f in "${flow_files[@]}"; do echo "== $(basename "$f")"; cat "$f" 2>/dev/null || echo "(missing)"; done
  } | sha256sum | cut -d' ' -f1
}

declare -A b_module=() b_stamp=() b_est_s=() b_est_mb=() is_cached=()
queue=()
cached=()
while read -r label module inst base files weight; do
  b_module[$label]=$module
  s=$(stamp_of "$label" "$files")
  b_stamp[$label]=$s
  d=$out/blocks/$label
  if [ -f "$d/stamp" ] && [ "$(cat "$d/stamp")" = "$s" ] && [ -s "$d/netlist.v" ] && [ -f "$d/area.txt" ]; then
    cached+=("$label"); is_cached[$label]=1
  else
    rm -f "$d/stamp"
    # Estimates for the schedule: the last run's time and peak when known,
    # else the block's size in the elaborated RTLIL (sub-modules included).
    if [ -s "$d/cost.txt" ]; then read -r b_est_s[$label] b_est_mb[$label] < "$d/cost.txt"
    else b_est_s[$label]=$(( weight / 1000 )); b_est_mb[$label]=0; fi
    queue+=("$label")
  fi
done < "$out/blocks.txt"
# Longest first.
if [ ${#queue[@]} -gt 0 ]; then
  mapfile -t queue < <(for l in "${queue[@]}"; do echo "${b_est_s[$l]} $l"; done | sort -k1,1nr | awk '{print $2}')
fi
echo "synth: $nblocks blocks (the top's own logic included); ${#cached[@]} unchanged since their last synthesis${cached[*]:+ (${cached[*]})}, ${#queue[@]} to synthesise, $jobs at a time"

mem_avail_mb() { awk '/^MemAvailable:/ {printf "%d", $2 / 1024; f = 1} END {if (!f) print 1000000}' /proc/meminfo 2>/dev/null || echo 1000000; }
declare -A b_start=()
done_count=0
launch() {
  local label=$1 d=$out/blocks/$1 bb=()
  mkdir -p "$d"
  [ "$label" = top ] && read -r -a bb <<< "$block_modules"
  b_start[$label]=$(date +%s)
  # Own process group (setsid), so that a failure elsewhere stops the block's
  # Yosys and ABC processes by that group's id.
  setsid -w "$root/scripts/synth_block.sh" "${b_module[$label]}" "$out/elab.il" "$d" "$period_ps" "$lib" \
    "${bb[@]}" > "$d/run.log" 2>&1 &
  running[$!]=$label
  echo "synth:   $label (${b_module[$label]}) started"
}
stop_all() {
  local p
  for p in "${!running[@]}"; do kill -TERM -- "-$p" "$p" 2>/dev/null || true; done
  for p in "${!running[@]}"; do wait "$p" 2>/dev/null || true; unset "running[$p]"; done
}
# Start order: longest first, but a block starts only when the expected peaks of
# the running blocks and its own stay within SYNTH_MEM_MB (default 7500 MB) and
# its own (plus 512 MB) is free on the machine now; the first block always
# starts. Expected peak: the block's last run, else 3500 MB.
est_mb() { local e=${b_est_mb[$1]:-0}; [ "$e" -gt 0 ] && echo "$e" || echo 3500; }
pending=("${queue[@]}")
pick() {   # index in pending of the first block that fits now, or -1
  local i used=0 p e avail
  for p in "${!running[@]}"; do used=$(( used + $(est_mb "${running[$p]}") )); done
  avail=$(mem_avail_mb)
  for i in "${!pending[@]}"; do
    e=$(est_mb "${pending[$i]}")
    if [ ${#running[@]} -eq 0 ] || { [ $(( used + e )) -le "$mem_budget" ] && [ $(( e + 512 )) -le "$avail" ]; }; then
      echo "$i"; return
    fi
  done
  echo -1
}
while [ ${#pending[@]} -gt 0 ] || [ ${#running[@]} -gt 0 ]; do
  while [ ${#pending[@]} -gt 0 ] && [ ${#running[@]} -lt "$jobs" ]; do
    i=$(pick)
    [ "$i" -ge 0 ] || break
    launch "${pending[$i]}"
    unset "pending[$i]"; pending=("${pending[@]}")
  done
  finished=""
  rc=0
  wait -n -p finished "${!running[@]}" || rc=$?
  [ -n "$finished" ] || continue
  label=${running[$finished]}
  unset "running[$finished]"
  d=$out/blocks/$label
  if [ "$rc" -ne 0 ]; then
    stop_all
    echo "synth: block '$label' (module ${b_module[$label]}) failed (exit $rc); the end of its output ($d/run.log):" >&2
    tail -25 "$d/run.log" | sed 's/^/  | /' >&2
    echo "synth: stopped after block '$label' failed (Yosys log $d/yosys.log); no summary.json written" >&2
    exit 1
  fi
  echo "${b_stamp[$label]}" > "$d/stamp"
  done_count=$((done_count + 1))
  read -r s mb < "$d/cost.txt"
  nand=$(awk -v m="${b_module[$label]}" -v a="$nand2_area" '/Chip area for module/ {n = $5; gsub(/[^A-Za-z0-9_]/, "", n); if (n == m) printf "%d", $NF / a + 0.5}' "$d/area.txt")
  echo "synth:   $label done in ${s} s, peak ${mb} MB, ${nand} NAND2 eq [$done_count/${#queue[@]}]"
done
yosys_wall=$(( $(date +%s) - t_start ))

# ---- (3) Assembly -------------------------------------------------------------------------
# One file, the top first, then each block module once; MCADSW_RAM stays a black
# box (sim/gls/mcadsw_ram_model.v for simulation, a generated liberty for STA).
{
  echo "// mcadsw_engine, DMAX = $dmax, PAR = $par: OSU 0.18 um netlist assembled by scripts/synth.sh from the"
  echo "// block netlists in $out/blocks (each synthesised on its own)."
  cat "$out/blocks/top/netlist.v"
  awk '$1 != "top" {print $1}' "$out/blocks.txt" | while read -r label; do cat "$out/blocks/$label/netlist.v"; done
} > "$out/mcadsw_engine_osu018.v.tmp"
for m in mcadsw_engine $block_modules; do
  n=$(grep -c "^module $m(" "$out/mcadsw_engine_osu018.v.tmp" || true)
  [ "$n" = 1 ] || { echo "synth: assembly: module $m defined $n times in the assembled netlist" >&2; exit 1; }
done
mv "$out/mcadsw_engine_osu018.v.tmp" "$out/mcadsw_engine_osu018.v"

# ---- (4) OpenSTA --------------------------------------------------------------------------
echo "synth: OpenSTA on the assembled netlist (log: $out/sta.log)"
sta_start=$(date +%s)
timed "$out/sta_netlist_time.txt" "$root/scripts/sta_netlist.sh" "$out/mcadsw_engine_osu018.v" "$out" "$lib" > "$out/sta_netlist.out" 2>&1 || {
  tail -20 "$out/sta_netlist.out" | sed 's/^/  | /' >&2; echo "synth: preparing the STA netlist failed (log: $out/sta_netlist.log)" >&2; exit 1; }
cat > "$out/sta.tcl" <<TCL
set lib $lib
set out $out
set sdc $sdc
source $root/constraints/sta_reports.tcl
# Nets between blocks (pins in more than one block instance, the top's own cells
# counted as one): driver, its cell, pins, worst transition at the driver. Each
# block's ABC buffered what it saw (its inputs driven by an INVX1, its outputs
# loaded with 0.02 pF); this shows what the assembled netlist makes of it.
set f [open $out/sta_crossing.txt w]
foreach net [get_nets *] {
  set drv ""; set blocks {}; set pins [get_pins -of_objects \$net]
  foreach p \$pins {
    set name [get_full_name \$p]
    set b [expr {[string first . \$name] < 0 ? "top" : [lindex [split \$name .] 0]}]
    if {[lsearch -exact \$blocks \$b] < 0} { lappend blocks \$b }
    if {[get_property \$p direction] == "output"} { set drv \$p }
  }
  if {[llength \$blocks] > 1 && \$drv != ""} {
    set t [expr {max([get_property \$drv actual_rise_transition_max], [get_property \$drv actual_fall_transition_max])}]
    puts \$f "[get_full_name \$net] [get_full_name \$drv] [get_property [get_cells -of_objects \$drv] ref_name] [llength \$pins] \$t"
  }
}
close \$f
TCL
timed "$out/sta_time.txt" sta -no_splash -exit "$out/sta.tcl" > "$out/sta.log" 2>&1 || {
  tail -20 "$out/sta.log" | sed 's/^/  | /' >&2; echo "synth: sta failed (log: $out/sta.log)" >&2; exit 1; }
sta_s=$(( $(date +%s) - sta_start ))
# wns: worst negative slack (0 when every path meets the clock); slack: the
# worst path's slack, negative or positive, which sets the achievable clock.
wns=$(awk '/^wns/ {print $2}' "$out/sta.log")
slack=$(awk '/^worst slack/ {print $3}' "$out/sta.log")
[ -n "$wns" ] && [ -n "$slack" ] || { tail -20 "$out/sta.log" | sed 's/^/  | /' >&2; echo "synth: no wns / worst slack in the OpenSTA log" >&2; exit 1; }
crit_start=$(awk '/^Startpoint:/ {sub(/^Startpoint: /, ""); print; exit}' "$out/sta.log")
crit_end=$(awk '/^Endpoint:/ {sub(/^Endpoint: /, ""); print; exit}' "$out/sta.log")
crit_arrival=$(awk '/data arrival time/ {print $1; exit}' "$out/sta.log")
cross_n=$(wc -l < "$out/sta_crossing.txt")
cross_worst=$(sort -k5,5gr "$out/sta_crossing.txt" | awk 'NR == 1 {printf "%.3f", $5} END {if (NR == 0) print "0"}')
cross_slow=$(awk '$5 > 0.5' "$out/sta_crossing.txt" | wc -l)
# Violating endpoints per block instance (the instance path's first component).
awk '/VIOLATED/ { e = $1; b = e; sub(/\..*/, "", b); sub(/\[.*/, "", b); if (b ~ /^_/) b = "top"
                  n[b]++; if (!(b in w) || $(NF - 1) < w[b]) w[b] = $(NF - 1) }
     END { for (b in n) printf "%s %d %s\n", b, n[b], w[b] }' "$out/sta_endpoints.log" |
  sort -k3 -g > "$out/sta_blocks.txt"

# ---- (5) Figures ----------------------------------------------------------------------------
# Per block: NAND2 eq (the module's own `stat -liberty` area / NAND2X1 area),
# flip-flops, memory bits, Yosys time and peak; instances multiply a block's
# figures into the totals. Fig. 16 group of each block.
: > "$out/block_figures.txt"
: > "$out/memories.txt"
: > "$out/registers.txt"
while read -r label module inst base files weight; do
  d=$out/blocks/$label
  read -r s mb < "$d/cost.txt"
  awk -v m="$module" -v a="$nand2_area" -v label="$label" -v inst="$inst" -v base="$base" -v s="$s" -v mb="$mb" \
      -v mem="$(awk '{b += $5} END {print b + 0}' "$d/memories.txt")" \
      -v cached="${is_cached[$label]:-0}" '
    /^=== / { cur = $2; next }
    cur == m && $1 ~ /^DFF/ && NF == 2 { ff += $2 }
    /Chip area for module/ { n = $5; gsub(/[^A-Za-z0-9_]/, "", n); if (n == m) area = $NF }
    END {
      if (base == "mcadsw_census") grp = (inst > 1) ? "census_left_right" : (label ~ /_r$/) ? "census_right" : "census_left"
      else if (base == "mcadsw_weight_gen") grp = "weight_generator"
      else if (base == "mcadsw_cost_agg") grp = "cost_aggregator_wta"
      else if (base == "mcadsw_mem_ctrl" || base == "mcadsw_win_reader") grp = "memory_controller"
      else if (base == "mcadsw_scheduler") grp = "block_scheduler"
      else if (base == "mcadsw_depth_fifo") grp = "depth_fifo"
      else if (base == "mcadsw_post") grp = "post_stage"
      else if (base == "mcadsw_engine") grp = "top_registers_counters"
      else grp = "other"
      printf "%s %s %d %d %d %d %s %d %d %d\n", label, m, inst, area / a + 0.5, ff, mem, grp, s, mb, cached
    }' "$d/area.txt" >> "$out/block_figures.txt"
  for ((i = 0; i < inst; i++)); do
    awk -v m="$module" '{$1 = m; print}' "$d/memories.txt" >> "$out/memories.txt"
    [ ! -f "$d/registers.txt" ] || awk -v m="$module" '{$1 = m; print}' "$d/registers.txt" >> "$out/registers.txt"
  done
done < "$out/blocks.txt"
# block_figures.txt: label module instances nand2 ff mem_bits group seconds peak_MB cached
nand2_total=$(awk '{s += $3 * $4} END {print s + 0}' "$out/block_figures.txt")
ff_count=$(awk '{s += $3 * $5} END {print s + 0}' "$out/block_figures.txt")
# The SoC wrapper around the engine (mcadsw_top: AXI4-Lite registers, AXI4
# master), mapped and timed apart by scripts/synth_soc.sh (about 20 s).
"$root/scripts/synth_soc.sh" "$rtl" "$out/soc" "$lib" "$dmax" "$par" ||
  die "the SoC wrapper's synthesis failed (log: $out/soc/yosys.log)"
read -r soc_regs soc_master soc_slack < "$out/soc/nand2.txt"
soc_total=$(( nand2_total + soc_regs + soc_master ))
mem_bits=$(awk '{s += $5} END {print s + 0}' "$out/memories.txt")
mem_count=$(wc -l < "$out/memories.txt")
# memories.txt: module cell width words bits read_ports write_ports sync|async
async_count=$(awk '$8 != "sync"' "$out/memories.txt" | wc -l)
reg_bits=$(awk '{s += $3} END {print s + 0}' "$out/registers.txt")
reg_count=$(wc -l < "$out/registers.txt")
mem_kb=$(awk -v b="$mem_bits" 'BEGIN {printf "%.1f", b / 8 / 1024}')
# The LR mode's post stage (issue 17) is reported apart: the engine's figures
# (the budget's memory) are those without it.
post_nand2=$(awk '$7 == "post_stage" {s += $3 * $4} END {print s + 0}' "$out/block_figures.txt")
post_bits=$(awk '$7 == "post_stage" {s += $3 * $6} END {print s + 0}' "$out/block_figures.txt")
post_kb=$(awk -v b="$post_bits" 'BEGIN {printf "%.1f", b / 8 / 1024}')
eng_bits=$((mem_bits - post_bits))
eng_kb=$(awk -v b="$eng_bits" 'BEGIN {printf "%.1f", b / 8 / 1024}')
fmax=$(awk -v p="$period_ns" -v w="$slack" 'BEGIN {printf "%.1f", 1000 / (p - w)}')
awk '{n[$7] += $3 * $4; f[$7] += $3 * $5; m[$7] += $3 * $6} END {for (g in n) printf "%s %d %d %d\n", g, n[g], f[g], m[g]}' \
  "$out/block_figures.txt" | sort -k2,2nr > "$out/groups.txt"
# Yosys per block: the largest single process; all processes of the run together (sampled).
# Peak memory of this run's processes (reused blocks ran in an earlier run): the
# largest single process (GNU time), and all processes together (sampled).
yosys_peak=$(awk 'BEGIN {m = 0} $10 == 0 && $9 > m {m = $9; l = $1} END {print m + 0, (l == "" ? "-" : l)}' "$out/block_figures.txt")
read -r yosys_peak_mb yosys_peak_block <<< "$yosys_peak"
yosys_cpu_s=$(awk '$10 == 0 {s += $8} END {print s + 0}' "$out/block_figures.txt")
stanet_mb=$(peak_mb "$out/sta_netlist_time.txt")
sta_mb=$(peak_mb "$out/sta_time.txt")
elab_mb=$(peak_mb "$out/elab_time.txt")
read -r proc_peak_mb proc_peak_what < <(printf '%s %s\n' "$yosys_peak_mb" "Yosys_of_block_$yosys_peak_block" \
  "$stanet_mb" "Yosys_preparing_the_STA_netlist" "$sta_mb" "OpenSTA" "$elab_mb" "Yosys_elaboration" | sort -k1,1n | tail -1)
proc_peak_what=${proc_peak_what//_/ }
sum_peak_mb=$(cat "$out/mem_peak_sum.txt" 2>/dev/null || echo 0)
wall_s=$(( $(date +%s) - t_start ))

# ---- Report -------------------------------------------------------------------------------
sim_json=$root/build/sim/summary.json
cif_cycles=""
if [ -f "$sim_json" ]; then
  cif_cycles=$(tr '{' '\n' < "$sim_json" | awk -F'"cycles": *' '/"case": *"cif_teddy"/ {split($2, a, ","); print a[1]}')
fi
grp_name() {
  case $1 in
    census_left) echo "census left (transformer + buffer)" ;; census_right) echo "census right (transformer + buffer)" ;;
    census_left_right) echo "census left + right (one module at this DMAX)" ;;
    weight_generator) echo "weight generator (+ weight buffers)" ;; cost_aggregator_wta) echo "cost aggregator + WTA" ;;
    memory_controller) echo "memory controller + window readers" ;; block_scheduler) echo "block scheduler" ;;
    depth_fifo) echo "depth FIFO" ;; top_registers_counters) echo "top: configuration, checks, counters" ;;
    post_stage) echo "LR post stage (check, fill, median; beyond the paper)" ;; *) echo "$1" ;;
  esac
}
paper_share() {   # what the paper's text says of Fig. 16 (the figure's numbers are not in the text)
  case $1 in
    census_left|census_right|cost_aggregator_wta) echo "one of the three that dominate" ;;
    census_left_right) echo "two of the three that dominate" ;;
    *) echo "not given" ;;
  esac
}
{
  echo "# Synthesis report (\`make synth\`, DMAX = $dmax, PAR = $par, hierarchical)"
  echo
  echo "Yosys 0.23 to OSU 0.18 um standard cells (\`$(basename "$lib")\`), block by block: each block"
  echo "(each module parameterisation the top instantiates, sub-modules flattened into it) and the top's own"
  echo "logic (blocks as black boxes) in its own Yosys process, $jobs at a time; ABC with buffering"
  echo "(\`constraints/abc_osu018.script\`, \`-constr constraints/abc_osu018.constr\`) per block; the block"
  echo "netlists assembled into \`mcadsw_engine_osu018.v\`; OpenSTA on it against \`constraints/mcadsw.sdc\`."
  echo "On-chip memories are black-box macros (\`MCADSW_RAM\`, ports from \`sim/gls/mcadsw_ram_model.v\`),"
  echo "counted apart as the paper does."
  echo
  echo "Run: ${wall_s} s wall (blocks ${yosys_wall} s incl. elaboration, STA ${sta_s} s); ${#queue[@]} blocks synthesised"
  echo "(${yosys_cpu_s} s of Yosys in all), ${#cached[@]} unchanged and reused. Peak memory: ${proc_peak_mb} MB for the largest"
  echo "single process ($proc_peak_what; $([ ${#queue[@]} -gt 0 ] && echo "largest block run ${yosys_peak_mb} MB" || echo "no block run"), STA netlist preparation ${stanet_mb} MB,"
  echo "OpenSTA ${sta_mb} MB), ${sum_peak_mb} MB for all processes of the run together (sampled each second)."
  echo
  echo "| figure | this engine | paper (Table III, UMC 90 nm) |"
  echo "|---|---|---|"
  echo "| gates (NAND2 equivalents, memories excluded) | $nand2_total | 563k |"
  echo "| with the SoC wrapper (mcadsw_top: AXI4-Lite registers $soc_regs, AXI4 master $soc_master; each timed alone, worst slack $soc_slack ns) | $soc_total | |"
  echo "| on-chip memory | $mem_bits bits = $mem_kb kB in $mem_count macros | 21.3 kB |"
  echo "| of which the engine of the paper (without the LR post stage) | $eng_bits bits = $eng_kb kB | 21.3 kB |"
  echo "| LR post stage (issue 17, beyond the paper): gates, memory | $post_nand2 NAND2 eq, $post_bits bits = $post_kb kB | |"
  echo "| macros with an asynchronous read port | $async_count (every other read port: address registered, data the next cycle) | |"
  echo "| data registers of 64 bits or more (flip-flops, in the gate count) | $reg_bits bits in $reg_count registers (listed below) | |"
  echo "| flip-flops (in the gate count) | $ff_count | |"
  echo "| clock target | $clock_mhz MHz | 95 MHz |"
  echo "| worst slack (WNS) | $slack ns ($wns ns) | |"
  echo "| achievable clock (1 / (period - slack)) | $fmax MHz | 95 MHz |"
  if [ -n "$cif_cycles" ] && [ "$dmax" = 64 ] && [ "$par" = 1 ]; then
    echo "| CIF frame at D = 64 (\`make sim\`) | $cif_cycles cycles = $(awk -v c="$cif_cycles" -v f="$fmax" 'BEGIN {printf "%.1f", f * 1e6 / c}') fps at $fmax MHz, $(awk -v c="$cif_cycles" 'BEGIN {printf "%.1f", 95e6 / c}') fps at 95 MHz | 42 fps at 95 MHz |"
  fi
  echo
  echo "Critical path: from \`$crit_start\` to \`$crit_end\`, arrival $crit_arrival ns"
  echo "(full path in \`sta.log\`). Paths into and out of the memory macros are timed with the"
  echo "assumed macro timing of \`constraints/mcadsw_ram_timing.cfg\` (OSU 0.18 um has no memory compiler):"
  echo "$(awk '/^clk_to_q/ {printf "clocked read %s ns after the clock", $2} /^async_access/ {printf ", asynchronous read %s ns", $2} /^setup/ {printf ", setup %s ns", $2}' "$root/constraints/mcadsw_ram_timing.cfg")."
  echo
  echo "Nets between blocks (\`sta_crossing.txt\`: pins in more than one block instance): $cross_n; worst"
  echo "transition at their driver $cross_worst ns, $cross_slow above 0.5 ns. The slowest:"
  echo
  echo "| net | driver | cell | pins | transition (ns) |"
  echo "|---|---|---|---|---|"
  sort -k5,5gr "$out/sta_crossing.txt" | awk 'NR <= 5 {printf "| `%s` | `%s` | %s | %d | %.3f |\n", $1, $2, $3, $4, $5}'
  echo
  if [ -s "$out/sta_blocks.txt" ]; then
    echo "Endpoints that miss the clock, per block instance (\`sta_endpoints.log\`):"
    echo
    echo "| instance | violating endpoints | worst slack (ns) |"
    echo "|---|---|---|"
    awk '{printf "| %s | %d | %s |\n", $1, $2, $3}' "$out/sta_blocks.txt"
  else
    echo "Every endpoint meets the clock."
  fi
  echo
  echo "## Blocks"
  echo
  echo "Each line one Yosys run (\`blocks/<block>/\`); figures per instance."
  echo
  echo "| block | module | instances | NAND2 eq | share | flip-flops | memory bits | Yosys s | peak MB | this run |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
  sort -k4,4nr "$out/block_figures.txt" | awk -v t="$nand2_total" '{printf "| %s | %s | %d | %d | %.1f %% | %d | %d | %d | %d | %s |\n",
    $1, $2, $3, $4, 100 * $3 * $4 / t, $5, $6, $8, $9, $10 ? "reused" : "synthesised"}'
  echo
  echo "## Gates per paper block (Fig. 16)"
  echo
  echo "The paper's Fig. 16 gives the gate shares as a chart only; its text says: \"The total gate-count"
  echo "was dominated by the cost aggregator and WTA, census left buffer, and census right buffer. This was"
  echo "due to the high-computation resource requirement and complex demultiplexing circuits.\""
  echo
  echo "| paper block | NAND2 eq | share | flip-flops | memory bits | paper (Fig. 16, text) |"
  echo "|---|---|---|---|---|---|"
  while read -r g n f m; do
    echo "| $(grp_name "$g") | $n | $(awk -v n="$n" -v t="$nand2_total" 'BEGIN {printf "%.1f %%", 100 * n / t}') | $f | $m | $(paper_share "$g") |"
  done < "$out/groups.txt"
  top3=$(head -3 "$out/groups.txt" | awk '{print $1}' | sort | tr '\n' ' ')
  if [ "$top3" = "census_left census_right cost_aggregator_wta " ]; then
    echo
    echo "As in the paper, the cost aggregator + WTA and the two census blocks are the three largest."
  fi
  echo
  echo "Memory per module (bits):"
  echo
  echo "| module | bits | kB |"
  echo "|---|---|---|"
  awk '{b[$1] += $5} END {for (k in b) printf "%s %d\n", k, b[k]}' "$out/memories.txt" | sort -k2 -n -r |
    awk '{printf "| %s | %d | %.1f |\n", $1, $2, $2 / 8192}'
  echo
  if awk -v k="$eng_kb" 'BEGIN {exit !(k > 21.3)}'; then
    echo "The memory exceeds the paper's 21.3 kB; where it stands and what would close the gap:"
    echo "docs/architecture.md sections 7.1 and 10."
    echo
  fi
  echo "## Memories (black-box macros)"
  echo
  echo "| module | memory | width | words | bits | read ports | write ports | read |"
  echo "|---|---|---|---|---|---|---|---|"
  awk '{printf "| %s | %s | %d | %d | %d | %s | %s | %s |\n", $1, $2, $3, $4, $5, $6, $7, $8}' "$out/memories.txt"
  echo
  echo "## Data registers (flip-flops of 64 bits or more)"
  echo
  echo "Registers that hold image, census, weight or cost words in flip-flops rather than in a macro:"
  echo "pipeline registers, staging registers and the buffers kept in flip-flops (docs/architecture.md"
  echo "section 7). Their bits are in the gate count, not in the memory figure."
  echo
  echo "| module | register | bits |"
  echo "|---|---|---|"
  sort -k3,3nr "$out/registers.txt" | awk '{printf "| %s | %s | %d |\n", $1, $2, $3}'
} > "$out/report.md.tmp"

{
  printf '{"dmax": %d, "par": %d, "flow": "hierarchical", "nand2_eq": %d, "memory_bits": %d, "memory_kB": %s, "memory_macros": %d, ' \
    "$dmax" "$par" "$nand2_total" "$mem_bits" "$mem_kb" "$mem_count"
  printf '"soc_regs_nand2_eq": %d, "soc_axi_master_nand2_eq": %d, "soc_total_nand2_eq": %d, "soc_worst_slack_ns": %s, ' \
    "$soc_regs" "$soc_master" "$soc_total" "$soc_slack"
  printf '"memory_kB_engine": %s, "post_stage_nand2_eq": %d, "post_stage_memory_bits": %d, "post_stage_memory_kB": %s, ' \
    "$eng_kb" "$post_nand2" "$post_bits" "$post_kb"
  printf '"async_read_macros": %d, "data_register_bits": %d, ' "$async_count" "$reg_bits"
  printf '"flip_flops": %d, "clock_mhz": %s, "wns_ns": %s, "worst_slack_ns": %s, "fmax_mhz": %s, ' \
    "$ff_count" "$clock_mhz" "$wns" "$slack" "$fmax"
  printf '"crossing_nets": %d, "crossing_worst_transition_ns": %s, ' "$cross_n" "$cross_worst"
  printf '"wall_seconds": %d, "yosys_seconds": %d, "yosys_peak_MB": %d, "peak_process_MB": %d, "peak_sum_MB": %d, ' \
    "$wall_s" "$yosys_cpu_s" "$yosys_peak_mb" "$proc_peak_mb" "$sum_peak_mb"
  printf '"per_block": {'
  awk 'NR > 1 {printf ", "} {printf "\"%s\": %d", $1, $2}' "$out/groups.txt"
  printf '}, "blocks": {'
  awk 'NR > 1 {printf ", "} {printf "\"%s\": {\"module\": \"%s\", \"instances\": %d, \"nand2_eq\": %d, \"flip_flops\": %d, \"memory_bits\": %d, \"group\": \"%s\", \"yosys_seconds\": %d, \"peak_MB\": %d, \"reused\": %s}",
    $1, $2, $3, $4, $5, $6, $7, $8, $9, $10 ? "true" : "false"}' "$out/block_figures.txt"
  printf '}}\n'
} > "$out/summary.json.tmp"
mv "$out/report.md.tmp" "$out/report.md"
mv "$out/summary.json.tmp" "$out/summary.json"

echo "synth: $nand2_total NAND2 eq (paper 563k), memory $mem_kb kB in $mem_count macros ($eng_kb kB without the LR post stage; paper 21.3 kB),"
echo "       LR post stage $post_nand2 NAND2 eq, $post_kb kB; with the SoC wrapper (registers $soc_regs, AXI4 master $soc_master, slack $soc_slack ns) $soc_total NAND2 eq,"
echo "       worst slack $slack ns (WNS $wns ns) at $clock_mhz MHz, achievable $fmax MHz (paper 95 MHz)"
echo "synth: report $out/report.md, summary $out/summary.json, netlist $out/mcadsw_engine_osu018.v"
echo "synth: wall time ${wall_s} s (${#queue[@]} blocks synthesised, ${#cached[@]} reused); peak memory ${proc_peak_mb} MB in one process ($proc_peak_what), ${sum_peak_mb} MB all processes together"
