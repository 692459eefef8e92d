#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

"""Clock gating of one block (flow/synth_block.tcl, between `synth` and `dfflibmap`).

The RTL has no gated clock: a register that holds its value does so through an
enable, which Yosys infers as a $_DFFE_ cell and which the OSU 0.18 um library
(no enable flip-flop, no integrated clock-gate cell) would otherwise map as a
multiplexer in front of a flip-flop clocked every cycle. This pass turns each
group of at least MIN flip-flops that share a clock and an enable into plain
flip-flops on a gated clock:

    clk_n = INVX1(clk)                     one a block and clock
    en_l  = LATCH(CLK = clk_n, D = en)     transparent while clk is low
    gclk  = AND2X2(A = clk, B = en_l)      the group's clock

the latch-based gate of every integrated clock-gate cell, built from the
library's own cells (a latch that holds the enable while the clock is high, so
the gated clock has no glitch). An active-low enable goes through a $_NOT_ that
ABC maps. Flip-flops clocked on the falling edge, with a synchronous reset
($_SDFFE_: the reset overrides the enable) or set and reset, and groups smaller
than MIN keep their enable (a multiplexer). The function is unchanged: a
flip-flop that took D when en was 1 and held when 0 now sees no edge when en is
0; make gls checks the netlist against the RTL, flow/power.py measures what it
saves.

  clock_gate.py IN.json OUT.json MODULE MIN REPORT.json
"""
import json
import re
import sys

# Enable flip-flops gated: type -> (clock polarity, enable polarity, type without enable).
GATEABLE = {}
for c in "P":       # rising edge only: the AND gate passes the high phase
    for e in "PN":
        GATEABLE[f"$_DFFE_{c}{e}_"] = (c, e, f"$_DFF_{c}_")
        for r in "PN":
            for v in "01":
                GATEABLE[f"$_DFFE_{c}{r}{v}{e}_"] = (c, e, f"$_DFF_{c}{r}{v}_")
                # $_SDFFCE_: the synchronous reset acts only when enabled, so the
                # flip-flop changes only when en is 1.
                GATEABLE[f"$_SDFFCE_{c}{r}{v}{e}_"] = (c, e, f"$_SDFF_{c}{r}{v}_")

LIB_PORTS = {"INVX1": {"A": "input", "Y": "output"},
             "LATCH": {"CLK": "input", "D": "input", "Q": "output"},
             "AND2X2": {"A": "input", "B": "input", "Y": "output"}}


def gate(design, module, min_group):
    m = design["modules"][module]
    cells = m["cells"]
    next_bit = 1 + max((b for n in m["netnames"].values() for b in n["bits"] if isinstance(b, int)), default=1)

    def new_net(name):
        nonlocal next_bit
        b = next_bit
        next_bit += 1
        m["netnames"][name] = {"hide_name": 0, "bits": [b], "attributes": {}}
        return b

    groups = {}
    for name, c in cells.items():
        t = GATEABLE.get(c["type"])
        if t is None:
            continue
        key = (c["connections"]["C"][0], c["connections"]["E"][0], t[1])
        groups.setdefault(key, []).append(name)
    net_name = {}
    for n, v in sorted(m["netnames"].items(), key=lambda kv: (kv[1].get("hide_name", 0), kv[0])):
        for i, b in enumerate(v["bits"]):
            if isinstance(b, int) and b not in net_name:
                net_name[b] = n if len(v["bits"]) == 1 else f"{n}[{i}]"

    clk_n = {}
    report = {"module": module, "min_group": min_group, "groups": [], "kept_enable_flops": 0}
    for k, ((clk, en, pol), members) in enumerate(sorted(groups.items(), key=lambda kv: -len(kv[1]))):
        if len(members) < min_group or isinstance(clk, str) or isinstance(en, str):
            report["kept_enable_flops"] += len(members)
            continue
        if clk not in clk_n:
            clk_n[clk] = new_net(f"clock_gate_clk_n_{len(clk_n)}")
            cells[f"clock_gate_clk_inv_{len(clk_n) - 1}"] = {
                "hide_name": 0, "type": "INVX1", "parameters": {}, "attributes": {},
                "port_directions": LIB_PORTS["INVX1"], "connections": {"A": [clk], "Y": [clk_n[clk]]}}
        d = en
        if pol == "N":
            d = new_net(f"clock_gate_{k}_en")
            cells[f"clock_gate_{k}_en_not"] = {
                "hide_name": 0, "type": "$_NOT_", "parameters": {}, "attributes": {},
                "port_directions": {"A": "input", "Y": "output"}, "connections": {"A": [en], "Y": [d]}}
        q = new_net(f"clock_gate_{k}_en_latched")
        gclk = new_net(f"clock_gate_{k}_gclk")
        cells[f"clock_gate_{k}_latch"] = {
            "hide_name": 0, "type": "LATCH", "parameters": {}, "attributes": {},
            "port_directions": LIB_PORTS["LATCH"], "connections": {"CLK": [clk_n[clk]], "D": [d], "Q": [q]}}
        cells[f"clock_gate_{k}_and"] = {
            "hide_name": 0, "type": "AND2X2", "parameters": {}, "attributes": {},
            "port_directions": LIB_PORTS["AND2X2"], "connections": {"A": [clk], "B": [q], "Y": [gclk]}}
        for name in members:
            c = cells[name]
            c["type"] = GATEABLE[c["type"]][2]
            del c["connections"]["E"]
            c["port_directions"].pop("E", None)
            c["connections"]["C"] = [gclk]
        report["groups"].append({"gate": k, "flops": len(members), "enable": net_name.get(en, str(en)),
                                 "active_low": pol == "N"})
    report["gated_flops"] = sum(g["flops"] for g in report["groups"])
    report["gates"] = len(report["groups"])
    return report


def main(argv):
    if len(argv) != 6:
        sys.exit(__doc__.strip().splitlines()[-1])
    src, dst, module, min_group, rep = argv[1:]
    design = json.load(open(src))
    if module not in design["modules"]:
        sys.exit(f"clock_gate: module {module} not in {src}")
    if not re.fullmatch(r"[0-9]+", min_group) or int(min_group) < 1:
        sys.exit(f"clock_gate: minimum group size '{min_group}' is not a positive integer")
    report = gate(design, module, int(min_group))
    with open(dst, "w") as f:
        json.dump(design, f)
    with open(rep, "w") as f:
        json.dump(report, f, indent=1)
    print(f"clock_gate: {module}: {report['gated_flops']} flip-flops behind {report['gates']} gates, "
          f"{report['kept_enable_flops']} keep their enable")


if __name__ == "__main__":
    main(sys.argv)
