#!/usr/bin/env bash
# Second simulator: the same small pair through Verilator (mcadsw_sim --dump)
# and through Icarus Verilog (4-state, tests/icarus/tb_mcadsw_top.sv) from the
# memory image the C++ harness wrote; the disparity planes and the counters
# must be identical, and no output may be X after reset.
#   tests/icarus/run.sh BUILD_DIR
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
work=${KEEP_DIR:-$(mktemp -d)}; [ -n "${KEEP_DIR:-}" ] || trap 'rm -rf "$work"' EXIT; mkdir -p "$work"
left=$root/data/cif/teddy/left.png
right=$root/data/cif/teddy/right.png
crop=${CROP:-150,120,22,12}
d=${D:-10}

"$build/bin/mcadsw_sim" "$left" "$right" -d "$d" --crop "$crop" --dump "$work" > "$work/verilator.log"
tail -1 "$work/verilator.log"
cd "$root/rtl"
mods=$(ls mcadsw_*.sv | grep -v '^mcadsw_pkg.sv$')
iverilog -g2012 -o "$work/tb" mcadsw_pkg.sv $mods "$root/tests/icarus/tb_mcadsw_top.sv" 2> "$work/iverilog.log" || {
  cat "$work/iverilog.log"; echo "icarus: compile failed" >&2; exit 1; }
# shellcheck disable=SC2046
vvp -n "$work/tb" +DIR="$work" $(cat "$work/config.txt") | tee "$work/vvp.log"
grep -q "^FAIL" "$work/vvp.log" && exit 1
[ -f "$work/icarus_out.hex" ] || { echo "icarus: no output" >&2; exit 1; }
if ! cmp -s "$work/icarus_out.hex" "$work/verilator_out.hex"; then
  diff "$work/icarus_out.hex" "$work/verilator_out.hex" | head; echo "icarus: disparity planes differ" >&2; exit 1
fi
if ! cmp -s "$work/icarus_counters.txt" "$work/verilator_counters.txt"; then
  cat "$work/icarus_counters.txt" "$work/verilator_counters.txt"; echo "icarus: counters differ" >&2; exit 1
fi
echo "icarus: disparity plane ($(wc -l < "$work/icarus_out.hex") words) and counters identical to Verilator's: $(cat "$work/icarus_counters.txt")"
