#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# make fpga's report (flow/fpga.py report) on hand-written step figures (tests/fpga/report/):
# a design over the ECP5's LUT4 sites fails its bars and is not placed; a placed one
# below 30 frames a second fails the Fmax bar, with the frames a second computed from the
# CIF D = 64 cycles (raw and LR, not the sub-pixel or other cases); the cells by module (the
# engine, wiring only, listed apart); missing figures exit 2; the SoC without the rectifier,
# placed, reported beside the whole SoC that does not fit; a placement whose routing stopped
# at the time limit, a design packed only, and one packed within the device that nextpnr
# could not place.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
fix=$root/tests/fpga/report
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "report_test: FAILED: $*" >&2; exit 1; }
setup() {   # setup ECP5_SUMMARY
  rm -rf "$tmp/fpga"; mkdir -p "$tmp/fpga/ecp5" "$tmp/fpga/xc7"
  cp "$fix/$1" "$tmp/fpga/ecp5/summary.json"; cp "$fix/blocks.json" "$tmp/fpga/ecp5/"
  cp "$fix/xc7_summary.json" "$tmp/fpga/xc7/summary.json"
}
run() { rc=0; out=$(python3 "$root/flow/fpga.py" report --root "$tmp/fpga" --sim "$fix/sim_summary.json" 2>&1) || rc=$?; }

# 1. Over the device: exit 1, the LUT4-site bar and place and route not met.
setup ecp5_summary.json; run
[ "$rc" = 1 ] || fail "over the device: exit $rc, expected 1: $out"
grep -q '| ECP5 TRELLIS_COMB (packed by nextpnr) | 90112 of 83640 | \*\*no\*\* |' <<<"$out" || fail "no failed LUT4-site bar: $out"
grep -q '| ECP5 placed and routed | no (does not fit) | \*\*no\*\* |' <<<"$out" || fail "placed bar: $out"
grep -q '| XC7Z020 LUTs (logic + memory) (estimate) | 60000 of 53200 | \*\*no\*\* |' <<<"$out" || fail "XC7Z020 LUT bar: $out"
grep -q '| XC7Z020 DSP48E1 (estimate) | 80 of 220 | yes |' <<<"$out" || fail "XC7Z020 DSP bar: $out"
python3 -c "import json,sys; s=json.load(open(sys.argv[1])); assert s['cif_d64_cycles']=={'raw':2226986,'lr':3396072}, s['cif_d64_cycles']; assert s['fps_cif_d64']=={}" "$tmp/fpga/summary.json" \
  || fail "cycles or frames a second in summary.json"
# The cells by module: a block with flip-flops, and the engine (wiring) listed apart.
grep -q '^| mcadsw_census | 1249 | 6 | 0 |$' "$tmp/fpga/report.md" || fail "census row: $(cat "$tmp/fpga/report.md")"
grep -q '^| mcadsw_engine (combinational) | 0 | 0 | 0 |$' "$tmp/fpga/report.md" || fail "combinational engine row"
grep -q 'u_soc.u_engine (mcadsw_engine)' "$tmp/fpga/report.md" || fail "instances with their modules"
# 2. Placed at 70.25 MHz: 30 x 2 226 986 cycles needs 66.8 MHz: met; frames a second.
setup ecp5_summary_placed.json; run
grep -q '| ECP5 Fmax >= 30 x 2226986 cycles = 66.8 MHz | 70.2 MHz | yes |' <<<"$out" || fail "Fmax bar: $out"
python3 -c "import json,sys; s=json.load(open(sys.argv[1])); assert s['fps_cif_d64']=={'raw':31.5,'lr':20.7}, s['fps_cif_d64']" "$tmp/fpga/summary.json" \
  || fail "frames a second"
[ "$rc" = 1 ] || fail "XC7Z020 over its LUTs: exit $rc, expected 1"
# 3. A step's figures missing: exit 2, no summary left behind.
setup ecp5_summary.json; rm "$tmp/fpga/xc7/summary.json"; run
[ "$rc" = 2 ] || fail "missing figures: exit $rc, expected 2"
grep -q 'missing figures of a step' <<<"$out" || fail "message: $out"
[ ! -e "$tmp/fpga/summary.json" ] || fail "a summary was written"
# 4. Beside the SoC over the device, the SoC without the rectifier placed at 70.25 MHz: its
# figures in their own section and summary key; the whole SoC's bars still fail (exit 1).
setup ecp5_summary.json; mkdir -p "$tmp/fpga/ecp5_norect"
cp "$fix/ecp5_summary_placed.json" "$tmp/fpga/ecp5_norect/summary.json"; run
[ "$rc" = 1 ] || fail "whole SoC over the device: exit $rc, expected 1"
grep -q '## ECP5 without the rectifier' <<<"$out" || fail "no section without the rectifier: $out"
grep -q '| ECP5 Fmax >= 66.8 MHz | 70.2 MHz | yes |' <<<"$out" || fail "Fmax without the rectifier: $out"
python3 -c "import json,sys; s=json.load(open(sys.argv[1])); assert s['ecp5_norect']['fps_cif_d64']=={'raw':31.5,'lr':20.7}, s; assert s['fps_cif_d64']=={}" "$tmp/fpga/summary.json" \
  || fail "frames a second without the rectifier"
# 5. The SoC fits, placed, routing stopped at the time limit: the placement's estimate in
# the Fmax row, not met; beside it the SoC without the rectifier packed only (--no-pnr).
setup ecp5_summary_timeout.json; mkdir -p "$tmp/fpga/ecp5_norect"
cp "$fix/ecp5_summary_packed.json" "$tmp/fpga/ecp5_norect/summary.json"; run
[ "$rc" = 1 ] || fail "routing unfinished: exit $rc, expected 1"
grep -q '| ECP5 TRELLIS_COMB (packed by nextpnr) | 83237 of 83640 | yes |' <<<"$out" || fail "fit: $out"
grep -q '| ECP5 placed and routed | no (placed; routing unfinished at the time limit) | \*\*no\*\* |' <<<"$out" \
  || fail "placed, not routed: $out"
grep -q '| ECP5 Fmax >= 30 x 2226986 cycles = 66.8 MHz | not routed (estimate after placement 30.1 MHz) | \*\*no\*\* |' \
  <<<"$out" || fail "Fmax after placement: $out"
grep -q '| ECP5 placed and routed | not attempted (packed only) | \*\*no\*\* |' <<<"$out" || fail "packed only: $out"
# 6. Packed within the device, but nextpnr found no legal placement: said so, not met.
setup ecp5_summary_unplaceable.json; run
[ "$rc" = 1 ] || fail "no legal placement: exit $rc, expected 1"
grep -q '| ECP5 placed and routed | no (packed within the device; nextpnr found no legal placement) | \*\*no\*\* |' \
  <<<"$out" || fail "no legal placement: $out"
grep -q '| ECP5 Fmax >= 30 x 2226986 cycles = 66.8 MHz | not placed | \*\*no\*\* |' <<<"$out" || fail "Fmax not placed: $out"
echo "report_test: 6 cases passed"
