#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# Bad input to `make power` (flow/power.py) gives one clear message and a non-zero
# exit and leaves no summary.json or report.md of an earlier run behind: a DMAX the
# generator rejects, a missing netlist (make synth not run), a missing activity
# file (--activity). No simulation or OpenSTA runs (a few seconds).
#   tests/power/bad_input.sh [GEN_RTL_PKG]
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
gen=${1:-$root/build/bin/gen_rtl_pkg}
[ -x "$gen" ] || { echo "bad_input: no gen_rtl_pkg at $gen"; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fails=0
# expect NAME RC REGEX -- ARGS...: flow/power.py ARGS with --out $work/out_NAME, which
# holds a stale summary.json and report.md before.
expect() {
  local name=$1 want=$2 regex=$3; shift 4
  local out=$work/out_$name rc=0
  mkdir -p "$out"
  echo '{"stale": true}' > "$out/summary.json"
  echo stale > "$out/report.md"
  python3 "$root/flow/power.py" --out "$out" --gen-rtl-pkg "$gen" "$@" > "$work/$name.out" 2> "$work/$name.err" || rc=$?
  local ok=1
  [ "$rc" = "$want" ] || { echo "  exit $rc, wanted $want"; ok=0; }
  grep -Eq "$regex" "$work/$name.err" || { echo "  stderr lacks /$regex/"; ok=0; }
  for f in summary.json report.md; do [ -e "$out/$f" ] && { echo "  stale $f left"; ok=0; }; done
  if [ "$ok" = 1 ]; then echo "ok   $name: $(head -1 "$work/$name.err")"
  else echo "FAIL $name"; sed 's/^/  stderr: /' "$work/$name.err" | tail -8; fails=$((fails + 1)); fi
}
# A configuration gen_rtl_pkg rejects (the one check of DMAX and PAR).
expect dmax_bad 2 "DMAX='0' is not supported" -- --dmax 0 --build "$work/build"
# No netlist: make synth has not run for this build folder.
expect no_netlist 1 "no mcadsw_engine_sta.v in .*: run make synth first" -- --build "$work/build"
# A netlist, but no activity in the --activity folder.
mkdir -p "$work/synth" "$work/act"
echo "module mcadsw_engine(); endmodule" > "$work/synth/mcadsw_engine_sta.v"
echo "library (x) { }" > "$work/synth/mcadsw_ram.lib"
echo '{"blocks": {}}' > "$work/synth/summary.json"
expect no_activity 1 "no activity file .*raw.frame.txt" -- --build "$work/build" --synth "$work/synth" --activity "$work/act"
[ "$fails" = 0 ] && echo "bad_input: all cases passed" || { echo "bad_input: $fails case(s) failed"; exit 1; }
