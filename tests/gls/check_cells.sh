#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# Runs tests/gls/cells_tb.v against the library's cell models and against
# sim/gls/osu018_cells.v (Icarus Verilog) and fails if the transcripts differ.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
lib=${OSU018_CELLS:-/usr/share/qflow/tech/osu018/osu018_stdcells.v}
[ -f "$lib" ] || { echo "check_cells: $lib not found (apt install qflow-tech-osu018)" >&2; exit 2; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
iverilog -o "$tmp/lib" "$root/tests/gls/cells_tb.v" "$lib" 2> "$tmp/lib_warnings.txt"  # "choosing typ expression"
iverilog -g2012 -o "$tmp/own" "$root/tests/gls/cells_tb.v" "$root/sim/gls/osu018_cells.v"
vvp -n "$tmp/lib" | grep -v '^VCD\|\$finish' > "$tmp/lib.txt"
vvp -n "$tmp/own" | grep -v '^VCD\|\$finish' > "$tmp/own.txt"
lines=$(wc -l < "$tmp/lib.txt")
[ "$lines" -ge 800 ] || { echo "check_cells: only $lines lines of transcript" >&2; exit 1; }
if ! diff "$tmp/lib.txt" "$tmp/own.txt" > "$tmp/diff.txt"; then
  head -20 "$tmp/diff.txt"; echo "check_cells: sim/gls/osu018_cells.v differs from $lib" >&2; exit 1
fi
if grep -Eq "=[01]*[xzXZ]" "$tmp/own.txt" "$tmp/lib.txt"; then echo "check_cells: X or Z in the transcript" >&2; exit 1; fi
echo "check_cells: $lines transcript lines identical (29 cells, exhaustive inputs, 400 flip-flop and latch steps)"
