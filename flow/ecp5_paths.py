# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

"""Where the long paths of a synth_ecp5 netlist are, before place and route: a rough static
timing of the netlist with one delay a cell type and one delay a net, its longest
register-to-register paths grouped by the RTL lines of their first and last register.

    python3 flow/ecp5_paths.py NETLIST.json [--groups N] [--json OUT.json]

nextpnr-ecp5 reports critical paths only once it has routed, which takes hours for the
engine on 2 cores; this takes seconds on the same netlist, so a change of the RTL can be
judged before a placement run. It is a guide, not a figure: the delays below are typical of
an ECP5 of speed grade 6 (LUT, carry and block-RAM delays of the Lattice data sheet, a
routed net as nextpnr estimates a short one) and every net gets the same one. On the SoC
without the rectifier (flow/ecp5.py soc --no-rect) the estimate was 41.4 ns against
nextpnr's 40.1 ns after placement (24.94 MHz).

Start points: flip-flop outputs (TRELLIS_FF.Q) and block-RAM outputs (DP16KD, unregistered:
clock to output). End points: flip-flop inputs (D, CE, LSR), block-RAM and LUT-RAM inputs.
Combinational arcs: LUT4, the LUT-combining muxes (PFUMX, L6MUX21: no net from the LUTs or
muxes they combine, which reach them on the slice's dedicated wires), carry cells (CCU2C:
carry in to carry out on the dedicated chain, without a net), multipliers (MULT18X18D,
unregistered as synth_ecp5 maps them), LUT-RAM reads (TRELLIS_DPR16X4 read address to data).
Exit 0; 2 on an unreadable netlist.
"""
import argparse
import json
import re
import sys
from collections import defaultdict, deque
from pathlib import Path

NET = 0.9            # ns, one routed net
SETUP = 0.2          # flip-flop / RAM input setup
CLK_TO_Q = {"TRELLIS_FF": 0.5, "DP16KD": 4.3}
LUT = 0.45
MUX = 0.3            # PFUMX, L6MUX21
CARRY_IN_S = 0.7     # CCU2C A/B/C/D to a sum (through its half of the chain)
CARRY_IN_CO = 0.6    # CCU2C A/B/C/D to carry out
CARRY_CI_S = 0.35
CARRY_CI_CO = 0.07   # one CCU2C (two bits) of a carry chain
MULT = 5.5
LUTRAM_READ = 0.6


def arcs(cell):
    """The combinational arcs of a cell: [(input ports, output ports, delay, through a net)]."""
    t, pd = cell["type"], cell.get("port_directions", {})
    ins = [p for p, d in pd.items() if d == "input"]
    outs = [p for p, d in pd.items() if d == "output"]
    if t == "LUT4":
        return [(ins, outs, LUT, True)]
    if t == "PFUMX":     # its LUT inputs come from the slice's own two LUTs
        return [(["ALUT", "BLUT"], outs, MUX, False), (["C0"], outs, MUX, True)]
    if t == "L6MUX21":   # its data inputs from the neighbouring slices' PFUMX, dedicated
        return [(["D0", "D1"], outs, MUX, False), (["SD"], outs, MUX, True)]
    if t == "CCU2C":
        data = [p for p in ins if p != "CIN"]
        return [(data, ["S0", "S1"], CARRY_IN_S, True), (data, ["COUT"], CARRY_IN_CO, True),
                (["CIN"], ["S0", "S1"], CARRY_CI_S, False), (["CIN"], ["COUT"], CARRY_CI_CO, False)]
    if t == "MULT18X18D":
        return [(ins, outs, MULT, True)]
    if t == "TRELLIS_DPR16X4":
        return [(["RAD"], ["DO"], LUTRAM_READ, True)]
    return []


ENDPOINTS = ("TRELLIS_FF", "DP16KD", "TRELLIS_DPR16X4")
CLOCKS = ("CLK", "CLKA", "CLKB", "WCK")


def rtl_lines(cell):
    """The RTL lines a cell keeps in its source attribute (rtl/FILE.sv:LINE), or its type."""
    s = sorted(set(re.findall(r"rtl/([\w/]+\.sv:\d+)", cell.get("attributes", {}).get("src", ""))))
    return " ".join(s) or cell["type"]


def top_module(netlist):
    """The top module (the one whose attributes say top) of a design in Yosys's JSON, as
    synth_ecp5 and nextpnr write it; ValueError if there is none."""
    mods = json.loads(Path(netlist).read_text())["modules"]
    top = next((v for v in mods.values() if v.get("attributes", {}).get("top")), None)
    if top is None:
        raise ValueError(f"{netlist}: no top module")
    return top


def analyse(netlist):
    """Arrival times of the top module's nets; returns (end points, the cells, predecessor
    map, arrival times, net names): end points [(arrival with setup, bit, cell, port)],
    slowest first; net names by bit, where Yosys kept one."""
    top = top_module(netlist)
    cells = top["cells"]
    names = {}
    for name, n in top.get("netnames", {}).items():
        if n.get("hide_name"):
            continue
        for i, b in enumerate(n.get("bits", [])):
            if isinstance(b, int):
                names.setdefault(b, name if len(n["bits"]) == 1 else f"{name}[{i}]")
    arr, pred = {}, {}
    users = defaultdict(list)           # bit -> [(cell, output bits, delay)]
    for cn, c in cells.items():
        con = c.get("connections", {})
        for ins, outs, dl, net in arcs(c):
            ob = [b for p in outs for b in con.get(p, []) if isinstance(b, int)]
            for p in ins:
                for b in con.get(p, []):
                    if isinstance(b, int):
                        users[b].append((cn, ob, dl + (NET if net else 0.0)))
        t0 = CLK_TO_Q.get(c["type"])
        if t0 is not None:
            for p, d in c.get("port_directions", {}).items():
                if d == "output":
                    for b in con.get(p, []):
                        if isinstance(b, int):
                            arr[b], pred[b] = t0, (None, cn)
    # Longest paths in topological order of the bits (Kahn).
    deps = defaultdict(int)
    for us in users.values():
        for _, ob, _ in us:
            for o in ob:
                deps[o] += 1
    todo = deque(b for b in set(arr) | set(users) if deps[b] == 0)
    while todo:
        b = todo.popleft()
        a = arr.setdefault(b, 0.0)
        for cn, ob, dl in users.get(b, []):
            for o in ob:
                if a + dl > arr.get(o, -1.0):
                    arr[o], pred[o] = a + dl, (b, cn)
                deps[o] -= 1
                if deps[o] == 0:
                    todo.append(o)
    loops = sum(1 for v in deps.values() if v > 0)
    if loops:
        raise ValueError(f"{netlist}: {loops} nets on combinational loops")
    ends = []
    for cn, c in cells.items():
        if c["type"] not in ENDPOINTS:
            continue
        for p, bits in c.get("connections", {}).items():
            if c.get("port_directions", {}).get(p) != "input" or p in CLOCKS:
                continue
            for b in bits:
                if isinstance(b, int) and b in arr:
                    ends.append((round(arr[b] + NET + SETUP, 2), b, cn, p))
    ends.sort(key=lambda e: -e[0])
    return ends, cells, pred, arr, names


def trace(end, cells, pred, arrivals, names):
    """The cells of an end point's slowest path, first to last: lines of arrival (ns), cell
    type, the cell's RTL lines, and the name of the net it drives (the netlist's, when Yosys
    kept one)."""
    steps, x = [], end[1]
    while x in pred:
        b, c = pred[x]
        steps.append((arrivals.get(x, 0.0), cells[c]["type"], rtl_lines(cells[c]), names.get(x, "")))
        if b is None:
            break
        x = b
    return [f"{t:6.2f}  {ty:<12} {ln:<40} {net}" for t, ty, ln, net in reversed(steps)]


def groups(ends, cells, pred):
    """The slowest path of each (first register's RTL lines, last register's RTL lines), slowest
    first: ([{"ns", "from", "to", "through"}], [the end point of each, for trace()]), through:
    the RTL lines of the carry chains and multipliers on the way (LUTs keep none)."""
    seen, out, out_ends = set(), [], []
    for t, b, cn, p in ends:
        through, x = [], b
        while x in pred and pred[x][0] is not None:
            x, c = pred[x]
            if cells[c]["type"] in ("CCU2C", "MULT18X18D"):
                ln = rtl_lines(cells[c])
                if ln not in through:
                    through.append(ln)
        start = pred[x][1] if x in pred else None
        key = (rtl_lines(cells[start]) if start else "input", rtl_lines(cells[cn]))
        if key in seen:
            continue
        seen.add(key)
        out.append({"ns": t, "from": key[0], "to": key[1], "through": list(reversed(through))})
        out_ends.append((t, b, cn, p))
    return out, out_ends


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("netlist")
    ap.add_argument("--groups", type=int, default=30, help="path groups listed (default 30)")
    ap.add_argument("--json", help="write the groups listed to this file")
    ap.add_argument("--trace", type=int, default=0, metavar="K",
                    help="print the cells of the K-th group's path (1: the slowest)")
    a = ap.parse_args(argv)
    try:
        ends, cells, pred, arrivals, names = analyse(a.netlist)
    except (OSError, ValueError, KeyError, StopIteration) as e:
        print(f"ecp5_paths: {e}", file=sys.stderr)
        return 2
    gs, g_ends = groups(ends, cells, pred)
    gs = gs[:a.groups]
    worst = gs[0]["ns"] if gs else 0.0
    print(f"estimated worst register-to-register path {worst:.1f} ns "
          f"({1000.0 / worst if worst else 0:.1f} MHz), {len(ends)} end points")
    for g in gs:
        print(f"{g['ns']:6.2f} ns  {g['from']}  ->  {g['to']}"
              + (f"   (through {', '.join(g['through'][:4])})" if g["through"] else ""))
    if a.trace:
        if not 1 <= a.trace <= len(gs):
            print(f"ecp5_paths: --trace {a.trace}: {len(gs)} groups listed", file=sys.stderr)
            return 2
        print(f"path of group {a.trace} (arrival ns, cell, RTL lines, net driven):")
        for line in trace(g_ends[a.trace - 1], cells, pred, arrivals, names):
            print("  " + line)
    if a.json:
        Path(a.json).write_text(json.dumps({"worst_ns": worst, "groups": gs}, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
