# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

"""The engine's blocks (flow/synth.py, steps 1 and 2): listed from the elaborated
RTLIL and renamed, each synthesised on its own by flow/synth_block.tcl (reused
when its stamp is unchanged), their outputs read, their figures and their group
of the paper's Fig. 16."""
import hashlib
import json
import re
import subprocess
import sys
from pathlib import Path

from flowlib import CON, FLOW, RAM_MODEL, FlowError, indent, log, tail

# Part of every block's stamp: change it when the block listing or renaming
# below changes what a block's netlist is.
STAMP_SALT = "blocks v1"


# ---- Block listing (the elaborated RTLIL) ----------------------------------------------------
def list_blocks(il_text):
    """Modules of the elaborated design (RTLIL written after hierarchy -check -top
    mcadsw_engine): each distinct module type the top instantiates is a block,
    renamed mcadsw_<instance name without u_>; the top keeps mcadsw_engine.
    Returns (blocks, renamed RTLIL); each block: label, module, instances,
    instance_names (the top's instances of it, as the flattened STA netlist prefixes
    their cells: u_post.<cell>; none for the top), base
    (its HDL module), files (its and its sub-modules' source files), weight (RTLIL
    lines of it and its sub-modules: a size estimate for the first schedule) and
    sig (its module names and parameters; for the top the ports of the blocks)."""
    lines = il_text.splitlines()
    mods, order_mods, pend, top, mod = {}, [], {}, None, None
    for line in lines:
        w = line.split()
        if line.startswith("attribute "):
            pend[w[1]] = w[2] if len(w) > 2 else ""
            continue
        if line.startswith("module "):
            mod = w[1]
            m = mods[mod] = {"src": "", "hdl": None, "bb": "\\blackbox" in pend, "par": "", "cells": [],
                             "ports": "", "nl": 0}
            order_mods.append(mod)
            if "\\src" in pend:
                m["src"] = pend["\\src"].strip('"').split(":")[0]
            if "\\hdlname" in pend:
                m["hdl"] = pend["\\hdlname"].strip('"').lstrip("\\")
            if "\\top" in pend:
                top = mod
            pend = {}
            continue
        if mod is None:
            continue
        if line.startswith("  parameter "):
            mods[mod]["par"] += f" {w[1]}={w[2] if len(w) > 2 else ''}"
        elif line.startswith("  cell "):
            mods[mod]["cells"].append((w[1], w[2]))
        elif line.startswith("  wire ") and re.search(r" (input|output|inout) ", line):
            mods[mod]["ports"] += line + "\n"
        elif line == "end":
            mod = None
        else:
            mods[mod]["nl"] += 1
    if top is None:
        raise FlowError("could not list the blocks of the elaborated design: no top module")

    def is_sub(t):
        return t in mods and not mods[t]["bb"]

    def base_of(m):
        return mods[m]["hdl"] or m[1:]

    memo = {}

    def weight(m):
        if m not in memo:
            memo[m] = mods[m]["nl"] + sum(weight(t) for t, _ in mods[m]["cells"] if is_sub(t) and t != m)
        return memo[m]

    newname, label, inst, names, order, used = {top: "\\mcadsw_engine"}, {}, {}, {}, [], set()
    for t, name in mods[top]["cells"]:
        if not is_sub(t):
            continue
        names.setdefault(t, []).append(name.lstrip("\\"))
        if t in label:
            inst[t] += 1
            continue
        lab = re.sub(r"[^A-Za-z0-9_]", "_", re.sub(r"^u_", "", name.lstrip("\\")))
        if lab == "top" or lab in used:
            k = 2
            while f"{lab}_{k}" in used:
                k += 1
            lab = f"{lab}_{k}"
        used.add(lab)
        label[t], inst[t] = lab, 1
        order.append(t)
        n = "\\mcadsw_" + lab
        while n in mods and n != t:   # a name another module of the design has
            n += "_blk"
        newname[t] = n

    blocks = []
    for t in order + [top]:
        files, sig = set(), ""
        if t != top:
            seen = set()

            def subtree(m, depth):
                nonlocal sig
                if depth > 50:
                    raise FlowError(f"module hierarchy too deep at {m}")
                files.add(mods[m]["src"])
                sig += f"module {m} ({base_of(m)}){mods[m]['par']}\n"
                for c, _ in mods[m]["cells"]:
                    if is_sub(c) and (m, c) not in seen:
                        seen.add((m, c))
                        subtree(c, depth + 1)
            subtree(t, 0)
        else:
            files.add(mods[t]["src"])
            sig = f"module {t} ({base_of(t)}){mods[t]['par']}\n"
            for b in order:
                sig += f"ports of {newname[b][1:]}:\n{mods[b]['ports']}"
        blocks.append({"label": label.get(t, "top"), "module": newname[t][1:],
                       "instances": inst.get(t, 1), "instance_names": names.get(t, []), "base": base_of(t),
                       "files": sorted(f for f in files if f),
                       "weight": weight(t) if t != top else mods[t]["nl"],
                       "sig": f"renamed {newname[t][1:]}\n{sig}"})
    out = []
    for line in lines:
        w = line.split()
        if line.startswith("module ") and w[1] in newname:
            line = "module " + newname[w[1]]
        elif line.startswith("  cell ") and w[1] in newname:
            line = f"  cell {newname[w[1]]} {w[2]}"
        out.append(line)
    return blocks, "\n".join(out) + "\n"


# ---- What a block's Yosys run wrote ------------------------------------------------------
def block_outputs(module, d):
    """Reads a finished block's files: memories.txt and registers.txt written, the
    macro restrictions checked. Raises FlowError."""
    dump = (d / "memories_dump.txt").read_text()
    for line in dump.splitlines():
        if (re.search(r"connect .RD_SRST [^1]*[^']1", line) or re.search(r"connect .RD_SRST .[a-zA-Z]", line)
                or re.search(r"parameter .RD_TRANSPARENCY_MASK [0-9]+'[01]*1", line)):
            raise FlowError(f"a memory of {module} uses a synchronous read reset or a transparent read; "
                            f"MCADSW_RAM does not model it ({d}/memories_dump.txt)")
    names = [ln.split("/") for ln in (d / "memories_list.txt").read_text().splitlines() if "/" in ln]
    mems = []
    for line in dump.splitlines():
        w = line.split()
        if re.search(r"cell \$mem_v2", line):
            mems.append({})
        elif mems and len(w) >= 3 and w[0] == "parameter":
            key = w[1].lstrip("\\")
            if key in ("WIDTH", "SIZE", "RD_PORTS", "WR_PORTS"):
                mems[-1][key] = int(w[2])
            elif key == "RD_CLK_ENABLE":
                mems[-1][key] = re.sub(r"^[0-9]+'", "", w[2])
    if len(mems) != len(names):
        raise FlowError(f"memory count mismatch in {d}: {len(mems)} dumped, {len(names)} listed")
    with open(d / "memories.txt", "w") as f:
        for (mod, cell, *_), m in zip(names, mems):
            sync = "sync" if re.fullmatch(r"1+", m.get("RD_CLK_ENABLE", "")) else "async"
            f.write(f"{mod} {cell} {m['WIDTH']} {m['SIZE']} {m['WIDTH'] * m['SIZE']} {m['RD_PORTS']} "
                    f"{m['WR_PORTS']} {sync}\n")
    regs = []
    for line in (d / "registers_dump.txt").read_text().splitlines():
        w = line.split()
        if re.search(r"cell \$[a-z]*dff", line):
            regs.append(["?", 0])
        elif regs and re.search(r"parameter .WIDTH ", line):
            regs[-1][1] = int(w[2])
        elif regs and re.search(r"connect .Q ", line):
            regs[-1][0] = w[2][1:] if w[2].startswith("\\") else "(several)"
    with open(d / "registers.txt", "w") as f:
        for q, width in regs:
            f.write(f"{module} {q} {width}\n")


# The OSU 0.18 um liberty gives its LATCH (the clock gates of flow/clock_gate.py)
# area 0; its LEF gives the cell 5.6 x 10 um, i.e. 56 in the liberty's units
# (NAND2X1: 24, 2.4 x 10 um). `stat -liberty` counts it 0, so area_figures adds it.
LATCH_AREA = 56.0


def area_figures(area_txt, module, nand2_area):
    """(NAND2 eq, flip-flops) of module in a `stat -liberty` output (latches added
    at their LEF area)."""
    cur, ff, latches, area = None, 0, 0, 0.0
    for line in Path(area_txt).read_text().splitlines():
        w = line.split()
        if line.startswith("=== "):
            cur = w[1].lstrip("\\")
        elif cur == module and len(w) == 2 and w[0].startswith("DFF") and w[1].isdigit():
            ff += int(w[1])
        elif cur == module and len(w) == 2 and w[0] == "LATCH" and w[1].isdigit():
            latches += int(w[1])
        elif "Chip area for module" in line and re.sub(r"[^A-Za-z0-9_]", "", w[4]) == module:
            area = float(w[-1])
    return int((area + latches * LATCH_AREA) / nand2_area + 0.5), ff


def read_table(path):
    try:
        return [ln.split() for ln in Path(path).read_text().splitlines() if ln.strip()]
    except OSError:
        return []


# ---- Groups of the paper's Fig. 16 --------------------------------------------------------
# The rectifier (the pass, its mark step and its configuration check) is
# inside the engine but beyond the paper: its group is reported apart, with its own
# budget (constraints/budget.json rect_*), and kept out of the engine's totals.
RECT_GROUP = "rectifier"
GROUPS = {"mcadsw_weight_gen": "weight_generator", "mcadsw_cost_agg": "cost_aggregator_wta",
          "mcadsw_scheduler": "block_scheduler", "mcadsw_depth_fifo": "depth_fifo",
          "mcadsw_post": "post_stage", "mcadsw_post_check": "post_stage",
          "mcadsw_post_fill": "post_stage", "mcadsw_fifo": "post_stage", "mcadsw_engine": "top_registers_counters",
          "mcadsw_cfg_check": "top_registers_counters", "mcadsw_frame_ctrl": "top_registers_counters",
          "mcadsw_win_geom": "top_registers_counters", "mcadsw_pass_cfg": "top_registers_counters",
          "mcadsw_port_mux": "top_registers_counters", "mcadsw_clock_gate": "top_registers_counters",
          "mcadsw_fetch": "memory_controller", "mcadsw_rectifier": RECT_GROUP}
GROUP_NAMES = {
    "census_left": "census left (transformer + buffer)", "census_right": "census right (transformer + buffer)",
    "census_left_right": "census left + right (one module at this DMAX)",
    "weight_generator": "weight generator (+ weight buffers)", "cost_aggregator_wta": "cost aggregator + WTA",
    "memory_controller": "memory controller + window readers", "block_scheduler": "block scheduler",
    "depth_fifo": "depth FIFO", "top_registers_counters": "engine core: configuration, check, frame controller, counters, window geometry, port owners",
    "post_stage": "LR post stage (check, fill, median; beyond the paper)",
    RECT_GROUP: "rectifier (pass, mark step, configuration check; beyond the paper, apart from the engine's budgets)"}


def group_of(b):
    if b["base"] == "mcadsw_census":
        return ("census_left_right" if b["instances"] > 1 else
                "census_right" if b["label"].endswith("_r") else "census_left")
    return GROUPS.get(b["base"], "other")


def paper_share(g):
    if g == RECT_GROUP:
        return "not in the paper (reported apart)"
    if g in ("census_left", "census_right", "cost_aggregator_wta"):
        return "one of the three that dominate"
    return "two of the three that dominate" if g == "census_left_right" else "not given"



def synthesise(run, blocks, out, rtl, pkg_text, yosys, lib, period_ps, jobs, mem_mb, nand2_area, gate_min):
    """Step 2: each block whose stamp changed through flow/synth_block.tcl (the
    top's own logic with the blocks as black boxes), longest first, on run's
    pool; marks each block cached or not. Returns the Yosys version."""
    block_modules = [b["module"] for b in blocks if b["label"] != "top"]
    # Stamp: everything a block's netlist depends on. Sources: the files of the
    # block's module and sub-modules (src attributes of the elaborated design) and
    # the package; parameters and module names (for the top also the ports of the
    # blocks it instantiates); flow: the block script, the files it reads, the
    # clock gating's group size and the Yosys version.
    yosys_version = subprocess.run([yosys, "-V"], capture_output=True, text=True).stdout.strip()
    flow_files = [FLOW / "synth_block.tcl", FLOW / "clock_gate.py", CON / "macro_map.v", CON / "latch_map.v", CON / "abc_osu018.constr",
                  CON / "abc_osu018.script", Path(lib), RAM_MODEL]
    for b in blocks:
        h = hashlib.sha256(f"{STAMP_SALT}; yosys: {yosys_version}; period_ps {period_ps}; "
                           f"clock gate min {gate_min}\n{b['sig']}".encode())
        for f in b["files"]:
            h.update(f"== {f}\n".encode())
            h.update((rtl / f).read_bytes() if (rtl / f).is_file() else b"(missing)")
        h.update(b"== package\n" + pkg_text.encode())
        for f in flow_files:
            h.update(f"== {f.name}\n".encode() + f.read_bytes())
        b["stamp"] = h.hexdigest()
        d = out / "blocks" / b["label"]
        b["cached"] = ((d / "stamp").is_file() and (d / "stamp").read_text().strip() == b["stamp"]
                       and (d / "netlist.v").is_file() and (d / "netlist.v").stat().st_size > 0
                       and (d / "area.txt").is_file() and (d / "cost.json").is_file()
                       and (gate_min == 0 or (d / "clock_gates.json").is_file()))
        if not b["cached"]:
            (d / "stamp").unlink(missing_ok=True)
            # Estimates for the schedule: the last run's time and peak when known,
            # else the block's size in the elaborated RTLIL (sub-modules included).
            try:
                cost = json.loads((d / "cost.json").read_text())
                b["est_s"], b["est_mb"] = cost["seconds"], cost["peak_MB"]
            except (OSError, ValueError, KeyError):
                b["est_s"], b["est_mb"] = b["weight"] // 1000, 0
    queue = sorted((b for b in blocks if not b["cached"]), key=lambda b: -b["est_s"])
    cached = [b["label"] for b in blocks if b["cached"]]
    log(f"{len(blocks)} blocks (the top's own logic included); {len(cached)} unchanged since their last "
        f"synthesis{' (' + ' '.join(cached) + ')' if cached else ''}, {len(queue)} to synthesise, "
        f"{jobs} at a time")

    def start(b):
        d = out / "blocks" / b["label"]
        d.mkdir(parents=True, exist_ok=True)
        for f in ("netlist.v", "netlist.v.tmp", "area.txt", "memories.txt", "registers.txt", "cost.json",
                  "clock_gates.json"):
            (d / f).unlink(missing_ok=True)
        with open(d / "yosys.err", "w") as err:
            p = run.start([yosys, "-q", "-l", str(d / "yosys.log"), "-c", str(FLOW / "synth_block.tcl")],
                          stderr=err,
                          env={"MODULE": b["module"], "ELAB_IL": str(out / "elab.il"), "OUT_DIR": str(d),
                               "BLACKBOXES": " ".join(block_modules) if b["label"] == "top" else "",
                               "PERIOD_PS": str(period_ps), "LIBERTY": lib, "CONSTRAINTS": str(CON),
                               "CLOCK_GATE_MIN": str(gate_min)})
        log(f"  {b['label']} ({b['module']}) started")
        return p

    done = [0]

    def finish(b, rc, mb, secs):
        d = out / "blocks" / b["label"]
        try:
            if rc != 0 or not (d / "netlist.v.tmp").is_file() or (d / "netlist.v.tmp").stat().st_size == 0:
                raise FlowError(f"yosys failed on {b['module']} (exit {rc})")
            block_outputs(b["module"], d)
        except FlowError as e:
            sys.stderr.write(f"synth: block '{b['label']}' (module {b['module']}) failed: {e}; the end of its "
                             f"Yosys log ({d}/yosys.log):\n")
            sys.stderr.write(indent(tail(d / "yosys.log", 20) + [ln for ln in tail(d / "yosys.err", 5)
                                                                  if not ln.startswith((" ", "\t"))]))
            raise FlowError(f"stopped after block '{b['label']}' failed (Yosys log {d}/yosys.log); "
                            f"no summary.json written") from None
        (d / "netlist.v.tmp").rename(d / "netlist.v")
        (d / "cost.json").write_text(json.dumps({"seconds": secs, "peak_MB": mb}) + "\n")
        (d / "stamp").write_text(b["stamp"] + "\n")
        done[0] += 1
        nand, _ = area_figures(d / "area.txt", b["module"], nand2_area)
        log(f"  {b['label']} done in {secs} s, peak {mb} MB, {nand} NAND2 eq [{done[0]}/{len(queue)}]")

    run.pool(queue, jobs, mem_mb, start, finish)
    return yosys_version
