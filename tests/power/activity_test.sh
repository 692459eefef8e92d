#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# mcadsw_activity (sim/activity/netlist_activity.cpp) on a netlist small enough to
# follow by hand: an inverter, a flip-flop with asynchronous reset, an XOR and a
# 2 x 1 memory macro, over five recorded cycles; then a flip-flop behind a clock
# gate (flow/clock_gate.py). The transitions, high cycles and macro accesses
# below are worked out from the circuits (see the comments), not taken from a
# run. A recording whose output disagrees, a missing port and a flip-flop on a
# data clock must stop the run.
#   tests/power/activity_test.sh [MCADSW_ACTIVITY]
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
act=${1:-$root/build/bin/mcadsw_activity}
[ -x "$act" ] || { echo "activity_test: no mcadsw_activity at $act"; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/n.v" <<'V'
module mcadsw_engine(clk_i, rst_ni, a_i, y_o, q_o, m_o);
  input clk_i;
  input rst_ni;
  input a_i;
  output y_o;
  output q_o;
  output m_o;
  wire n1;
  INVX1 g1 (.A(a_i), .Y(n1));
  DFFSR r1 (.CLK(clk_i), .D(n1), .Q(q_o), .R(rst_ni), .S(1'b1));
  XOR2X1 g2 (.A(q_o), .B(a_i), .Y(y_o));
  MCADSW_RAM_S2_W1_A1_SYNC_WE m (.RD_ADDR(a_i), .RD_ARST(1'b0), .RD_CLK(clk_i), .RD_DATA(m_o), .RD_EN(1'b1),
    .WR_ADDR(q_o), .WR_CLK(clk_i), .WR_DATA(n1), .WR_WE(rst_ni));
endmodule
V
# Cycle by cycle (values before the rising edge; n1 = ~a, y = q ^ a, q <= n1 unless
# reset, m <= mem[a] then mem[q] <= n1 while rst_ni):
#   c0: rst 0 a 0 -> n1 1 q 0 y 0 m 0; edge: read mem[0] = 0, no write
#   c1: rst 1 a 1 -> n1 0 q 0 y 1 m 0; edge: q 0, read mem[1] = 0, mem[0] <= 0
#   c2: rst 1 a 0 -> n1 1 q 0 y 0 m 0; edge: q 1, read mem[0] = 0, mem[0] <= 1
#   c3: rst 1 a 0 -> n1 1 q 1 y 1 m 0; edge: q 1, read mem[0] = 1, mem[1] <= 1
#   c4: rst 1 a 1 -> n1 0 q 1 y 0 m 1; edge: q 0, read mem[1] = 1, mem[1] <= 0
#   after: q 0 a 1 -> y 1
{ echo "ports rst_ni:1:in a_i:1:in y_o:1:out q_o:1:out m_o:1:out"
  printf '%s\n' "0 0 0 0 0" "1 1 1 0 0" "1 0 0 0 0" "1 0 1 1 0" "1 1 0 1 1"; } > "$work/p.txt"
fails=0
if ! "$act" "$work/n.v" "$work/p.txt" "$work/a" --hold 3 > "$work/log" 2>&1; then
  echo "FAIL: mcadsw_activity failed on a consistent recording"; cat "$work/log"; exit 1
fi
# Transitions and high cycles over the 5 cycles (from the all-zero, reset state):
#   a: up at c1, down c2, up c4 = 3, high c1 and c4 = 2;  rst: 1, high c1..c4 = 4
#   n1: down c1, up c2, down c4 = 3, high c0, c2, c3 = 3;  q: up after c2, down after c4 = 2, high c3, c4 = 2
#   y: up c1, down c2, up c3, down c4, up after = 5, high c1, c3 = 2;  m: up after c3 = 1, high c4 = 1
# Macro: 5 reads (RD_EN always), 4 writes (rst_ni high at c1..c4).
# expect FILE LINE: FILE (frame or idle) has LINE.
expect() {
  local key
  key=$(cut -d' ' -f1-2 <<< "$2")
  if grep -qx "$2" "$work/a.$1.txt"; then echo "ok   $1: $2"
  else echo "FAIL $1: $2 (got: $(grep "^$key " "$work/a.$1.txt"))"; fails=$((fails + 1)); fi
}
expect frame "cycles 5"
expect frame "net a_i 3 2"
expect frame "net rst_ni 1 4"
expect frame "net n1 3 3"
expect frame "net q_o 2 2"
expect frame "net y_o 5 2"
expect frame "net m_o 1 1"
expect frame "macro m MCADSW_RAM_S2_W1_A1_SYNC_WE 2 1 5 4"
# --hold 3: the inputs held (a 1, rst 1; this netlist has no start or memory port to
# quiet), 4 cycles to drain, then 3 counted: q stays 0 (n1 = 0), y = 1; the drains'
# first edge reads mem[1] = 0 (written at the c4 edge), so m is 0 in the window;
# every edge reads and (rst high) writes.
expect idle "cycles 3"
expect idle "net a_i 0 3"
expect idle "net rst_ni 0 3"
expect idle "net y_o 0 3"
expect idle "net n1 0 0"
expect idle "net q_o 0 0"
expect idle "net m_o 0 0"
expect idle "macro m MCADSW_RAM_S2_W1_A1_SYNC_WE 2 1 3 3"
# refused NAME RECORDING REGEX: mcadsw_activity must fail on RECORDING, saying REGEX.
refused() {
  if "$act" "$work/n.v" "$2" "$work/r_$1" > "$work/$1.log" 2>&1; then
    echo "FAIL: $1: accepted"; fails=$((fails + 1))
  elif grep -q "$3" "$work/$1.log"; then
    echo "ok   $1 refused: $(grep "$3" "$work/$1.log")"
  else
    echo "FAIL: $1: the message lacks /$3/"; cat "$work/$1.log"; fails=$((fails + 1))
  fi
}
# An output that disagrees with the recording (y at c3) stops the run.
sed '5s/^1 0 1 1 0$/1 0 0 1 0/' "$work/p.txt" > "$work/bad.txt"
refused wrong_output "$work/bad.txt" "cycle 3: output y_o bit 0: netlist 1, RTL 0"
# A recording without one of the netlist's ports (m_o) is refused by name.
{ echo "ports rst_ni:1:in a_i:1:in y_o:1:out q_o:1:out"; printf '%s\n' "0 0 0 0"; } > "$work/short.txt"
refused missing_port "$work/short.txt" "missing: m_o"
# A clock gate as flow/clock_gate.py builds it: ck_n = ~clk, the latch el takes en
# while the clock is low, gclk = clk & el clocks the flip-flop g (reset by rst_ni).
cat > "$work/g.v" <<'V'
module mcadsw_engine(clk_i, rst_ni, en_i, d_i, g_o);
  input clk_i;
  input rst_ni;
  input en_i;
  input d_i;
  output g_o;
  wire ck_n;
  wire el;
  wire gclk;
  INVX1 i0 (.A(clk_i), .Y(ck_n));
  LATCH l0 (.CLK(ck_n), .D(en_i), .Q(el));
  AND2X2 a0 (.A(clk_i), .B(el), .Y(gclk));
  DFFSR g (.CLK(gclk), .D(d_i), .Q(g_o), .R(rst_ni), .S(1'b1));
endmodule
V
# Cycles (values before the rising edge; the edge after cycle k is at half cycle
# 2k + 2, the fall of cycle k at 2k + 1):
#   c0: rst 0 en 0 d 1 -> g 0 (reset); el 0
#   c1: rst 1 en 1 d 1 -> g 0; el 1 from the fall (3); edge (4) passes: g <= 1
#   c2: rst 1 en 0 d 0 -> g 1; gclk falls and el 0 at the fall (5); edge gated
#   c3: rst 1 en 1 d 0 -> g 1; el 1 (7); edge (8) passes: g <= 0
#   c4: rst 1 en 0 d 1 -> g 0; gclk and el fall (9); edge (10) gated
{ echo "ports rst_ni:1:in en_i:1:in d_i:1:in g_o:1:out"
  printf '%s\n' "0 0 1 0" "1 1 1 0" "1 0 0 1" "1 1 0 1" "1 0 1 0"; } > "$work/gp.txt"
if ! "$act" "$work/g.v" "$work/gp.txt" "$work/ga" > "$work/glog" 2>&1; then
  echo "FAIL: mcadsw_activity failed on the clock gate"; cat "$work/glog"; fails=$((fails + 1))
else
  cp "$work/ga.frame.txt" "$work/a.gate.txt"
  # g: up after c1, down after c3, high c2 c3. gclk: up 4, 8, down 5, 9: 4, high
  # 2 half cycles. el: up 3, 7, down 5, 9: 4, high 4 halves. ck_n: down at every
  # edge (2, 4, 6, 8, 10), up at the falls 3, 5, 7, 9: 9, high [0,2) and four
  # halves = 6 halves. clk_i: the other 9 transitions, high 4 halves.
  expect gate "cycles 5"
  expect gate "net g_o 2 2"
  expect gate "net gclk 4 1"
  expect gate "net el 4 2"
  expect gate "net ck_n 9 3"
  expect gate "net clk_i 9 2"
fi
# A flip-flop clocked by anything but clk_i or such a gate is refused.
sed 's/DFFSR g (.CLK(gclk)/DFFSR g (.CLK(en_i)/' "$work/g.v" > "$work/g_bad.v"
if "$act" "$work/g_bad.v" "$work/gp.txt" "$work/gb" > "$work/gb.log" 2>&1; then
  echo "FAIL: a flip-flop clocked by en_i accepted"; fails=$((fails + 1))
elif grep -q "flip-flop g is clocked by en_i, neither clk_i nor a clock gate" "$work/gb.log"; then
  echo "ok   data clock refused: $(grep -o 'flip-flop g is clocked.*' "$work/gb.log")"
else
  echo "FAIL: data clock: the message lacks the flip-flop"; cat "$work/gb.log"; fails=$((fails + 1))
fi
[ "$fails" = 0 ] && echo "activity_test: all checks passed" || { echo "activity_test: $fails failed"; exit 1; }
