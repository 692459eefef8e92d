#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""mcadsw_activity (sim/activity/netlist_activity.cpp) on a netlist small enough to follow by
hand: an inverter, a flip-flop with asynchronous reset, an XOR and a 2 x 1 memory macro, over
five recorded cycles; then a flip-flop behind a clock gate (flow/clock_gate.py); then a gate
behind that gate (flow/clock_gate.py's inside a block whose clock is gated as a whole) and a
memory macro on a gated clock. The
transitions, high cycles and macro accesses below are worked out from the circuits (see the
comments), not taken from a run. A recording whose output disagrees, a missing port and a
flip-flop or a macro on a data clock must stop the run.
  tests/power/activity_test.py [MCADSW_ACTIVITY]
"""
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent.parent
fails = 0

NETLIST = """module mcadsw_engine(clk_i, rst_ni, a_i, y_o, q_o, m_o);
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
"""
# Cycle by cycle (values before the rising edge; n1 = ~a, y = q ^ a, q <= n1 unless reset,
# m <= mem[a] then mem[q] <= n1 while rst_ni):
#   c0: rst 0 a 0 -> n1 1 q 0 y 0 m 0; edge: read mem[0] = 0, no write
#   c1: rst 1 a 1 -> n1 0 q 0 y 1 m 0; edge: q 0, read mem[1] = 0, mem[0] <= 0
#   c2: rst 1 a 0 -> n1 1 q 0 y 0 m 0; edge: q 1, read mem[0] = 0, mem[0] <= 1
#   c3: rst 1 a 0 -> n1 1 q 1 y 1 m 0; edge: q 1, read mem[0] = 1, mem[1] <= 1
#   c4: rst 1 a 1 -> n1 0 q 1 y 0 m 1; edge: q 0, read mem[1] = 1, mem[1] <= 0
#   after: q 0 a 1 -> y 1


def recording(ports, cycles):
    """A recorded-ports file (sim/dut_core.cpp --record-ports): the ports line, a line a cycle."""
    return "ports " + ports + "\n" + "".join(c + "\n" for c in cycles)


PORTS = "rst_ni:1:in a_i:1:in y_o:1:out q_o:1:out m_o:1:out"
CYCLES = ["0 0 0 0 0", "1 1 1 0 0", "1 0 0 0 0", "1 0 1 1 0", "1 1 0 1 1"]

# A clock gate as flow/clock_gate.py builds it: ck_n = ~clk, the latch el takes en while the
# clock is low, gclk = clk & el clocks the flip-flop g (reset by rst_ni).
GATED = """module mcadsw_engine(clk_i, rst_ni, en_i, d_i, g_o);
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
"""
# Cycles (values before the rising edge; the edge after cycle k is at half cycle 2k + 2, the
# fall of cycle k at 2k + 1):
#   c0: rst 0 en 0 d 1 -> g 0 (reset); el 0
#   c1: rst 1 en 1 d 1 -> g 0; el 1 from the fall (3); edge (4) passes: g <= 1
#   c2: rst 1 en 0 d 0 -> g 1; gclk falls and el 0 at the fall (5); edge gated
#   c3: rst 1 en 1 d 0 -> g 1; el 1 (7); edge (8) passes: g <= 0
#   c4: rst 1 en 0 d 1 -> g 0; gclk and el fall (9); edge (10) gated
GATED_REC = recording("rst_ni:1:in en_i:1:in d_i:1:in g_o:1:out",
                      ["0 0 1 0", "1 1 1 0", "1 0 0 1", "1 1 0 1", "1 0 1 0"])

# A gate behind the gate above (i1, l1, a1 on gclk: g2clk = gclk & el2, el2 taking e2_i while
# gclk is low), the flip-flop h on g2clk and the memory macro m on gclk (reads mem[0], writes
# mem[0] <= d_i while rst_ni; RD_CLK = WR_CLK = gclk).
NESTED = GATED.replace("  output g_o;\n", """  output g_o;
  output h_o;
  output m_o;
  wire gk_n;
  wire el2;
  wire g2clk;
  INVX1 i1 (.A(gclk), .Y(gk_n));
  LATCH l1 (.CLK(gk_n), .D(e2_i), .Q(el2));
  AND2X2 a1 (.A(gclk), .B(el2), .Y(g2clk));
  DFFSR h (.CLK(g2clk), .D(d_i), .Q(h_o), .R(rst_ni), .S(1'b1));
  MCADSW_RAM_S2_W1_A1_SYNC_WE m (.RD_ADDR(1'b0), .RD_ARST(1'b0), .RD_CLK(gclk), .RD_DATA(m_o), .RD_EN(1'b1),
    .WR_ADDR(1'b0), .WR_CLK(gclk), .WR_DATA(d_i), .WR_WE(rst_ni));
""").replace("(clk_i, rst_ni, en_i, d_i, g_o)", "(clk_i, rst_ni, en_i, e2_i, d_i, g_o, h_o, m_o)").replace(
    "  input d_i;\n", "  input e2_i;\n  input d_i;\n")
# Cycles (rst en e2 d; g h m before the edge): the edge after cycle k at half cycle 2k + 2, the
# inputs of cycle k set at 2k, the fall at 2k + 1.
#   c0: 0 0 0 1; el 0, el2 0 (l1 open: gclk low), edge 2 gated
#   c1: 1 1 1 1; el2 1 at 2, el 1 at the fall (3); edge 4: gclk and g2clk rise: g <= 1, h <= 1,
#       m <= mem[0] = 0, mem[0] <= 1
#   c2: 1 1 0 0; g 1 h 1; l1 closed while gclk is high, so el2 falls only at the fall (5);
#       edge 6: gclk passes, g2clk gated: g <= 0, m <= mem[0] = 1, mem[0] <= 0
#   c3: 1 0 1 1; g 0 h 1 m 1; el 0 and el2 1 at the fall (7); edge 8 gated: nothing clocked, the
#       macro neither read nor written
#   c4: 1 1 1 0; el 1 at the fall (9); edge 10: both pass: g <= 0, h <= 0, m <= mem[0] = 0
NESTED_REC = recording("rst_ni:1:in en_i:1:in e2_i:1:in d_i:1:in g_o:1:out h_o:1:out m_o:1:out",
                       ["0 0 0 1 0 0 0", "1 1 1 1 0 0 0", "1 1 0 0 1 1 0", "1 0 1 1 0 1 1", "1 1 1 0 0 1 1"])


def expect(what, path, line):
    """PATH (an activity file) has LINE."""
    global fails
    lines = path.read_text().splitlines()
    if line in lines:
        print(f"ok   {what}: {line}")
    else:
        key = " ".join(line.split()[:2]) + " "
        got = [ln for ln in lines if ln.startswith(key)]
        print(f"FAIL {what}: {line} (got: {' '.join(got)})")
        fails += 1


def run(act, netlist, rec, out, *more):
    r = subprocess.run([act, str(netlist), str(rec), str(out), *more], capture_output=True, text=True)
    return r.returncode, r.stdout + r.stderr


def refused(act, work, name, netlist, rec, regex):
    """mcadsw_activity must fail on NETLIST and REC, saying REGEX."""
    global fails
    rc, out = run(act, netlist, rec, work / f"r_{name}")
    hit = re.search(regex, out)
    if rc == 0:
        print(f"FAIL: {name}: accepted")
        fails += 1
    elif hit:
        print(f"ok   {name} refused: {out[hit.start():].splitlines()[0]}")
    else:
        print(f"FAIL: {name}: the message lacks /{regex}/\n{out}")
        fails += 1


def main(argv):
    global fails
    act = argv[0] if argv else str(ROOT / "build" / "bin" / "mcadsw_activity")
    if not os.access(act, os.X_OK):
        print(f"activity_test: no mcadsw_activity at {act}")
        return 1
    with tempfile.TemporaryDirectory() as tmp:
        w = Path(tmp)
        (w / "n.v").write_text(NETLIST)
        (w / "p.txt").write_text(recording(PORTS, CYCLES))
        rc, out = run(act, w / "n.v", w / "p.txt", w / "a", "--hold", "3")
        if rc != 0:
            print(f"FAIL: mcadsw_activity failed on a consistent recording\n{out}")
            return 1
        # Transitions and high cycles over the 5 cycles (from the all-zero, reset state):
        #   a: up at c1, down c2, up c4 = 3, high c1 and c4 = 2;  rst: 1, high c1..c4 = 4
        #   n1: down c1, up c2, down c4 = 3, high c0, c2, c3 = 3;  q: up after c2, down after
        #   c4 = 2, high c3, c4 = 2;  y: up c1, down c2, up c3, down c4, up after = 5, high c1,
        #   c3 = 2;  m: up after c3 = 1, high c4 = 1. Macro: 5 reads (RD_EN always), 4 writes
        #   (rst_ni high at c1..c4).
        for line in ["cycles 5", "net a_i 3 2", "net rst_ni 1 4", "net n1 3 3", "net q_o 2 2", "net y_o 5 2",
                     "net m_o 1 1", "macro m MCADSW_RAM_S2_W1_A1_SYNC_WE 2 1 5 4"]:
            expect("frame", w / "a.frame.txt", line)
        # --hold 3: the inputs held (a 1, rst 1; this netlist has no start or memory port to
        # quiet), 4 cycles to drain, then 3 counted: q stays 0 (n1 = 0), y = 1; the drains'
        # first edge reads mem[1] = 0 (written at the c4 edge), so m is 0 in the window; every
        # edge reads and (rst high) writes.
        for line in ["cycles 3", "net a_i 0 3", "net rst_ni 0 3", "net y_o 0 3", "net n1 0 0", "net q_o 0 0",
                     "net m_o 0 0", "macro m MCADSW_RAM_S2_W1_A1_SYNC_WE 2 1 3 3"]:
            expect("idle", w / "a.idle.txt", line)
        # An output that disagrees with the recording (y at c3) stops the run.
        bad = CYCLES[:3] + ["1 0 0 1 0"] + CYCLES[4:]
        (w / "bad.txt").write_text(recording(PORTS, bad))
        refused(act, w, "wrong_output", w / "n.v", w / "bad.txt", "cycle 3: output y_o bit 0: netlist 1, RTL 0")
        # A recording without one of the netlist's ports (m_o) is refused by name.
        (w / "short.txt").write_text(recording("rst_ni:1:in a_i:1:in y_o:1:out q_o:1:out", ["0 0 0 0"]))
        refused(act, w, "missing_port", w / "n.v", w / "short.txt", "missing: m_o")

        (w / "g.v").write_text(GATED)
        (w / "gp.txt").write_text(GATED_REC)
        rc, out = run(act, w / "g.v", w / "gp.txt", w / "ga")
        if rc != 0:
            print(f"FAIL: mcadsw_activity failed on the clock gate\n{out}")
            fails += 1
        else:
            # g: up after c1, down after c3, high c2 c3. gclk: up 4, 8, down 5, 9: 4, high 2
            # half cycles. el: up 3, 7, down 5, 9: 4, high 4 halves. ck_n: down at every edge
            # (2, 4, 6, 8, 10), up at the falls 3, 5, 7, 9: 9, high [0,2) and four halves = 6
            # halves. clk_i: the other 9 transitions, high 4 halves.
            for line in ["cycles 5", "net g_o 2 2", "net gclk 4 1", "net el 4 2", "net ck_n 9 3", "net clk_i 9 2"]:
                expect("gate", w / "ga.frame.txt", line)
        # A flip-flop clocked by anything but clk_i or such a gate is refused.
        (w / "g_bad.v").write_text(GATED.replace("DFFSR g (.CLK(gclk)", "DFFSR g (.CLK(en_i)"))
        refused(act, w, "data_clock", w / "g_bad.v", w / "gp.txt",
                "flip-flop g is clocked by en_i, neither clk_i nor a clock gate")

        (w / "n2.v").write_text(NESTED)
        (w / "n2p.txt").write_text(NESTED_REC)
        rc, out = run(act, w / "n2.v", w / "n2p.txt", w / "na")
        if rc != 0:
            print(f"FAIL: mcadsw_activity failed on the gate behind a gate\n{out}")
            fails += 1
        else:
            # gclk: up 4, 6, 10, down 5, 7: 5, high [4,5) [6,7): 1 cycle. g2clk: up 4, 10, down 5:
            # 3, high half a cycle. el: up 3, down 7, up 9: 3, high [3,7) [9,10]: 2.5. el2: up 2,
            # down 5, up 7: 3, high [2,5) [7,10]: 3. g: up 4, down 6: 2, high 1. h: up 4, down 10:
            # 2, high 3. m: up 6, down 10: 2, high 2. Macro: 3 reads, 3 writes (edges 4, 6, 10).
            for line in ["cycles 5", "net gclk 5 1", "net g2clk 3 0.5", "net el 3 2.5", "net el2 3 3",
                         "net g_o 2 1", "net h_o 2 3", "net m_o 2 2", "macro m MCADSW_RAM_S2_W1_A1_SYNC_WE 2 1 3 3"]:
                expect("gate behind a gate", w / "na.frame.txt", line)
        # A macro on a data clock, or on two clocks, is refused.
        (w / "m_bad.v").write_text(NESTED.replace(".RD_CLK(gclk)", ".RD_CLK(en_i)").replace(".WR_CLK(gclk)",
                                                                                         ".WR_CLK(en_i)"))
        refused(act, w, "macro_data_clock", w / "m_bad.v", w / "n2p.txt",
                "macro m is clocked by en_i, neither clk_i nor a clock gate")
        (w / "m_two.v").write_text(NESTED.replace(".WR_CLK(gclk)", ".WR_CLK(clk_i)"))
        refused(act, w, "macro_two_clocks", w / "m_two.v", w / "n2p.txt", "macro m has two clocks")
    if fails:
        print(f"activity_test: {fails} failed")
        return 1
    print("activity_test: all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
