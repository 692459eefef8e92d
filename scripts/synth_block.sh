#!/usr/bin/env bash
# One block of the hierarchical `make synth` (called by scripts/synth.sh, two at a time):
# the block's module from the elaborated design (elab.il: every module derived with
# the top's parameters, block modules renamed by synth.sh) through the same steps as
# the flattened flow: its sub-modules flattened into it, memories listed and mapped
# onto the MCADSW_RAM macro (constraints/macro_map.v), OSU 0.18 um flip-flops, ABC
# with the buffering script and -constr (constraints/abc_osu018.constr: block inputs
# and flip-flop outputs modelled as driven by an INVX1, outputs loaded with 0.02 pF,
# so ABC builds buffer trees on high-fanout nets, including those that enter the
# block through a port).
#
#   scripts/synth_block.sh MODULE ELAB_IL OUT_DIR PERIOD_PS LIBERTY [BLACKBOX_MODULE...]
#
# MODULE is the block module (mcadsw_engine for the top's own logic, with the block
# modules given as BLACKBOX_MODULEs: only their ports are kept). Writes in OUT_DIR:
# synth.ys, yosys.log, time.txt, netlist.v (the block module alone), area.txt
# (stat -liberty), memories.txt (module cell width words bits read_ports write_ports
# sync|async), registers.txt (module register bits: registers of 64 bits or more), cost.txt
# (seconds peak_MB). The caller writes the stamp after a zero exit.
# YOSYS=<binary> selects the Yosys executable (default: yosys from PATH).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
[ $# -ge 5 ] || { echo "usage: $0 MODULE ELAB_IL OUT_DIR PERIOD_PS LIBERTY [BLACKBOX_MODULE...]" >&2; exit 2; }
module=$1; elab=$2; out=$3; period_ps=$4; lib=$5; shift 5
yosys_bin=${YOSYS:-yosys}
mkdir -p "$out"
rm -f "$out/netlist.v" "$out/area.txt" "$out/memories.txt" "$out/registers.txt" "$out/cost.txt"

{
  echo "read_rtlil $elab"
  for bb in "$@"; do echo "blackbox $bb"; done
  cat <<YS
hierarchy -check -top $module
synth -run :fine
flatten
# Sub-modules are flattened into the block; drop their now unused definitions.
hierarchy -top $module
# Memories: listed, then replaced by black-box macros.
tee -q -o $out/memories_list.txt select -list t:\$mem_v2
tee -q -o $out/memories_dump.txt dump t:\$mem_v2
# Registers of 64 bits or more (data, not control: image, census, weight and cost
# words in flip-flops), listed so that no buffer hides in flip-flops.
tee -q -o $out/registers_dump.txt dump t:\$*dff* r:WIDTH>=64 %i
techmap -map $root/constraints/macro_map.v t:\$mem_v2
synth -run fine:
dfflibmap -liberty $lib
abc -D $period_ps -constr $root/constraints/abc_osu018.constr -liberty $lib -script $root/constraints/abc_osu018.script
setundef -zero
opt_clean -purge
tee -q -o $out/area.txt stat -liberty $lib
write_verilog -noattr -noexpr -nohex -nodec $out/netlist.v.tmp
YS
} > "$out/synth.ys"
# write_verilog skips black-box modules (MCADSW_RAM, the blocks seen from the top),
# so netlist.v holds the block module alone.

start=$(date +%s)
status=0
if [ -x /usr/bin/time ]; then
  /usr/bin/time -v "$yosys_bin" -q -l "$out/yosys.log" "$out/synth.ys" > /dev/null 2> "$out/time.txt" || status=$?
else
  "$yosys_bin" -q -l "$out/yosys.log" "$out/synth.ys" > /dev/null 2> "$out/time.txt" || status=$?
fi
if [ "$status" -ne 0 ] || [ ! -s "$out/netlist.v.tmp" ]; then
  # The log tail (or Yosys's stderr when it never got as far as the log) goes
  # with the caller's message.
  { [ -s "$out/yosys.log" ] && tail -20 "$out/yosys.log"; grep -v -E '^\s|^Command exited' "$out/time.txt" | tail -5; } >&2 || true
  echo "synth_block: yosys failed on $module (exit $status, log: $out/yosys.log)" >&2
  exit 1
fi
mv "$out/netlist.v.tmp" "$out/netlist.v"
secs=$(( $(date +%s) - start ))
mb=$(awk '/Maximum resident/ {printf "%d", $NF / 1024}' "$out/time.txt")
echo "$secs ${mb:-0}" > "$out/cost.txt"

# The macros model what the engine's memories use; anything else stops here:
# synchronous read resets, read-port initial values, transparent reads.
if grep -Eq "connect .RD_SRST [^1]*[^']1|connect .RD_SRST .[a-zA-Z]" "$out/memories_dump.txt" ||
   grep -Eq "parameter .RD_TRANSPARENCY_MASK [0-9]+'[01]*1" "$out/memories_dump.txt"; then
  echo "synth_block: a memory of $module uses a synchronous read reset or a transparent read; MCADSW_RAM does not model it ($out/memories_dump.txt)" >&2
  exit 1
fi

# Memories: module/cell from `select -list`, WIDTH x SIZE from `dump` (same order),
# read and write ports, and whether every read port is clocked (sync) or not (async:
# no SRAM offers it).
awk '
  FNR == NR { if ($0 ~ /\//) { n++; split($0, p, "/"); mod[n] = p[1]; cell[n] = p[2] } next }
  /cell \$mem_v2/ { m++ }
  /parameter .WIDTH / { w[m] = $3 }
  /parameter .SIZE / { s[m] = $3 }
  /parameter .RD_PORTS / { rp[m] = $3 }
  /parameter .WR_PORTS / { wp[m] = $3 }
  /parameter .RD_CLK_ENABLE / { v = $3; sub(/^[0-9]+\047/, "", v); ce[m] = v }
  END {
    if (m != n) { print "synth_block: memory count mismatch " m " " n > "/dev/stderr"; exit 1 }
    for (i = 1; i <= m; i++)
      printf "%s %s %d %d %d %d %d %s\n", mod[i], cell[i], w[i], s[i], w[i] * s[i], rp[i], wp[i],
             (ce[i] ~ /^1+$/) ? "sync" : "async"
  }' "$out/memories_list.txt" "$out/memories_dump.txt" > "$out/memories.txt"
# Data registers: module, register (the Q signal), bits.
awk -v mod="$module" '
  /cell \$[a-z]*dff/ { k++; q[k] = "?" }
  /parameter .WIDTH / && k { w[k] = $3 }
  /connect .Q / && k { v = $3; if (v ~ /^\\/) { sub(/^\\/, "", v); q[k] = v } else q[k] = "(several)" }
  END { for (i = 1; i <= k; i++) printf "%s %s %d\n", mod, q[i], w[i] }' \
  "$out/registers_dump.txt" > "$out/registers.txt"
