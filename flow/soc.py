# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

"""The SoC wrapper around the engine (mcadsw_top: the AXI4-Lite register block
and the AXI4 master), mapped alone by flow/soc.tcl and timed by
flow/sta_alone.tcl (flow/synth.py, step 5; about 20 s, reused when unchanged)."""
import re
import sys
from pathlib import Path

from blocks import area_figures
from flowlib import CON, FLOW, FlowError, indent, log, reusable, stamp_of, tail

MODULES = ("mcadsw_regs", "mcadsw_axi_master")


def synth_soc(run, out, rtl, pkg, pkg_text, dmax, par, yosys, yosys_version, lib, period_ns, period_ps,
              nand2_area):
    """Returns ({module: NAND2 eq}, the worse of the two worst slacks in ns)."""
    soc = out / "soc"
    soc.mkdir(exist_ok=True)
    soc_nand, soc_slack = {}, None
    socs = MODULES
    soc_stamp = stamp_of(yosys_version, pkg_text, f"DMAX {dmax} PAR {par} period {period_ns}\n",
                         *[rtl / f"{m}.sv" for m in socs], FLOW / "soc.tcl", FLOW / "sta_alone.tcl",
                         CON / "abc_osu018.constr", CON / "abc_osu018.script", Path(lib))
    soc_reused = reusable(soc / "stamp", soc_stamp, [soc / f for m in socs
                                                     for f in (f"{m}_area.txt", f"{m}.v", f"sta_{m}.log")])
    if soc_reused:
        log(f"SoC wrapper unchanged, reused ({soc})")
    else:
        (soc / "sta.log").write_text("")
        rc, _, _ = run.run([yosys, "-q", "-l", str(soc / "yosys.log"), "-c", str(FLOW / "soc.tcl")],
                           err_path=soc / "yosys.err",
                           env={"PKG": str(pkg), "RTL_DIR": str(rtl), "DMAX": str(dmax), "PAR": str(par),
                                "OUT_DIR": str(soc), "PERIOD_PS": str(period_ps), "LIBERTY": lib,
                                "CONSTRAINTS": str(CON)})
        if rc != 0:
            sys.stderr.write(indent(tail(soc / "yosys.log", 10)))
            raise FlowError(f"the SoC wrapper's synthesis failed (log: {soc}/yosys.log)", 2)
        for m in socs:
            rc, _, _ = run.run(["sta", "-no_splash", "-exit", str(FLOW / "sta_alone.tcl")],
                               out_path=soc / f"sta_{m}.log", err_path=soc / f"sta_{m}.err",
                               env={"LIBERTY": lib, "NETLIST": str(soc / f"{m}.v"), "MODULE": m,
                                    "PERIOD_NS": period_ns})
            slog = (soc / f"sta_{m}.log").read_text(errors="replace")
            with open(soc / "sta.log", "a") as f:
                f.write(f"== {m}\n{slog}")
            if rc != 0 or not re.search(r"^worst slack", slog, re.M):
                raise FlowError(f"the SoC wrapper's synthesis failed: no slack from OpenSTA for {m} "
                                f"({soc}/sta.log)", 2)
        (soc / "stamp").write_text(soc_stamp + "\n")
    for m in socs:
        soc_nand[m], _ = area_figures(soc / f"{m}_area.txt", m, nand2_area)
        slog = (soc / f"sta_{m}.log").read_text(errors="replace")
        sl = float([ln.split()[-1] for ln in slog.splitlines() if ln.startswith("worst slack")][-1])
        soc_slack = sl if soc_slack is None else min(soc_slack, sl)
    return soc_nand, soc_slack
