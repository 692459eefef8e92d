#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

"""make power: the engine's power at 95 MHz from the activity of real frames.

Method (docs/results.md, "Power"): the RTL engine core runs a CIF crop of Teddy at
D = 64 (DMAX when smaller) in the raw mode and in the LR mode and records its ports every cycle
(mcadsw_sim_core --record-ports); mcadsw_activity replays those inputs on the
netlist OpenSTA times (BUILD/synth/mcadsw_engine_sta.v of `make synth`), checks its
outputs against the RTL's in every cycle and counts every net's transitions and
high cycles; OpenSTA (flow/power.tcl) evaluates each cell at the activity of the
nets it drives and reports the power from the OSU 0.18 um liberty's internal-power
tables, by block. The memory macros have no liberty power: a first-order SRAM
model (below) times the access counts of the same simulation. Clock nets are not
in OpenSTA's cell figures: the net of clk_i adds C V^2 f (the liberty capacitances
of its pins), each gated clock net C V^2 f r (r: the fraction of cycles its gate
opened). Clock gates (flow/clock_gate.py): OpenSTA runs on a power view of the
netlist with the gated flip-flops on clk_i, and flow/power.tcl scales their clock
part (and their gate's) by r.

Outputs: BUILD/power/summary.json and report.md (the previous ones are removed
first, so a failed run leaves none). Python 3 standard library only."""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from flowlib import CON, FLOW, LIBERTY, PREFIX, ROOT, FlowError, Run, default_out, gen_package, indent, log, tail  # noqa: E402

CIF = (352, 288)
D_PAPER = 64                     # the paper's D; a smaller DMAX runs at D = DMAX
CROP = "140,117,72,54"           # 4 x 3 blocks of 18 x 18 inside Teddy's CIF frame
IDLE_CYCLES = 2000
LEFT = ROOT / "data" / "cif" / "teddy" / "left.png"
RIGHT = ROOT / "data" / "cif" / "teddy" / "right.png"
MODES = {"raw": [], "lr": ["--lr"]}

# ---- Memory macros: a first-order SRAM energy model -----------------------------------------
# After CACTI's decomposition (S. Wilton, N. Jouppi, "CACTI: an enhanced cache access and
# cycle time model", IEEE JSSC 31(5), 1996): a word line across the W cells of the row, one
# bit-line pair per bit spanning the S rows, a sense amplifier per bit, the row decoder.
# Assumed 0.18 um parameters (an estimate, not a memory compiler's datasheet): gate oxide
# 4 nm (8.6 fF/um^2), access transistor 0.3 um / 0.18 um (0.46 fF of gate), 0.5 fF of drain
# junction, 0.2 fF/um of wire, a bit cell of 600 lambda^2 (2.2 um pitch, lambda = 0.09 um),
# a read swing of 0.2 V on the bit line, 50 fJ a sense amplifier (15 fF switched), 20 fF of
# decoder per address bit; the cell's leakage that of two INVX1 of the liberty.
C_WL_CELL = 2 * 0.46e-15 + 2.2 * 0.2e-15     # two access gates + wire
C_BL_CELL = 0.5e-15 + 2.2 * 0.2e-15          # one access drain + wire
DV_READ = 0.2
E_SA = 50e-15
C_DEC_BIT = 20e-15
MEM_MODEL = ("first-order SRAM model after CACTI (Wilton and Jouppi, IEEE JSSC 31(5) 1996): "
             "word line W x 1.4 fF x V^2, bit lines W x S x 0.94 fF x V x 0.2 V (read) or x V^2 "
             "(write, charged for the whole word whatever its bit enables), 50 fJ a sense amplifier a bit (read), "
             "20 fF x V^2 an address bit; leakage "
             "a bit = two INVX1 of the OSU liberty; assumed 0.18 um parameters, an estimate")


def macro_energy(words, bits, vdd):
    """(read J, write J) of one access to a words x bits macro."""
    dec = math.ceil(math.log2(max(words, 2))) * C_DEC_BIT * vdd * vdd
    wl = bits * C_WL_CELL * vdd * vdd
    read = wl + bits * (words * C_BL_CELL * vdd * DV_READ + E_SA) + dec
    write = wl + bits * words * C_BL_CELL * vdd * vdd + dec
    return read, write


# ---- The liberty: supply, clock-pin capacitances, leakage ------------------------------------
def liberty_facts(path):
    text = Path(path).read_text()
    m = re.search(r"nom_voltage\s*:\s*([0-9.]+)", text)
    if not m:
        raise FlowError(f"no nom_voltage in {path}")
    cells = {}
    for cm in re.finditer(r"cell\s*\(\s*(\w+)\s*\)", text):
        cells[cm.group(1)] = cm.start()
    starts = sorted(cells.values()) + [len(text)]

    def body(cell):
        s = cells[cell]
        return text[s:starts[starts.index(s) + 1]]

    def pin_cap(cell, pin):
        b = body(cell)
        pm = re.search(r"pin\s*\(\s*" + pin + r"\s*\)\s*\{[^}]*?capacitance\s*:\s*([0-9.eE+-]+)", b)
        if not pm:
            raise FlowError(f"no capacitance of {cell}/{pin} in {path}")
        return float(pm.group(1)) * 1e-12   # capacitive_load_unit (1,pf)

    def leak(cell):
        lm = re.search(r"cell_leakage_power\s*:\s*([0-9.eE+-]+)", body(cell))
        return float(lm.group(1)) * 1e-9    # leakage_power_unit 1nW
    return {"vdd": float(m.group(1)), "pin_cap": pin_cap, "inv_leak": leak("INVX1")}


# ---- The netlist (write_verilog of flow/sta_netlist.tcl: one pin a line) ------------------
CELL_LINE = re.compile(r"\s*([A-Za-z_][A-Za-z0-9_]*)\s+(\S+ ?)\s*\($")
PIN_LINE = re.compile(r"(\s*\.)(\w+)\((.*?)(\s*\),?\s*)$")


def connections(netlist):
    """(line, cell, instance, pin match or None) for every line of a netlist; names
    unescaped as OpenSTA prints them."""
    cell = inst = None
    with open(netlist) as f:
        for line in f:
            m = CELL_LINE.match(line)
            if m:
                cell, inst = m.group(1), unescape(m.group(2))
                yield line, cell, inst, None
            else:
                yield line, cell, inst, PIN_LINE.match(line) if cell else None


def unescape(tok):
    return tok[1:].strip() if tok.startswith("\\") else tok.strip()


def net_loads(netlist, pin_cap):
    """({net: capacitance of the cell input pins on it (F)}, {(cell, pin): count} of
    the pins on clk_i). Memory macros' pins are left out (no liberty capacitance)."""
    inputs, loads, clk_pins = {}, {}, {}
    for _, cell, _, m in connections(netlist):
        if not m or cell.startswith("MCADSW_RAM") or m.group(3).startswith("1'b"):
            continue
        key = (cell, m.group(2))
        if key not in inputs:
            try:
                inputs[key] = pin_cap(*key)
            except FlowError:
                inputs[key] = None   # an output pin: no capacitance of its own
        if inputs[key] is not None:
            net = unescape(m.group(3))
            loads[net] = loads.get(net, 0.0) + inputs[key]
            if net == "clk_i":
                clk_pins[key] = clk_pins.get(key, 0) + 1
    return loads, clk_pins


def power_view(netlist, view, gates_file, pin_cap):
    """Writes the power view of a netlist: every flip-flop clocked by a gated clock (a
    net driven by a clock gate's AND, flow/clock_gate.py's, on clk_i or on a gated clock in
    front of a whole block, a gate behind a gate) clocked by clk_i
    instead; and gates_file, "flop|gate INSTANCE NET" for each gated flip-flop and each
    gate's AND. Returns {net: capacitance of its flip-flop clock pins (F)}."""
    gated_cap, gates, and_of = {}, [], {}
    with open(view, "w") as v:
        for line, cell, inst, m in connections(netlist):
            if m and cell.startswith("DFF") and m.group(2) == "CLK" and m.group(3) != "clk_i":
                net = unescape(m.group(3))
                gated_cap[net] = gated_cap.get(net, 0.0) + pin_cap(cell, "CLK")
                gates.append(f"flop {inst} {net}")
                line = f"{m.group(1)}CLK(clk_i{m.group(4)}"
            elif m and cell in ("AND2X1", "AND2X2") and m.group(2) == "Y":
                and_of[unescape(m.group(3))] = inst
            v.write(line)
    # Every gated clock net is driven by a gate's AND (nothing else may drive a clock pin).
    missing = sorted(n for n in gated_cap if n not in and_of)
    if missing:
        raise FlowError(f"power view: {len(missing)} clock nets of flip-flops without a clock gate's AND "
                        f"in {netlist}, e.g. {missing[0]}")
    gates += [f"gate {and_of[n]} {n}" for n in gated_cap]
    Path(gates_file).write_text("".join(g + "\n" for g in gates))
    return gated_cap


# ---- Steps ----------------------------------------------------------------------------------
def harness(args, out):
    """(mcadsw_sim_core, mcadsw_activity) for the configuration: the build tree's for
    DMAX = 64, PAR = 1; otherwise a tree of its own (as make gls does)."""
    build = Path(args.build)
    if args.dmax == "64" and args.par == "1":
        tree = build
    else:
        tree = build / f"power_harness_dmax{args.dmax}_par{args.par}"
        log(f"building the harness for DMAX = {args.dmax}, PAR = {args.par} ({tree})")
        r = subprocess.run(["cmake", "-S", str(ROOT), "-B", str(tree), "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                            f"-DMCADSW_DMAX={args.dmax}", f"-DMCADSW_PAR={args.par}", "-DMCADSW_BLOCK_BENCHES=none"],
                           capture_output=True, text=True)
        if r.returncode != 0:
            raise FlowError("cmake configure of the harness failed:\n" + indent((r.stdout + r.stderr).splitlines()[-20:]))
        r = subprocess.run(["cmake", "--build", str(tree), "--target", "mcadsw_sim_core", "mcadsw_activity"],
                           capture_output=True, text=True)
        if r.returncode != 0:
            raise FlowError("building the harness failed:\n" + indent((r.stdout + r.stderr).splitlines()[-20:]))
    sim, act = tree / "bin" / "mcadsw_sim_core", tree / "bin" / "mcadsw_activity"
    for p in (sim, act):
        if not p.is_file():
            raise FlowError(f"{p} not found (make power builds it; or: cmake --build {tree} "
                            f"--target mcadsw_sim_core mcadsw_activity)")
    return sim, act


def run_jobs(jobs, out):
    """Runs the (name, cmd, log) jobs two at a time; each must exit 0."""
    run = Run()
    try:
        queue = [{"name": n, "cmd": c, "log": lg, "est_mb": 600} for n, c, lg in jobs]

        def start(j):
            j["t0"] = time.time()
            log(f"  {j['name']} started")
            return run.start(j["cmd"], stdout=open(j["log"], "w"), stderr=subprocess.STDOUT)

        def finish(j, rc, mb, secs):
            if rc != 0:
                raise FlowError(f"{j['name']} failed (exit {rc}; log {j['log']}):\n" + indent(tail(j["log"], 12)))
            log(f"  {j['name']} done in {secs} s, peak {mb} MB")
        run.pool(queue, 2, 8000, start, finish)
    finally:
        run.stop()


def cycles_of(logfile):
    m = re.search(r"\s(\d+) cycles\s", Path(logfile).read_text())
    if not m:
        raise FlowError(f"no cycle count in {logfile}")
    return int(m.group(1))


def read_results(path):
    """flow/power.tcl's lines -> ((nets, cells), gated), {run: {...}}: totals and per
    kind (sequential, combinational) summed from the block lines."""
    runs = {}
    nets = gated = None
    for line in Path(path).read_text().splitlines():
        f = line.split()
        if not f:
            continue
        if f[0] == "netlist":
            nets = (int(f[2]), int(f[4]))
        elif f[0] == "gated":
            gated = {"flip_flops": int(f[2]), "gates": int(f[4])}
        elif f[0] == "run":
            runs[f[1]] = {"period_ns": float(f[3]), "annotated_cells": int(f[5]), "missing_nets": int(f[7]),
                          "blocks": {}, "total": [0.0] * 4, "sequential": [0.0] * 4, "combinational": [0.0] * 4}
        elif f[0] == "correction":
            runs[f[1]]["gating_correction_w"] = float(f[2])
        elif f[0] == "clock_pins":
            runs[f[1]]["clock_pins_w"] = float(f[2])
        elif f[0] == "block":
            r = runs[f[1]]
            v = [float(x) for x in f[4:8]]
            r["blocks"][(f[2], f[3])] = v
            r["total"] = [a + b for a, b in zip(r["total"], v)]
            if f[3] in ("seq", "comb"):
                k = "sequential" if f[3] == "seq" else "combinational"
                r[k] = [a + b for a, b in zip(r[k], v)]
    if nets is None or gated is None:
        raise FlowError(f"OpenSTA wrote no results ({path})")
    return (nets, gated), runs


def net_activity(path, names):
    """{net: transitions a cycle} of the nets in names, from an activity file."""
    acts, cycles = {}, None
    with open(path) as f:
        for line in f:
            w = line.split()
            if w[0] == "cycles":
                cycles = int(w[1])
            elif w[0] == "net" and w[1] in names:
                acts[w[1]] = int(w[2]) / cycles
    missing = [n for n in names if n not in acts]
    if missing:
        raise FlowError(f"{path}: no activity of net {missing[0]} ({len(missing)} nets missing)")
    return acts


def read_macros(path):
    macros, cycles = [], None
    with open(path) as f:
        for line in f:
            if line.startswith("cycles "):
                cycles = int(line.split()[1])
            elif line.startswith("macro "):
                _, name, cell, words, bits, reads, writes = line.split()
                macros.append({"name": name, "cell": cell, "words": int(words), "bits": int(bits),
                               "reads": int(reads), "writes": int(writes)})
    if cycles is None:
        raise FlowError(f"{path} is not an activity file (no 'cycles' line)")
    return cycles, macros


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--dmax", default="64")
    ap.add_argument("--par", default="1")
    ap.add_argument("--build", default=str(ROOT / "build"))
    ap.add_argument("--synth", help="the make synth output folder (default BUILD/synth[_dmax<N>][_par<P>])")
    ap.add_argument("--out", help="output folder (default BUILD/power[_dmax<N>][_par<P>])")
    ap.add_argument("--activity", help="reuse this folder's activity files (raw.frame.txt, raw.idle.txt, "
                                       "lr.frame.txt, *.cycles) instead of simulating")
    ap.add_argument("--gen-rtl-pkg", help="the package generator, the one check of DMAX and PAR "
                                          "(default BUILD/bin/gen_rtl_pkg)")
    ap.add_argument("--sta", default="sta")
    ap.add_argument("--liberty", default=LIBERTY)
    args = ap.parse_args()
    PREFIX[0] = "power"
    t_start = time.time()
    suffix = "" if (args.dmax, args.par) == ("64", "1") else f"_dmax{args.dmax}" + (
        f"_par{args.par}" if args.par != "1" else "")
    out = Path(args.out or Path(args.build) / f"power{suffix}")
    for stale in ("summary.json", "report.md"):
        (out / stale).unlink(missing_ok=True)
    gen_package(args.gen_rtl_pkg or Path(args.build) / "bin" / "gen_rtl_pkg", args.dmax, args.par)
    out.mkdir(parents=True, exist_ok=True)
    d = min(D_PAPER, int(args.dmax))
    synth = Path(args.synth or default_out(args.build, args.dmax, args.par))
    netlist, ram_lib = synth / "mcadsw_engine_sta.v", synth / "mcadsw_ram.lib"
    for p in (netlist, ram_lib, synth / "summary.json"):
        if not p.is_file():
            raise FlowError(f"no {p.name} in {synth}: run make synth"
                            f"{'' if not suffix else f' DMAX={args.dmax} PAR={args.par}'} first")
    # Instance prefix of the flat netlist (u_<block>, the engine's own cells: top) -> the
    # groups `make synth` reports.
    # Each instance's group: u_<label>, and every instance of a block's module that has several
    # (one synthesised block serves every instance of its module), named in blocks.json.
    groups = {label: b["group"] for label, b in json.loads((synth / "summary.json").read_text())["blocks"].items()}
    group_of = {("top" if label == "top" else "u_" + label): g for label, g in groups.items()}
    if (synth / "blocks.json").is_file():
        for b in json.loads((synth / "blocks.json").read_text()):
            group_of.update({n: groups[b["label"]] for n in b["instance_names"]})

    # 1-2. Ports recorded by the RTL, activity of the netlist, the whole CIF frame's cycles.
    act_dir = Path(args.activity) if args.activity else out
    files = {m: act_dir / f"{m}.frame.txt" for m in MODES}
    files["idle"] = act_dir / "raw.idle.txt"
    if args.activity:
        for p in list(files.values()) + [act_dir / f"{m}.cycles" for m in MODES]:
            if not p.is_file():
                raise FlowError(f"no activity file {p} (run make power without --activity first)")
    else:
        sim, act = harness(args, out)
        log(f"recording the RTL core's ports: Teddy CIF crop {CROP}, D = {d}, raw and LR")
        jobs = []
        for m, flags in MODES.items():
            jobs.append((f"RTL {m} crop", [str(sim), str(LEFT), str(RIGHT), "-d", str(d), "--crop", CROP, *flags,
                                           "--record-ports", str(out / f"{m}.ports.txt")], out / f"{m}.rtl.log"))
        run_jobs(jobs, out)
        log("netlist activity (mcadsw_activity: every output compared with the RTL's every cycle), "
            "and the whole CIF frame's cycles on the RTL")
        jobs = []
        for m in MODES:
            hold = ["--hold", str(IDLE_CYCLES)] if m == "raw" else []
            jobs.append((f"activity {m}", [str(act), str(netlist), str(out / f"{m}.ports.txt"), str(out / m), *hold],
                         out / f"{m}.activity.log"))
        for m, flags in MODES.items():
            jobs.append((f"RTL {m} CIF frame", [str(sim), str(LEFT), str(RIGHT), "-d", str(d), *flags],
                         out / f"{m}.cif.log"))
        run_jobs(jobs, out)
        for m in MODES:
            (out / f"{m}.cycles").write_text(f"{cycles_of(out / f'{m}.cif.log')}\n")
            (out / f"{m}.ports.txt").unlink()   # large; the activity files keep what counts
    for p in files.values():
        if not p.is_file():
            raise FlowError(f"no activity file {p}")
    if shutil.which(args.sta) is None:
        raise FlowError(f"OpenSTA ({args.sta}) not found (make bootstrap installs it)")
    lib = liberty_facts(args.liberty)

    # 3. OpenSTA, at the clock of constraints/mcadsw.sdc (the one place it is set).
    period = float(re.search(r"^set period\s+(\S+)", (CON / "mcadsw.sdc").read_text(), re.M).group(1))
    freq_mhz = 1000.0 / period
    runs = [("raw", files["raw"], 1), ("raw_half_clock", files["raw"], 2), ("lr", files["lr"], 1),
            ("idle", files["idle"], 1)]
    res = out / "power_sta.txt"
    view, gates_file = out / "netlist_power_view.v", out / "clock_gates.txt"
    gated_cap = power_view(netlist, view, gates_file, lib["pin_cap"])
    log(f"OpenSTA: each cell at the activity of the nets it drives, by block ({len(gated_cap)} clock gates)")
    env = {"LIBERTY": args.liberty, "RAM_LIB": str(ram_lib), "NETLIST": str(view), "GATES": str(gates_file),
           "PERIOD_NS": f"{period:.6f}",
           "RUNS": " ".join("{%s %s %d}" % (n, f, k) for n, f, k in runs), "OUT": str(res)}
    t0 = time.time()
    r = subprocess.run([args.sta, "-no_splash", "-exit", str(FLOW / "power.tcl")], env={**os.environ, **env},
                       capture_output=True, text=True)
    (out / "sta.log").write_text(r.stdout + r.stderr)
    if r.returncode != 0 or "Error" in r.stdout + r.stderr:
        raise FlowError(f"OpenSTA failed (log {out}/sta.log):\n" + indent(tail(out / "sta.log", 15)))
    log(f"  OpenSTA done in {int(time.time() - t0)} s")
    ((nets, cells), gated), sta = read_results(res)
    view.unlink()   # 66 MB; power_view() writes it again

    # 4. Figures.
    vdd, f_hz = lib["vdd"], freq_mhz * 1e6
    flops = {"DFFPOSX1": 0, "DFFSR": 0}
    for line, cell, _, _ in connections(netlist):
        if cell in flops and CELL_LINE.match(line):
            flops[cell] += 1
    loads, clk_pins = net_loads(netlist, lib["pin_cap"])
    clk_cap = loads["clk_i"]
    clk_net_w = clk_cap * vdd * vdd * f_hz
    summary = {"clock_mhz": round(freq_mhz, 3), "vdd": vdd, "liberty": args.liberty, "netlist": str(netlist),
               "crop": CROP, "disparities": d, "netlist_nets": nets, "netlist_cells": cells,
               "flip_flops": flops, "clock_gating": gated,
               "clock_port_pins": {f"{c}/{p}": n for (c, p), n in sorted(clk_pins.items())},
               "clock_port_pf": clk_cap * 1e12, "memory_model": MEM_MODEL, "runs": {}}
    groups_all = sorted(set(group_of.values()))
    for net in ["clk_i"] + list(gated_cap):
        loads.pop(net, None)
    for name, run in sta.items():
        mode = "raw" if name.startswith("raw") else name
        cycles, macros = read_macros(files[mode])
        mem_w = 0.0
        mem_leak = 0.0
        mem_by_group = {}
        for mc in macros:
            er, ew = macro_energy(mc["words"], mc["bits"], vdd)
            w = (mc["reads"] * er + mc["writes"] * ew) / cycles * f_hz / run["period_ns"] * period
            leak = mc["words"] * mc["bits"] * 2 * lib["inv_leak"]
            mem_w += w
            mem_leak += leak
            blk = mc["name"].split(".")[0] if "." in mc["name"] else "top"
            g = group_of.get(blk)
            if g is None:
                raise FlowError(f"memory {mc['name']}: instance prefix {blk} is no block of {synth}/summary.json")
            mem_by_group[g] = mem_by_group.get(g, 0.0) + w + leak
        internal, switching, leakage, _ = run["total"]
        clk = clk_net_w * period / run["period_ns"]
        # Gated clock nets: C V^2 f r, r = the net's transitions / 2 a cycle.
        acts = net_activity(files[mode], gated_cap)
        gclk = sum(c * vdd * vdd * f_hz * acts[n] / 2 for n, c in gated_cap.items()) * period / run["period_ns"]
        by_group = {g: {"logic_w": 0.0, "memory_w": mem_by_group.get(g, 0.0)} for g in groups_all}
        for (blk, kind), v in run["blocks"].items():
            g = group_of.get(blk)
            if g is None:
                raise FlowError(f"instance prefix {blk} is no block of {synth}/summary.json")
            by_group[g]["logic_w"] += v[3]
        total = internal + switching + leakage + clk + gclk + mem_w + mem_leak
        # Cross-check of OpenSTA's switching: 1/2 C V^2 a f over every net's pin loads.
        acts = net_activity(files[mode], loads)
        sw_check = sum(0.5 * c * vdd * vdd * acts[n] * f_hz for n, c in loads.items()) * period / run["period_ns"]
        summary["runs"][name] = {
            "period_ns": run["period_ns"], "cycles_simulated": cycles,
            "annotated_cells": run["annotated_cells"], "nets_without_activity": run["missing_nets"],
            "annotated_fraction": run["annotated_cells"] / cells,
            "logic_internal_w": internal, "logic_switching_w": switching, "logic_leakage_w": leakage,
            "sequential_w": run["sequential"][3], "combinational_w": run["combinational"][3],
            "switching_from_pin_loads_w": sw_check,
            "clock_net_w": clk, "gated_clock_nets_w": gclk, "memory_dynamic_w": mem_w, "memory_leakage_w": mem_leak,
            "flip_flop_clock_pins_w": run["clock_pins_w"], "gating_correction_w": run["gating_correction_w"],
            "memory_accesses": {mc["name"]: [mc["reads"], mc["writes"]] for mc in macros},
            "total_w": total, "dynamic_w": total - leakage - mem_leak, "by_group": by_group}

    # Checks: a frame costs more than idling; twice the period, half the dynamic power.
    raw, half, idle = summary["runs"]["raw"], summary["runs"]["raw_half_clock"], summary["runs"]["idle"]
    if not raw["total_w"] > idle["total_w"]:
        raise FlowError(f"check failed: the busy engine ({raw['total_w']:.4f} W) does not exceed the idle one "
                        f"({idle['total_w']:.4f} W)")
    ratio = half["dynamic_w"] / raw["dynamic_w"]
    if abs(ratio - 0.5) > 0.005:
        raise FlowError(f"check failed: at half the clock the dynamic power is {ratio:.4f} of it, not 0.5")
    for name, run in summary["runs"].items():
        if run["annotated_fraction"] < 0.999:
            raise FlowError(f"{name}: only {run['annotated_fraction']:.1%} of the cells found their nets' activity in "
                            f"the simulation ({run['nets_without_activity']} nets without)")
    # OpenSTA's switching against 1/2 C V^2 a f over the nets' pin loads (the figure
    # an activity that does not reach the cells would miss: pin annotation once gave
    # a third of it).
    sw_dev = {}
    for name in ("raw", "lr"):
        run = summary["runs"][name]
        sw_dev[name] = run["logic_switching_w"] / run["switching_from_pin_loads_w"] - 1
        if abs(sw_dev[name]) > 0.05:
            raise FlowError(f"check failed: {name}: OpenSTA's switching power {run['logic_switching_w'] * 1e3:.1f} mW is "
                            f"not within 5 % of the nets' 1/2 C V^2 a f {run['switching_from_pin_loads_w'] * 1e3:.1f} mW")
    summary["checks"] = {"busy_over_idle": raw["total_w"] / idle["total_w"], "half_clock_dynamic_ratio": ratio,
                         "switching_vs_pin_loads": sw_dev}
    # The clock, told apart: the flip-flops' clock pins in the raw frame (their power
    # when no data moves, scaled by their gate's open fraction), the net of clk_i and
    # the gated clock nets (the gates' own latches and inverters are in the logic).
    clock_w = raw["flip_flop_clock_pins_w"] + raw["clock_net_w"] + raw["gated_clock_nets_w"]
    summary["clock"] = {"flip_flop_clock_pins_w": raw["flip_flop_clock_pins_w"], "clock_net_w": raw["clock_net_w"],
                        "gated_clock_nets_w": raw["gated_clock_nets_w"], "total_w": clock_w,
                        "share_of_raw_frame": clock_w / raw["total_w"]}

    # Energy per CIF frame, pixel and disparity evaluation (the crop's mean power over the
    # whole frame's cycles, measured on the RTL); scaled to 90 nm / 1.0 V.
    scale = (0.09 / 0.18) * (1.0 / vdd) ** 2
    summary["scaling_rule"] = ("dynamic energy C V^2 with C proportional to the feature size: x (90/180) x "
                               f"(1.0/{vdd})^2 = {scale:.3f}; leakage not scaled (an estimate)")
    summary["frames"] = {}
    for mode in MODES:
        cycles = int((act_dir / f"{mode}.cycles").read_text())
        run = summary["runs"][mode]
        t = cycles / f_hz
        e = run["total_w"] * t
        e_dyn = run["dynamic_w"] * t
        passes = 2 if mode == "lr" else 1
        px = CIF[0] * CIF[1]
        summary["frames"][mode] = {
            "cif_cycles": cycles, "fps": f_hz / cycles, "energy_j": e, "energy_per_pixel_j": e / px,
            "energy_per_disparity_evaluation_j": e / (px * d * passes), "disparity_passes": passes,
            "energy_90nm_estimate_j": e_dyn * scale, "energy_per_pixel_90nm_estimate_j": e_dyn * scale / px,
            "power_90nm_estimate_w": run["dynamic_w"] * scale}
    summary["seconds"] = int(time.time() - t_start)
    (out / "summary.json").write_text(json.dumps(summary, indent=2) + "\n")
    write_report(out, summary)
    log(f"summary {out}/summary.json, report {out}/report.md ({summary['seconds']} s)")
    for mode in MODES:
        fr, rn = summary["frames"][mode], summary["runs"][mode]
        log(f"  {mode}: {rn['total_w'] * 1e3:.1f} mW at {freq_mhz:.1f} MHz, {fr['energy_j'] * 1e3:.2f} mJ a CIF frame "
            f"at D = {d}, {fr['energy_per_pixel_j'] * 1e9:.1f} nJ a pixel")
    log(f"  idle (configured, not started): {idle['total_w'] * 1e3:.1f} mW")


def write_report(out, s):
    mw = lambda w: f"{w * 1e3:.1f}" if w >= 1e-3 or w == 0 else f"{w * 1e3:.3f}"  # noqa: E731
    r = s["runs"]
    lines = [
        "# Power of the engine (`make power`)", "",
        f"OSU 0.18 um, {s['vdd']} V, {s['clock_mhz']:g} MHz; activity of a Teddy CIF crop ({s['crop']}) at "
        f"D = {s['disparities']} simulated on the netlist (each of {r['raw']['annotated_cells']} of "
        f"{s['netlist_cells']} cells evaluated at the simulated activity of the nets it drives, "
        f"{r['raw']['nets_without_activity']} nets without; every output equal to the RTL's in "
        "every cycle). Zero-delay activity: glitches are not counted.", "",
        "| mW | raw frame | LR frame | idle (configured, not started) |", "|---|---|---|---|"]
    rows = [("logic, internal (OpenSTA)", "logic_internal_w"), ("logic, switching (OpenSTA)", "logic_switching_w"),
            ("logic, leakage (OpenSTA)", "logic_leakage_w"), ("  of it sequential (flip-flops)", "sequential_w"),
            ("  of it combinational", "combinational_w"), ("clock net of clk_i (C V^2 f of its pins)", "clock_net_w"),
            ("gated clock nets (C V^2 f r)", "gated_clock_nets_w"),
            ("memories, dynamic (model)", "memory_dynamic_w"), ("memories, leakage (model)", "memory_leakage_w"),
            ("**total**", "total_w")]
    for label, key in rows:
        lines.append(f"| {label} | {mw(r['raw'][key])} | {mw(r['lr'][key])} | {mw(r['idle'][key])} |")
    lines += ["", "By block (logic from OpenSTA, memories from the model), mW:", "",
              "| block | raw logic | raw memories | LR logic | LR memories | idle |", "|---|---|---|---|---|---|"]
    for g in sorted(r["raw"]["by_group"]):
        a, b, c = r["raw"]["by_group"][g], r["lr"]["by_group"][g], r["idle"]["by_group"][g]
        lines.append(f"| {g} | {mw(a['logic_w'])} | {mw(a['memory_w'])} | {mw(b['logic_w'])} | {mw(b['memory_w'])} "
                     f"| {mw(c['logic_w'] + c['memory_w'])} |")
    lines += ["", f"Energy of a CIF frame (352 x 288) at D = {s['disparities']}: the crop's mean power over the frame's cycles "
              "(measured on the RTL core):", "",
              "| mode | cycles | fps | mJ a frame | nJ a pixel | pJ a disparity evaluation | 90 nm / 1.0 V estimate, nJ a pixel |",
              "|---|---|---|---|---|---|---|"]
    for mode, f in s["frames"].items():
        lines.append(f"| {mode} | {f['cif_cycles']} | {f['fps']:.1f} | {f['energy_j'] * 1e3:.2f} | "
                     f"{f['energy_per_pixel_j'] * 1e9:.1f} | {f['energy_per_disparity_evaluation_j'] * 1e12:.1f} | "
                     f"{f['energy_per_pixel_90nm_estimate_j'] * 1e9:.2f} |")
    c = s["clock"]
    g = s["clock_gating"]
    gating = (f"{g['flip_flops']} of {sum(s['flip_flops'].values())} flip-flops are behind {g['gates']} clock gates (flow/clock_gate.py); "
              f"OpenSTA's figure for the cells on gated clocks was lowered by {mw(r['raw']['gating_correction_w'])} mW "
              f"(raw), {mw(r['idle']['gating_correction_w'])} mW (idle) to the fraction of cycles their gate opened"
              if g["gates"] else "no flip-flop is clock-gated (CLOCK_GATE_MIN=0)")
    lines += ["", f"The clock: {mw(c['flip_flop_clock_pins_w'])} mW in the flip-flops' clock pins (raw frame; "
              f"idle {mw(r['idle']['flip_flop_clock_pins_w'])} mW), {mw(c['clock_net_w'])} mW in the net of clk_i "
              f"({s['clock_port_pf']:.1f} pF) and {mw(c['gated_clock_nets_w'])} mW in the gated clock nets, "
              f"{c['share_of_raw_frame']:.0%} of the raw frame's power; {gating}."]
    lines += ["", f"Checks: the raw frame's power is {s['checks']['busy_over_idle']:.2f} x the idle power; at half "
              f"the clock the dynamic power is {s['checks']['half_clock_dynamic_ratio']:.4f} of it; OpenSTA's "
              f"switching is within {max(abs(v) for v in s['checks']['switching_vs_pin_loads'].values()):.1%} of "
              "1/2 C V^2 a f over the nets' pin loads (raw, LR).", "",
              f"Memory model: {s['memory_model']}.", "", f"Scaling: {s['scaling_rule']}.", ""]
    (out / "report.md").write_text("\n".join(lines))


if __name__ == "__main__":
    try:
        main()
    except FlowError as e:
        print(f"power: {e}", file=sys.stderr)
        sys.exit(e.code)
    except KeyboardInterrupt:
        sys.exit(130)
