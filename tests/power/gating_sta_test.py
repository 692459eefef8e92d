#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""flow/power.py's power view and flow/power.tcl's accounting of clock gates on a netlist small
enough to follow: flip-flop g behind a clock gate (INVX1 -> LATCH -> AND2X2, as
flow/clock_gate.py builds it), flip-flop h on clk_i, no data moving. OpenSTA charges a clock pin
the full clock whatever activity is set on it, so the power view clocks g by clk_i and
power.tcl scales the clock part of g and of the gate's AND by the fraction r of cycles the gate
opened (gclk's transitions / 2 a cycle). Checked:
  - the view: g on clk_i, the gate file lists g and the AND, the gated net's clock-pin
    capacitance is one DFFSR's;
  - with r = 0, 1/4 and 1: r = 1 takes nothing off; the flip-flops' clock part at r = 0 is h's
    alone, half of that at r = 1 (same cell, same clock slew); it is linear in r; r = 0 takes
    off g's whole clock part;
  - a flip-flop on a clock net that no gate's AND drives is refused.
  tests/power/gating_sta_test.py
"""
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent.parent
sys.path.insert(0, str(ROOT / "flow"))
import power  # noqa: E402

LIB = "/usr/share/qflow/tech/osu018/osu018_stdcells.lib"
NETLIST = """module mcadsw_engine(clk_i, rst_ni, en_i, d_i, g_o, h_o);
  input clk_i;
  input rst_ni;
  input en_i;
  input d_i;
  output g_o;
  output h_o;
  wire ck_n;
  wire el;
  wire clock_gate_0_gclk;
  INVX1 i0 (
    .A(clk_i),
    .Y(ck_n)
  );
  LATCH l0 (
    .CLK(ck_n),
    .D(en_i),
    .Q(el)
  );
  AND2X2 a0 (
    .A(clk_i),
    .B(el),
    .Y(clock_gate_0_gclk)
  );
  DFFSR g (
    .CLK(clock_gate_0_gclk),
    .D(d_i),
    .Q(g_o),
    .R(rst_ni),
    .S(1'b1)
  );
  DFFSR h (
    .CLK(clk_i),
    .D(d_i),
    .Q(h_o),
    .R(rst_ni),
    .S(1'b1)
  );
endmodule
"""
fails = 0


def check(ok, what):
    global fails
    print(("ok   " if ok else "FAIL ") + what)
    fails += not ok


def main():
    if not shutil.which("sta"):
        print("gating_sta_test: OpenSTA (sta) not found (make bootstrap)")
        return 1
    with tempfile.TemporaryDirectory() as tmp:
        w = Path(tmp)
        (w / "n.v").write_text(NETLIST)
        for r in (0, 25, 100):
            (w / f"a{r}.txt").write_text("cycles 100\n" + "".join(f"net {n} 0 0\n" for n in
                                                                  ("en_i", "d_i", "el", "g_o", "h_o", "rst_ni"))
                                         + f"net ck_n 200 50\nnet clock_gate_0_gclk {2 * r} {r // 2}\n")
        lib = power.liberty_facts(LIB)
        cap = power.power_view(str(w / "n.v"), str(w / "view.v"), str(w / "gates.txt"), lib["pin_cap"])
        gates = [g for g in (w / "gates.txt").read_text().split("\n") if g]
        view = (w / "view.v").read_text()
        ok = (sorted(gates) == ["flop g clock_gate_0_gclk", "gate a0 clock_gate_0_gclk"]
              and cap == {"clock_gate_0_gclk": lib["pin_cap"]("DFFSR", "CLK")}
              and view.count(".CLK(clk_i)") == 2 and ".CLK(clock_gate_0_gclk)" not in view)
        check(ok, f"power view: gates {gates}, gated clock-pin capacitance {cap}")
        if not ok:
            return 1
        # A flip-flop on a clock that no gate's AND drives (here the latch's inverted clock) is
        # refused: the view would charge it as gated without a gate to scale it by.
        (w / "bad.v").write_text(NETLIST.replace(".CLK(clock_gate_0_gclk)", ".CLK(ck_n)"))
        try:
            power.power_view(str(w / "bad.v"), str(w / "bad_view.v"), str(w / "bad_gates.txt"), lib["pin_cap"])
            check(False, "power view: a flip-flop on ck_n (no gate's AND) accepted")
        except power.FlowError as e:
            check("without a clock gate's AND" in str(e) and "ck_n" in str(e), f"power view refuses: {e}")
        env = dict(os.environ, LIBERTY=LIB, RAM_LIB="", NETLIST=str(w / "view.v"), GATES=str(w / "gates.txt"),
                   PERIOD_NS="10.526", OUT=str(w / "out.txt"),
                   RUNS=" ".join(f"{{r{r} {w}/a{r}.txt 1}}" for r in (0, 25, 100)))
        r = subprocess.run(["sta", "-no_splash", "-exit", str(ROOT / "flow" / "power.tcl")], env=env,
                           capture_output=True, text=True)
        if r.returncode != 0 or "Error" in r.stdout + r.stderr:
            print(f"FAIL: flow/power.tcl failed\n{r.stdout}{r.stderr}")
            return 1
        lines = [ln.split() for ln in (w / "out.txt").read_text().splitlines() if ln.strip()]

    def get(kind, run):
        return next(ln for ln in lines if ln[0] == kind and ln[1] == run)
    gated = next(ln for ln in lines if ln[0] == "gated")
    check(gated[1:] == ["flops", "1", "gates", "1"], "gated cells: " + " ".join(gated[1:]))
    cp = {r: float(get("clock_pins", r)[2]) for r in ("r0", "r25", "r100")}
    corr = {r: float(get("correction", r)[2]) for r in ("r0", "r25", "r100")}
    check(corr["r100"] == 0.0, f"r = 1 takes nothing off ({corr['r100']:.3e} W)")
    check(cp["r100"] > 0 and abs(cp["r0"] / cp["r100"] - 0.5) < 0.02,
          f"clock part r = 0: {cp['r0']:.4e} W, r = 1: {cp['r100']:.4e} W (ratio {cp['r0'] / cp['r100']:.4f}, 0.5)")
    g_part = cp["r100"] - cp["r0"]
    check(abs(cp["r25"] - cp["r0"] - 0.25 * g_part) < 1e-3 * g_part,
          f"r = 1/4 adds {(cp['r25'] - cp['r0']) / g_part:.4f} of g's clock part (0.25)")
    # Uncorrected, OpenSTA charges g its full clock part; at r = 0 the correction removes it
    # (and the AND's, nothing here: in the view it drives no pin; the gated net's C V^2 f r is
    # flow/power.py's), at r = 1/4 three quarters of that.
    check(abs(corr["r0"] - g_part) <= 1e-6 * g_part, f"r = 0 takes off {corr['r0']:.4e} W, g's clock part {g_part:.4e} W")
    check(abs(corr["r25"] - 0.75 * corr["r0"]) < 1e-3 * corr["r0"],
          f"r = 1/4 takes off {corr['r25'] / corr['r0']:.4f} of r = 0 (0.75)")
    print("gating_sta_test: all checks passed" if not fails else "gating_sta_test: failed")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
