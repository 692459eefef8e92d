"""The rectifier (issue 32, rtl/rect/), mapped and timed apart from the engine
(flow/synth.py, step 5b; reused when unchanged): the pass mcadsw_rect, the mark step
mcadsw_rect_mark and the configuration check mcadsw_rect_check, each elaborated alone (flow/rect_elab.tcl), mapped exactly as
an engine block is (flow/synth_block.tcl: memories as MCADSW_RAM macros, clock
gating, OSU 0.18 um cells, ABC with the buffering script), prepared for OpenSTA as
the engine's netlist is (flow/sta_netlist.tcl, a generated macro liberty) and timed
alone at the SDC's clock (flow/sta_alone.tcl, as the SoC wrapper's blocks). The issue's budget is for them
together: constraints/budget.json rect_nand2_eq_max, rect_memory_kB_max."""
import json
import re
import sys
from pathlib import Path

from blocks import area_figures, block_outputs, read_table
from flowlib import CON, FLOW, RAM_MODEL, ROOT, FlowError, indent, log, reusable, stamp_of, tail
from sta import sta_netlist

MODULES = ("mcadsw_rect", "mcadsw_rect_mark", "mcadsw_rect_check")


def rect_files():
    """The rectifier's files (rtl/rect/rect.f), absolute paths, its package first."""
    d = ROOT / "rtl" / "rect"
    return [d / ln.split("//")[0].strip() for ln in (d / "rect.f").read_text().splitlines()
            if ln.split("//")[0].strip()]


def synth_rect(run, out, rtl, pkg, pkg_text, yosys, yosys_version, lib, period_ns, period_ps, nand2_area,
               gate_min):
    """Returns {module: {nand2_eq, flip_flops, memory_bits, async_read_macros, worst_slack_ns,
    gated_flip_flops}}."""
    top_dir = out / "rect"
    top_dir.mkdir(exist_ok=True)
    files = rect_files()
    flow_files = [FLOW / "rect.py", FLOW / "rect_elab.tcl", FLOW / "synth_block.tcl", FLOW / "clock_gate.py",
                  FLOW / "sta_netlist.tcl", FLOW / "sta_alone.tcl", FLOW / "sta.py", CON / "macro_map.v",
                  CON / "abc_osu018.constr", CON / "abc_osu018.script", CON / "mcadsw_ram_timing.cfg",
                  RAM_MODEL, Path(lib)]
    res = {}
    for m in MODULES:
        d = top_dir / m
        d.mkdir(exist_ok=True)
        stamp = stamp_of(yosys_version, pkg_text, f"period {period_ns} clock gate min {gate_min} module {m}\n",
                         rtl / "mcadsw_fifo.sv", *files, *flow_files)
        outs = [d / f for f in ("area.txt", "memories.txt", "sta.log")]
        if reusable(d / "stamp", stamp, outs):
            log(f"rectifier: {m} unchanged, reused ({d})")
        else:
            log(f"rectifier: {m} mapped and timed apart from the engine ({d})")
            for f in outs + [d / "netlist.v.tmp", d / "clock_gates.json"]:
                f.unlink(missing_ok=True)
            rc, _, _ = run.run([yosys, "-q", "-l", str(d / "elab.log"), "-c", str(FLOW / "rect_elab.tcl")],
                               err_path=d / "elab.err",
                               env={"TOP": m, "PKG": str(pkg), "RTL_DIR": str(rtl),
                                    "RTL_MODULES": " ".join(str(f) for f in files), "RAM_MODEL": str(RAM_MODEL),
                                    "OUT_IL": str(d / "elab.il")})
            if rc != 0:
                sys.stderr.write(indent(tail(d / "elab.log", 10) or tail(d / "elab.err", 10)))
                raise FlowError(f"elaboration of {m} failed (log: {d}/elab.log)")
            rc, _, _ = run.run([yosys, "-q", "-l", str(d / "yosys.log"), "-c", str(FLOW / "synth_block.tcl")],
                               err_path=d / "yosys.err",
                               env={"MODULE": m, "ELAB_IL": str(d / "elab.il"), "OUT_DIR": str(d),
                                    "BLACKBOXES": "", "PERIOD_PS": str(period_ps), "LIBERTY": lib,
                                    "CONSTRAINTS": str(CON), "CLOCK_GATE_MIN": str(gate_min)})
            if rc != 0 or not (d / "netlist.v.tmp").is_file():
                sys.stderr.write(indent(tail(d / "yosys.log", 20)))
                raise FlowError(f"synthesis of {m} failed (log: {d}/yosys.log)")
            block_outputs(m, d)
            (d / "netlist.v.tmp").rename(d / "netlist.v")
            rc, _, _ = run.run([yosys, "-q", "-l", str(d / "sta_netlist.log"), "-c", str(FLOW / "sta_netlist.tcl")],
                               err_path=d / "sta_netlist.err",
                               env={"RAM_MODEL": str(RAM_MODEL), "LIBERTY": lib, "NETLIST": str(d / "netlist.v"),
                                    "OUT_V": str(d / "flat.v"), "TOP": m})
            if rc != 0:
                sys.stderr.write(indent(tail(d / "sta_netlist.log", 20)))
                raise FlowError(f"preparing the STA netlist of {m} failed (log: {d}/sta_netlist.log)")
            sta_netlist(d / "flat.v", d, CON / "mcadsw_ram_timing.cfg", top=m)
            (d / "flat.v").unlink()
            rc, _, _ = run.run(["sta", "-no_splash", "-exit", str(FLOW / "sta_alone.tcl")],
                               out_path=d / "sta.log", err_path=d / "sta.err",
                               env={"LIBERTY": lib, "RAM_LIB": str(d / "mcadsw_ram.lib"),
                                    "NETLIST": str(d / f"{m}_sta.v"), "MODULE": m, "PERIOD_NS": period_ns})
            slog = (d / "sta.log").read_text(errors="replace")
            if rc != 0 or not re.search(r"^worst slack", slog, re.M):
                sys.stderr.write(indent(slog.splitlines()[-20:] + tail(d / "sta.err", 5)))
                raise FlowError(f"OpenSTA gave no worst slack for {m} ({d}/sta.log)")
            (d / "stamp").write_text(stamp + "\n")
        nand, ff = area_figures(d / "area.txt", m, nand2_area)
        mems = read_table(d / "memories.txt")
        slog = (d / "sta.log").read_text(errors="replace")
        slack = float([ln.split()[-1] for ln in slog.splitlines() if ln.startswith("worst slack")][-1])
        cg = json.loads((d / "clock_gates.json").read_text()) if gate_min else {}
        res[m] = {"nand2_eq": nand, "flip_flops": ff, "memory_bits": sum(int(x[4]) for x in mems),
                  "memory_macros": len(mems), "async_read_macros": sum(1 for x in mems if x[7] != "sync"),
                  "worst_slack_ns": slack, "gated_flip_flops": cg.get("gated_flops", 0)}
        log(f"  {m}: {nand} NAND2 eq, {ff} flip-flops, {res[m]['memory_bits']} memory bits, "
            f"worst slack {slack} ns")
    return res
