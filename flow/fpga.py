# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

"""make fpga: an FPGA estimate of the design by Yosys synth_xilinx (flow/fpga.tcl),
run by flow/synth.py fpga."""
import json
import re
import shutil
import sys
import time
from pathlib import Path

from flowlib import FLOW, FlowError, Run, gen_package, log, rtl_list, tail


def fpga(a):
    """An FPGA estimate: Yosys synth_xilinx for a 7-series part
    (flow/fpga.tcl) maps the top to LUTs, flip-flops, block RAMs (RAMB18E1 /
    RAMB36E1), LUT RAMs and DSP48E1s; the counts go to summary.json and report.md
    with whether they fit an XC7Z020 and an XC7A100T. No timing: nextpnr-xilinx is
    not packaged (place and route would be needed for a clock figure)."""
    if a.out:
        for f in ("summary.json", "report.md"):
            (Path(a.out) / f).unlink(missing_ok=True)
    pkg_text = gen_package(a.gen_rtl_pkg, a.dmax, a.par)
    name = "fpga" if (a.dmax, a.par) == ("64", "1") else f"fpga_dmax{a.dmax}_par{a.par}"
    out = Path(a.out or Path(a.build) / name).resolve()
    (out / "rtl").mkdir(parents=True, exist_ok=True)
    for f in ("summary.json", "report.md"):
        (out / f).unlink(missing_ok=True)
    if not shutil.which(a.yosys):
        raise FlowError(f"'{a.yosys}' not found in PATH (run scripts/bootstrap.sh, or make fpga, which runs it)", 2)
    pkg = out / "rtl" / "mcadsw_pkg.sv"
    pkg.write_text(pkg_text)
    rtl = Path(a.rtl).resolve()
    log(f"synth_xilinx -family xc7 of {a.top} (DMAX={a.dmax}, PAR={a.par}); log {out}/yosys.log")
    t0 = time.time()
    run = Run()
    try:
        rc, _, _ = run.run([a.yosys, "-q", "-l", str(out / "yosys.log"), "-c", str(FLOW / "fpga.tcl")],
                           err_path=out / "yosys.err",
                           env={"PKG": str(pkg), "TOP": a.top, "OUT_DIR": str(out), "RTL_DIR": str(rtl),
                                "RTL_MODULES": " ".join(str(rtl / f) for f in rtl_list(no_pkg=True))})
    finally:
        run.stop()
    if rc != 0:
        errs = [ln for f in ("yosys.log", "yosys.err") for ln in tail(out / f, 10**6) if "ERROR" in ln]
        sys.stderr.write("".join(ln + "\n" for ln in (errs[:3] or tail(out / "yosys.err", 5))))
        raise FlowError(f"synth_xilinx failed (log {out}/yosys.log)", 2)
    secs = int(time.time() - t0)
    # Cell counts of the design (synth_xilinx flattens it: the last "=== ... ===" block).
    cells = {}
    for line in (out / "stat.txt").read_text().splitlines():
        w = line.split()
        if re.fullmatch(r"=== .* ===", line.strip()):
            cells = {}
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
    summary = {"top": a.top, "dmax": int(a.dmax), "par": int(a.par), "family": "xc7", "lut": lut,
               "lut_logic": lut_logic, "lut_memory": lut_mem, "ff": ff, "bram36_equivalent": bram,
               "ramb36e1": bram36, "ramb18e1": bram18, "dsp48e1": dsp, "carry4": carry, "yosys_seconds": secs,
               **fits}
    report = [f"# FPGA estimate (`make fpga`, {a.top}, DMAX = {a.dmax}, PAR = {a.par})", "",
              f"Yosys `synth_xilinx -family xc7` ({secs} s); no place and route, so no clock figure.", "",
              "| resource | count |", "|---|---|",
              f"| LUTs (logic + memory / shift registers) | {lut} ({lut_logic} + {lut_mem}) |",
              f"| flip-flops | {ff} |", f"| block RAM (36 Kb equivalents) | {bram} ({bram36} RAMB36E1, {bram18} RAMB18E1) |",
              f"| DSP48E1 | {dsp} |", "", "| device | fits | use |", "|---|---|---|"]
    report += [f"| {d} | {'yes' if f['fits'] else 'no'} | {f['use']} |" for d, f in fits.items()]
    (out / "summary.json").write_text(json.dumps(summary, indent=2) + "\n")
    (out / "report.md").write_text("\n".join(report) + "\n")
    print("\n".join(report))
    log(f"summary {out}/summary.json")

