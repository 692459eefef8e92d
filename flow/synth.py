#!/usr/bin/env python3
"""The synthesis flow of the engine (`make synth`, `make synth-check`).

Yosys 0.23 to OSU 0.18 um standard cells, block by block, on-chip memories kept
out of the gate count as black-box macros (MCADSW_RAM), timing by OpenSTA against
constraints/mcadsw.sdc on the assembled netlist; report next to the paper's
Table III and Fig. 16. The Yosys and OpenSTA steps are the scripts in this folder;
this driver (Python 3 standard library only) runs them:

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
     (flow/soc.tcl) and timed alone (flow/sta_soc.tcl);
  6. report.md and summary.json, written last (deleted at the start).

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
import hashlib
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import synth_report

ROOT = Path(__file__).resolve().parent.parent
FLOW = ROOT / "flow"
CON = ROOT / "constraints"
RAM_MODEL = ROOT / "sim" / "gls" / "mcadsw_ram_model.v"
LIBERTY = "/usr/share/qflow/tech/osu018/osu018_stdcells.lib"
# Part of every block's stamp: change it when the block listing or renaming
# below changes what a block's netlist is.
STAMP_SALT = "blocks v1"
STALE = ("summary.json", "report.md", "mcadsw_engine_osu018.v")
STA_OUT = ("mcadsw_engine_sta.v", "mcadsw_ram.lib", "sta.log", "sta_endpoints.log", "sta_crossing.txt")


def stamp_of(*parts):
    """sha256 of strings, bytes and files (by content) in order."""
    h = hashlib.sha256()
    for p in parts:
        if isinstance(p, Path):
            h.update(f"== {p.name}\n".encode() + (p.read_bytes() if p.is_file() else b"(missing)"))
        else:
            h.update(p if isinstance(p, bytes) else str(p).encode())
    return h.hexdigest()


def reusable(stamp_file, stamp, outputs):
    """Whether a stage's outputs are those of a successful run with this stamp;
    if not, the stamp goes (it is written again after the stage succeeds)."""
    ok = (stamp_file.is_file() and stamp_file.read_text().strip() == stamp
          and all(o.is_file() for o in outputs))
    if not ok:
        stamp_file.unlink(missing_ok=True)
    return ok


class FlowError(Exception):
    """A failure with its message (printed as 'synth: <message>') and exit code."""

    def __init__(self, message, code=1):
        super().__init__(message)
        self.code = code


PREFIX = ["synth"]   # of every message: synth or fpga


def log(msg):
    print(f"{PREFIX[0]}: {msg}", flush=True)


def tail(path, n):
    try:
        return Path(path).read_text(errors="replace").splitlines()[-n:]
    except OSError:
        return []


def indent(lines):
    return "".join(f"  | {line}\n" for line in lines)


def rtl_list(no_pkg=False):
    """The files of rtl/mcadsw.f, relative to the RTL folder."""
    files = []
    for line in (ROOT / "rtl" / "mcadsw.f").read_text().splitlines():
        line = line.split("//")[0].strip()
        if line and not (no_pkg and line == "mcadsw_pkg.sv"):
            files.append(line)
    return files


# ---- Processes --------------------------------------------------------------------------
class Run:
    """Processes of this run: each in its own process group (stopped as a group),
    waited with os.wait4 for its peak memory; all of them sampled each second."""

    def __init__(self):
        self.procs = {}   # pid -> Popen, kept until os.wait4 reaped it (else Popen's own
                          # clean-up could reap it first and its exit status be lost)
        self.peak_sum_mb = 0
        self._stop = threading.Event()
        threading.Thread(target=self._sample, daemon=True).start()

    def _sample(self):
        me = os.getpid()
        while not self._stop.is_set():
            parent, rss = {}, {}
            for d in os.listdir("/proc"):
                if d.isdigit():
                    try:
                        f = Path(f"/proc/{d}/stat").read_text().rsplit(")", 1)[1].split()
                        parent[int(d)], rss[int(d)] = int(f[1]), int(f[21])
                    except (OSError, IndexError, ValueError):
                        pass
            total = 0
            for pid in parent:
                q = pid
                for _ in range(64):
                    if q == me:
                        total += rss[pid]
                        break
                    q = parent.get(q, 0)
                    if q <= 1:
                        break
            self.peak_sum_mb = max(self.peak_sum_mb, total * os.sysconf("SC_PAGE_SIZE") // 2**20)
            self._stop.wait(1)

    def start(self, cmd, cwd=None, env=None, stdout=None, stderr=None):
        p = subprocess.Popen(cmd, cwd=cwd, env={**os.environ, **(env or {})}, stdin=subprocess.DEVNULL,
                             stdout=stdout or subprocess.DEVNULL, stderr=stderr or subprocess.DEVNULL,
                             start_new_session=True)
        self.procs[p.pid] = p
        return p

    def reap(self, pid=-1):
        """Waits for one process of this run: (pid, exit code, peak MB)."""
        pid, status, ru = os.wait4(pid, 0)
        rc = os.waitstatus_to_exitcode(status)
        if pid in self.procs:
            self.procs.pop(pid).returncode = rc
        return pid, rc, ru.ru_maxrss // 1024

    def run(self, cmd, out_path=None, err_path=None, **kw):
        """Runs cmd to its end: (exit code, peak MB, seconds)."""
        t0 = time.time()
        with open(out_path or os.devnull, "w") as o, open(err_path or os.devnull, "w") as e:
            p = self.start(cmd, stdout=o, stderr=e, **kw)
            _, rc, mb = self.reap(p.pid)
        return rc, mb, int(time.time() - t0)

    def stop(self):
        for g in list(self.procs):
            try:
                os.killpg(g, signal.SIGTERM)
            except OSError:
                pass
        for g in list(self.procs):
            try:
                self.reap(g)
            except ChildProcessError:
                self.procs.pop(g, None)
        self._stop.set()


# ---- Block listing (the elaborated RTLIL) ----------------------------------------------------
def list_blocks(il_text):
    """Modules of the elaborated design (RTLIL written after hierarchy -check -top
    mcadsw_engine): each distinct module type the top instantiates is a block,
    renamed mcadsw_<instance name without u_>; the top keeps mcadsw_engine.
    Returns (blocks, renamed RTLIL); each block: label, module, instances, base
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

    newname, label, inst, order, used = {top: "\\mcadsw_engine"}, {}, {}, [], set()
    for t, name in mods[top]["cells"]:
        if not is_sub(t):
            continue
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
                       "instances": inst.get(t, 1), "base": base_of(t),
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


def area_figures(area_txt, module, nand2_area):
    """(NAND2 eq, flip-flops) of module in a `stat -liberty` output."""
    cur, ff, area = None, 0, 0.0
    for line in Path(area_txt).read_text().splitlines():
        w = line.split()
        if line.startswith("=== "):
            cur = w[1].lstrip("\\")
        elif cur == module and len(w) == 2 and w[0].startswith("DFF") and w[1].isdigit():
            ff += int(w[1])
        elif "Chip area for module" in line and re.sub(r"[^A-Za-z0-9_]", "", w[4]) == module:
            area = float(w[-1])
    return int(area / nand2_area + 0.5), ff


def read_table(path):
    try:
        return [ln.split() for ln in Path(path).read_text().splitlines() if ln.strip()]
    except OSError:
        return []


# ---- STA netlist: parameter-free macro cells and their liberty ---------------------------
def sta_netlist(flat_v, out, cfg_path):
    """Every MCADSW_RAM instance of the flattened netlist renamed to a parameter-free
    cell per shape (MCADSW_RAM_S<words>_W<bits>_A<addr bits>_<SYNC|ASYNC>, _WE when
    all bit write enables are one net: a word write enable); writes
    mcadsw_engine_sta.v and mcadsw_ram.lib (a cell per shape, timing from
    constraints/mcadsw_ram_timing.cfg). Returns the number of shapes."""
    def val(s):
        s = s[s.rfind("(") + 1:]
        s = s.split(")")[0]
        if "'b" in s:   # x and z bits (initial values) count as 0
            return int(re.sub(r"[^01]", "0", s.split("'b")[1]) or "0", 2)
        if "'d" in s:
            s = s.split("'d")[1]
        m = re.match(r"\s*[0-9]+", s)
        return int(m.group()) if m else 0

    renamed, shapes, inmac, p = [], {}, False, {}
    for line in Path(flat_v).read_text().splitlines():
        if re.match(r"^ *MCADSW_RAM #\($", line):
            inmac, p = True, {}
        elif inmac and re.match(r"^ *\.", line):
            p[line.strip()[1:].split("(")[0]] = val(line)
        elif inmac and re.match(r"^ *\) ", line):
            if p.get("RD_PORTS") != 1 or p.get("WR_PORTS") != 1:
                raise FlowError("STA netlist: multi-port macro")
            cell = (f"MCADSW_RAM_S{p['SIZE']}_W{p['WIDTH']}_A{p['ABITS']}_"
                    f"{'SYNC' if p['RD_CLK_ENABLE'] else 'ASYNC'}")
            shapes.setdefault(cell, (p["SIZE"], p["WIDTH"], p["ABITS"], p["RD_CLK_ENABLE"]))
            renamed.append(re.sub(r"^ *\)", "  " + cell, line, count=1))
            inmac = False
        elif inmac:
            raise FlowError(f"STA netlist: unexpected line in a macro instance: {line}")
        else:
            renamed.append(line)
    # A macro whose bit write enables are all one net is a macro with a word write
    # enable (WR_WE): that is how it would be built, and it keeps a single enable
    # from appearing to drive thousands of macro pins.
    final, buf, inst = [], [], False
    for line in renamed:
        if re.match(r"^ *MCADSW_RAM_[A-Z0-9_]+ .*\($", line):
            inst, buf = True, [line]
            continue
        if inst and re.match(r"^ *\.WR_EN\(\{ .* \}\),?$", line):
            body = re.sub(r"^ *\.WR_EN\(\{ ", "", line)
            comma = body.endswith(",")
            items = re.sub(r" \}\),?$", "", body).split(", ")
            if all(i == items[0] for i in items):
                buf[0] = re.sub(r"^( *MCADSW_RAM_[A-Z0-9_]+)", r"\1_WE", buf[0], count=1)
                buf.append(f"    .WR_WE({items[0]})" + ("," if comma else ""))
                continue
        if inst:
            buf.append(line)
            if re.match(r"^ *\);$", line):
                inst = False
                final += buf
                buf = []
            continue
        final.append(line)
    text = "\n".join(final) + "\n"
    if "#(" in text:
        raise FlowError(f"STA netlist: parameterised instances left in {out}/mcadsw_engine_sta.v")
    (out / "mcadsw_engine_sta.v").write_text(text)

    cfg = {}
    for line in Path(cfg_path).read_text().splitlines():
        w = line.split()
        if len(w) >= 2 and not w[0].startswith("#"):
            cfg[w[0]] = w[1]
    cap, slew = cfg["pin_cap"], cfg["out_transition"]
    lib = []

    def arc(rel, typ, d):
        lib.append(f'      timing () {{ related_pin : "{rel}"; timing_type : {typ};')
        if "setup" in typ or "hold" in typ:
            lib.append(f'        rise_constraint (scalar) {{ values ("{d}"); }} '
                       f'fall_constraint (scalar) {{ values ("{d}"); }} }}')
        else:
            lib.append(f'        cell_rise (scalar) {{ values ("{d}"); }} cell_fall (scalar) {{ values ("{d}"); }}')
            lib.append(f'        rise_transition (scalar) {{ values ("{slew}"); }} '
                       f'fall_transition (scalar) {{ values ("{slew}"); }} }}')

    def input_bus(name, w, clk):
        lib.append(f"    bus ({name}) {{ bus_type : bus{w}; direction : input; capacitance : {cap};")
        arc(clk, "setup_rising", cfg["setup"])
        arc(clk, "hold_rising", cfg["hold"])
        lib.append("    }")

    def input_pin(name, clk):
        lib.append(f"    pin ({name}) {{ direction : input; capacitance : {cap};")
        arc(clk, "setup_rising", cfg["setup"])
        arc(clk, "hold_rising", cfg["hold"])
        lib.append("    }")

    lib += ["/* Generated by flow/synth.py from constraints/mcadsw_ram_timing.cfg: timing models",
            "   of the MCADSW_RAM memory macros (one cell per shape). Not a characterised library. */",
            "library (mcadsw_ram) {",
            "  delay_model : table_lookup;",
            '  time_unit : "1ns"; voltage_unit : "1V"; current_unit : "1uA";',
            '  pulling_resistance_unit : "1kohm"; leakage_power_unit : "1nW"; capacitive_load_unit (1,pf);',
            "  slew_upper_threshold_pct_rise : 80; slew_lower_threshold_pct_rise : 20;",
            "  slew_upper_threshold_pct_fall : 80; slew_lower_threshold_pct_fall : 20;",
            "  input_threshold_pct_rise : 50; input_threshold_pct_fall : 50;",
            "  output_threshold_pct_rise : 50; output_threshold_pct_fall : 50;",
            "  nom_process : 1; nom_voltage : 1.8; nom_temperature : 25;"]
    for n in sorted({w for s in shapes.values() for w in (s[1], s[2])}):
        lib.append(f"  type (bus{n}) {{ base_type : array; data_type : bit; bit_width : {n}; "
                   f"bit_from : {n - 1}; bit_to : 0; downto : true; }}")
    for cell, (size, width, abits, sync) in shapes.items():
        for we in (False, True):
            lib.append(f"  cell ({cell}{'_WE' if we else ''}) {{")
            lib.append("    area : 0; dont_touch : true; dont_use : true;")
            lib.append(f"    pin (RD_CLK) {{ direction : input; capacitance : {cap}; clock : true; }}")
            lib.append(f"    pin (WR_CLK) {{ direction : input; capacitance : {cap}; clock : true; }}")
            lib.append(f"    pin (RD_ARST) {{ direction : input; capacitance : {cap}; }}")
            if sync:
                input_pin("RD_EN", "RD_CLK")
                input_bus("RD_ADDR", abits, "RD_CLK")
            else:
                lib.append(f"    pin (RD_EN) {{ direction : input; capacitance : {cap}; }}")
                lib.append(f"    bus (RD_ADDR) {{ bus_type : bus{abits}; direction : input; capacitance : {cap}; }}")
            if we:
                input_pin("WR_WE", "WR_CLK")
            else:
                input_bus("WR_EN", width, "WR_CLK")
            input_bus("WR_ADDR", abits, "WR_CLK")
            input_bus("WR_DATA", width, "WR_CLK")
            lib.append(f"    bus (RD_DATA) {{ bus_type : bus{width}; direction : output;")
            if sync:
                arc("RD_CLK", "rising_edge", cfg["clk_to_q"])
            else:
                acc = cfg["async_access"]
                lib.append('      timing () { related_bus_pins : "RD_ADDR"; timing_type : combinational; '
                           'timing_sense : non_unate;')
                lib.append(f'        cell_rise (scalar) {{ values ("{acc}"); }} cell_fall (scalar) {{ values ("{acc}"); }}')
                lib.append(f'        rise_transition (scalar) {{ values ("{slew}"); }} '
                           f'fall_transition (scalar) {{ values ("{slew}"); }} }}')
                arc("WR_CLK", "rising_edge", acc)
            lib.append("    }\n  }")
    lib.append("}")
    (out / "mcadsw_ram.lib").write_text("\n".join(lib) + "\n")
    return len(shapes)


# ---- The flow ------------------------------------------------------------------------------
GROUPS = {"mcadsw_weight_gen": "weight_generator", "mcadsw_cost_agg": "cost_aggregator_wta",
          "mcadsw_mem_ctrl": "memory_controller", "mcadsw_win_reader": "memory_controller",
          "mcadsw_scheduler": "block_scheduler", "mcadsw_depth_fifo": "depth_fifo",
          "mcadsw_post": "post_stage", "mcadsw_post_check": "post_stage",
          "mcadsw_post_fill": "post_stage", "mcadsw_fifo": "post_stage", "mcadsw_engine": "top_registers_counters",
          "mcadsw_cfg_check": "top_registers_counters", "mcadsw_frame_ctrl": "top_registers_counters",
          "mcadsw_win_geom": "top_registers_counters"}
GROUP_NAMES = {
    "census_left": "census left (transformer + buffer)", "census_right": "census right (transformer + buffer)",
    "census_left_right": "census left + right (one module at this DMAX)",
    "weight_generator": "weight generator (+ weight buffers)", "cost_aggregator_wta": "cost aggregator + WTA",
    "memory_controller": "memory controller + window readers", "block_scheduler": "block scheduler",
    "depth_fifo": "depth FIFO", "top_registers_counters": "engine core: configuration, check, frame controller, counters, window geometry",
    "post_stage": "LR post stage (check, fill, median; beyond the paper)"}


def group_of(b):
    if b["base"] == "mcadsw_census":
        return ("census_left_right" if b["instances"] > 1 else
                "census_right" if b["label"].endswith("_r") else "census_left")
    return GROUPS.get(b["base"], "other")


def paper_share(g):
    if g in ("census_left", "census_right", "cost_aggregator_wta"):
        return "one of the three that dominate"
    return "two of the three that dominate" if g == "census_left_right" else "not given"


def gen_package(gen, dmax, par):
    """The package of the configuration from gen_rtl_pkg, the one check of DMAX
    and PAR (exit 2 with its message)."""
    if not (Path(gen).is_file() and os.access(gen, os.X_OK)):
        raise FlowError(f"gen_rtl_pkg not found at {gen} (make synth builds it; or: "
                        f"cmake --build build --target gen_rtl_pkg)", 2)
    r = subprocess.run([gen, "--dmax", dmax, "--par", par], capture_output=True, text=True)
    if r.returncode != 0:
        raise FlowError(r.stderr.strip() or f"gen_rtl_pkg failed (exit {r.returncode})", 2)
    return r.stdout


def default_out(build, dmax, par):
    if par != "1":
        return Path(build) / f"synth_dmax{dmax}_par{par}"
    return Path(build) / ("synth" if dmax == "64" else f"synth_dmax{dmax}")


def run_sta(run, out, yosys, lib, sdc, netlist):
    """The STA netlist and macro liberty, then OpenSTA: (peak MB of each)."""
    log(f"OpenSTA on the assembled netlist (log: {out}/sta.log)")
    for f in STA_OUT:
        (out / f).unlink(missing_ok=True)
    rc, stanet_mb, _ = run.run([yosys, "-q", "-l", str(out / "sta_netlist.log"), "-c", str(FLOW / "sta_netlist.tcl")],
                               err_path=out / "sta_netlist.err",
                               env={"RAM_MODEL": str(RAM_MODEL), "LIBERTY": lib, "NETLIST": str(netlist),
                                    "OUT_V": str(out / "mcadsw_engine_flat.v")})
    if rc != 0:
        sys.stderr.write(indent(tail(out / "sta_netlist.log", 20)))
        raise FlowError(f"preparing the STA netlist failed (log: {out}/sta_netlist.log)")
    resized = [ln for ln in tail(out / "sta_netlist.log", 10**7) if "Resizing cell port" in ln]
    if resized:
        sys.stderr.write("".join(ln + "\n" for ln in resized[:5]))
        raise FlowError(f"STA netlist: port widths of an instance and its module differ in {netlist}")
    nshapes = sta_netlist(out / "mcadsw_engine_flat.v", out, CON / "mcadsw_ram_timing.cfg")
    (out / "mcadsw_engine_flat.v").unlink()
    log(f"  {nshapes} macro shapes -> {out}/mcadsw_ram.lib, netlist {out}/mcadsw_engine_sta.v")
    rc, sta_mb, _ = run.run(["sta", "-no_splash", "-exit", str(FLOW / "sta_engine.tcl")],
                            out_path=out / "sta.log", err_path=out / "sta.err",
                            env={"LIBERTY": lib, "OUT_DIR": str(out), "SDC": str(sdc)})
    sta_log = (out / "sta.log").read_text(errors="replace")
    if rc != 0 or not re.search(r"^worst slack", sta_log, re.M):
        sys.stderr.write(indent(sta_log.splitlines()[-20:] + tail(out / "sta.err", 5)))
        raise FlowError(f"sta failed or gave no worst slack (log: {out}/sta.log)")
    return stanet_mb, sta_mb


def synth(a):
    t_start = time.time()
    # No result of an earlier run may pass for this one's: summary, report and
    # assembled netlist go first, and are written again only when everything succeeded.
    if a.out:
        for f in STALE:
            (Path(a.out) / f).unlink(missing_ok=True)
    pkg_text = gen_package(a.gen_rtl_pkg, a.dmax, a.par)
    dmax, par = int(a.dmax), int(a.par)
    out = Path(a.out or default_out(a.build, a.dmax, a.par)).resolve()
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
                         period_ps, clock_mhz, nand2_area)
    finally:
        run.stop()


def synth_run(a, run, t_start, out, rtl, pkg, pkg_text, dmax, par, yosys, lib, sdc, period_ns, period_ps,
              clock_mhz, nand2_area):
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
    blocks, il = list_blocks((out / "elab_raw.il").read_text())
    (out / "elab.il").write_text(il)
    (out / "elab_raw.il").unlink()
    (out / "blocks.json").write_text(json.dumps(
        [{k: v for k, v in b.items() if k != "sig"} for b in blocks], indent=1) + "\n")
    block_modules = [b["module"] for b in blocks if b["label"] != "top"]

    # ---- (2) Blocks ----
    # Stamp: everything a block's netlist depends on. Sources: the files of the
    # block's module and sub-modules (src attributes of the elaborated design) and
    # the package; parameters and module names (for the top also the ports of the
    # blocks it instantiates); flow: the block script, the files it reads and the
    # Yosys version.
    yosys_version = subprocess.run([yosys, "-V"], capture_output=True, text=True).stdout.strip()
    flow_files = [FLOW / "synth_block.tcl", CON / "macro_map.v", CON / "abc_osu018.constr",
                  CON / "abc_osu018.script", Path(lib), RAM_MODEL]
    for b in blocks:
        h = hashlib.sha256(f"{STAMP_SALT}; yosys: {yosys_version}; period_ps {period_ps}\n{b['sig']}".encode())
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
                       and (d / "area.txt").is_file() and (d / "cost.json").is_file())
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
        f"{a.jobs} at a time")

    def est_mb(b):
        return b["est_mb"] if b["est_mb"] > 0 else 3500

    def mem_avail_mb():
        try:
            m = re.search(r"^MemAvailable:\s+(\d+)", Path("/proc/meminfo").read_text(), re.M)
            return int(m.group(1)) // 1024
        except (OSError, AttributeError):
            return 10**6

    # A block starts when the expected peaks of the running blocks and its own stay
    # within --mem-mb and its own (plus 512 MB) is free on the machine now; the
    # first block always starts. Expected peak: the block's last run, else 3500 MB.
    pending, running, done = list(queue), {}, 0
    while pending or running:
        while pending and len(running) < a.jobs:
            used = sum(est_mb(b) for b, _ in running.values())
            avail = mem_avail_mb()
            pick = next((b for b in pending if not running or
                         (used + est_mb(b) <= a.mem_mb and est_mb(b) + 512 <= avail)), None)
            if pick is None:
                break
            pending.remove(pick)
            d = out / "blocks" / pick["label"]
            d.mkdir(parents=True, exist_ok=True)
            for f in ("netlist.v", "netlist.v.tmp", "area.txt", "memories.txt", "registers.txt", "cost.json"):
                (d / f).unlink(missing_ok=True)
            with open(d / "yosys.err", "w") as err:
                p = run.start([yosys, "-q", "-l", str(d / "yosys.log"), "-c", str(FLOW / "synth_block.tcl")],
                              stderr=err,
                              env={"MODULE": pick["module"], "ELAB_IL": str(out / "elab.il"), "OUT_DIR": str(d),
                                   "BLACKBOXES": " ".join(block_modules) if pick["label"] == "top" else "",
                                   "PERIOD_PS": str(period_ps), "LIBERTY": lib, "CONSTRAINTS": str(CON)})
            running[p.pid] = (pick, time.time())
            log(f"  {pick['label']} ({pick['module']}) started")
        pid, rc, mb = run.reap()
        if pid not in running:
            continue
        b, t0 = running.pop(pid)
        d = out / "blocks" / b["label"]
        secs = int(time.time() - t0)
        try:
            if rc != 0 or not (d / "netlist.v.tmp").is_file() or (d / "netlist.v.tmp").stat().st_size == 0:
                raise FlowError(f"yosys failed on {b['module']} (exit {rc})")
            block_outputs(b["module"], d)
        except FlowError as e:
            run.stop()
            sys.stderr.write(f"synth: block '{b['label']}' (module {b['module']}) failed: {e}; the end of its "
                             f"Yosys log ({d}/yosys.log):\n")
            sys.stderr.write(indent(tail(d / "yosys.log", 20) + [ln for ln in tail(d / "yosys.err", 5)
                                                                  if not ln.startswith((" ", "\t"))]))
            raise FlowError(f"stopped after block '{b['label']}' failed (Yosys log {d}/yosys.log); "
                            f"no summary.json written") from None
        (d / "netlist.v.tmp").rename(d / "netlist.v")
        (d / "cost.json").write_text(json.dumps({"seconds": secs, "peak_MB": mb}) + "\n")
        (d / "stamp").write_text(b["stamp"] + "\n")
        done += 1
        nand, _ = area_figures(d / "area.txt", b["module"], nand2_area)
        log(f"  {b['label']} done in {secs} s, peak {mb} MB, {nand} NAND2 eq [{done}/{len(queue)}]")
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
                         CON / "mcadsw_ram_timing.cfg", Path(lib), RAM_MODEL, Path(__file__))
    sta_reused = reusable(out / "sta.stamp", sta_stamp, [out / f for f in STA_OUT])
    stanet_mb = sta_mb = 0
    if sta_reused:
        log(f"OpenSTA: the assembled netlist is unchanged, its timing reused ({out}/sta.log)")
    else:
        stanet_mb, sta_mb = run_sta(run, out, yosys, lib, sdc, netlist)
        (out / "sta.stamp").write_text(sta_stamp + "\n")
    sta_log = (out / "sta.log").read_text(errors="replace")
    sta_s = int(time.time() - sta_start)

    def first(pattern, text, field):
        for line in text.splitlines():
            if re.match(pattern, line):
                return line.split()[field]
        return None
    # wns: worst negative slack (0 when every path meets the clock); slack: the
    # worst path's slack, negative or positive, which sets the achievable clock.
    wns, slack = first(r"^wns", sta_log, 1), first(r"^worst slack", sta_log, 2)
    if wns is None or slack is None:
        sys.stderr.write(indent(sta_log.splitlines()[-20:] + tail(out / "sta.err", 5)))
        raise FlowError(f"sta failed or gave no wns / worst slack (log: {out}/sta.log)")
    wns, slack = float(wns), float(slack)
    crit_start = next((ln[len("Startpoint: "):] for ln in sta_log.splitlines() if ln.startswith("Startpoint:")), "")
    crit_end = next((ln[len("Endpoint: "):] for ln in sta_log.splitlines() if ln.startswith("Endpoint:")), "")
    crit_arrival = next((ln.split()[0] for ln in sta_log.splitlines() if "data arrival time" in ln), "")
    crossing = [(w[0], w[1], w[2], int(w[3]), float(w[4])) for w in read_table(out / "sta_crossing.txt")]
    crossing.sort(key=lambda c: -c[4])
    cross_worst = float(f"{crossing[0][4]:.3f}") if crossing else 0
    cross_slow = sum(1 for c in crossing if c[4] > 0.5)
    # Violating endpoints per block instance (the instance path's first component).
    viol = {}
    for line in (out / "sta_endpoints.log").read_text(errors="replace").splitlines():
        if "VIOLATED" in line:
            w = line.split()
            bl = re.sub(r"\[.*", "", w[0].split(".")[0])
            bl = "top" if bl.startswith("_") else bl
            n, worst = viol.get(bl, (0, None))
            s = float(w[-2])
            viol[bl] = (n + 1, s if worst is None or s < worst else worst)

    # ---- (5) The SoC wrapper around the engine (mcadsw_top: AXI4-Lite registers,
    # AXI4 master), mapped and timed apart (about 20 s) ----
    soc = out / "soc"
    soc.mkdir(exist_ok=True)
    soc_nand, soc_slack = {}, None
    socs = ("mcadsw_regs", "mcadsw_axi_master")
    soc_stamp = stamp_of(yosys_version, pkg_text, f"DMAX {dmax} PAR {par} period {period_ns}\n",
                         *[rtl / f"{m}.sv" for m in socs], FLOW / "soc.tcl", FLOW / "sta_soc.tcl",
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
            rc, _, _ = run.run(["sta", "-no_splash", "-exit", str(FLOW / "sta_soc.tcl")],
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

    # ---- (6) Figures ----
    # Per block: NAND2 eq (the module's own `stat -liberty` area / NAND2X1 area),
    # flip-flops, memory bits, Yosys time and peak; instances multiply a block's
    # figures into the totals. Fig. 16 group of each block.
    memories, registers = [], []
    for b in blocks:
        d = out / "blocks" / b["label"]
        cost = json.loads((d / "cost.json").read_text())
        b["seconds"], b["peak_MB"] = cost["seconds"], cost["peak_MB"]
        b["nand2"], b["ff"] = area_figures(d / "area.txt", b["module"], nand2_area)
        mems = read_table(d / "memories.txt")
        b["mem"] = sum(int(m[4]) for m in mems)
        b["group"] = group_of(b)
        for _ in range(b["instances"]):
            memories += [[b["module"]] + m[1:] for m in mems]
            registers += [[b["module"]] + r[1:] for r in read_table(d / "registers.txt")]
    (out / "memories.txt").write_text("".join(" ".join(m) + "\n" for m in memories))
    (out / "registers.txt").write_text("".join(" ".join(r) + "\n" for r in registers))
    nand2_total = sum(b["instances"] * b["nand2"] for b in blocks)
    ff_count = sum(b["instances"] * b["ff"] for b in blocks)
    soc_total = nand2_total + soc_nand["mcadsw_regs"] + soc_nand["mcadsw_axi_master"]
    mem_bits = sum(int(m[4]) for m in memories)
    async_count = sum(1 for m in memories if m[7] != "sync")
    reg_bits = sum(int(r[2]) for r in registers)

    def kb(bits):
        return float(f"{bits / 8 / 1024:.1f}")
    # The LR mode's post stage (issue 17) is reported apart: the engine's figures
    # (the budget's memory) are those without it.
    post_nand2 = sum(b["instances"] * b["nand2"] for b in blocks if b["group"] == "post_stage")
    post_bits = sum(b["instances"] * b["mem"] for b in blocks if b["group"] == "post_stage")
    eng_bits = mem_bits - post_bits
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
        "memory_kB_engine": kb(eng_bits), "post_stage_nand2_eq": post_nand2, "post_stage_memory_bits": post_bits,
        "post_stage_memory_kB": kb(post_bits), "async_read_macros": async_count, "data_register_bits": reg_bits,
        "flip_flops": ff_count, "clock_mhz": clock_mhz, "wns_ns": wns, "worst_slack_ns": slack, "fmax_mhz": fmax,
        "crossing_nets": len(crossing), "crossing_worst_transition_ns": cross_worst,
        "wall_seconds": wall_s, "yosys_seconds": yosys_cpu_s, "yosys_peak_MB": yosys_peak_mb,
        "peak_process_MB": proc_peak_mb, "peak_sum_MB": sum_peak_mb,
        "per_block": {g: v[0] for g, v in groups},
        "blocks": {b["label"]: {"module": b["module"], "instances": b["instances"], "nand2_eq": b["nand2"],
                                "flip_flops": b["ff"], "memory_bits": b["mem"], "group": b["group"],
                                "yosys_seconds": b["seconds"], "peak_MB": b["peak_MB"], "reused": b["cached"]}
                   for b in blocks},
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
        "groups": [{"group": g, "name": GROUP_NAMES.get(g, g), "nand2_eq": n, "flip_flops": f, "memory_bits": m,
                    "paper": paper_share(g)} for g, (n, f, m) in groups],
        "memories": memories, "data_registers": registers}
    (out / "report.md.tmp").write_text(synth_report.render(summary))
    (out / "summary.json.tmp").write_text(json.dumps(summary, indent=2) + "\n")
    (out / "report.md.tmp").rename(out / "report.md")
    (out / "summary.json.tmp").rename(out / "summary.json")

    log(f"{nand2_total} NAND2 eq (paper 563k), memory {kb(mem_bits)} kB in {len(memories)} macros "
        f"({kb(eng_bits)} kB without the LR post stage; paper 21.3 kB),")
    print(f"       LR post stage {post_nand2} NAND2 eq, {kb(post_bits)} kB; with the SoC wrapper (registers "
          f"{soc_nand['mcadsw_regs']}, AXI4 master {soc_nand['mcadsw_axi_master']}, slack {soc_slack} ns) "
          f"{soc_total} NAND2 eq,")
    print(f"       worst slack {slack} ns (WNS {wns} ns) at {clock_mhz} MHz, achievable {fmax} MHz (paper 95 MHz)")
    log(f"report {out}/report.md, summary {out}/summary.json, netlist {netlist}")
    log(f"wall time {wall_s} s ({len(ran)} blocks synthesised, {len(cached)} reused); peak memory {proc_peak_mb} MB "
        f"in one process ({proc_peak_what}), {sum_peak_mb} MB all processes together")
    return out / "summary.json"


# ---- make fpga -------------------------------------------------------------------------------
def fpga(a):
    """An FPGA estimate (issue 19): Yosys synth_xilinx for a 7-series part
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
                           env={"PKG": str(pkg), "TOP": a.top, "OUT_DIR": str(out),
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


# ---- make synth-check --------------------------------------------------------------------------
def check(a):
    """The summary against constraints/budget.json: fails when the engine has more
    NAND2 equivalents than nand2_eq_max, a worst slack at the SDC clock below
    wns_ns_min (negative: 95 MHz missed), more on-chip memory than memory_kB_max,
    or (when the budget sets async_read_macros_max) more macros with an
    asynchronous read port; the SoC wrapper's total and slack where the summary
    has them. Without --summary, synthesises (DMAX = 64, incrementally) first."""
    def fail2(msg):
        print(f"synth-check: {msg}", file=sys.stderr)
        return 2
    budget_path = Path(a.budget)
    if not budget_path.is_file():
        return fail2(f"no budget file {budget_path}")
    if a.summary:
        summary_path = Path(a.summary)
    else:
        if a.dmax not in ("64",) or a.par != "1":
            return fail2(f"the budget is for DMAX = 64, PAR = 1 (got DMAX={a.dmax}, PAR={a.par})")
        try:
            summary_path = synth(a)
        except FlowError as e:
            print(f"synth: {e}", file=sys.stderr)
            print("synth-check: FAILED: make synth did not complete (above)", file=sys.stderr)
            return 1
    if not summary_path.is_file():
        print(f"synth-check: no summary {summary_path}", file=sys.stderr)
        return 1
    try:
        s = json.loads(summary_path.read_text())
        budget = json.loads(budget_path.read_text())
    except ValueError as e:
        return fail2(f"cannot read {summary_path} or {budget_path}: {e}")
    # Memory: the engine's without the LR mode's post stage (reported apart, issue 17)
    # where the summary has it, otherwise all of it.
    v = {"nand2": s.get("nand2_eq"), "slack": s.get("worst_slack_ns"),
         "mem": s.get("memory_kB_engine", s.get("memory_kB")),
         "max_nand2": budget.get("nand2_eq_max"), "min_slack": budget.get("wns_ns_min"),
         "max_mem": budget.get("memory_kB_max")}
    for k in ("nand2", "mem", "slack", "max_nand2", "min_slack", "max_mem"):
        if not isinstance(v[k], (int, float)):
            return fail2(f"'{k}' missing from {summary_path} or {budget_path}")
    clock, want_clock = s.get("clock_mhz"), budget.get("clock_mhz")
    if s.get("dmax") not in (None, 64):
        return fail2(f"{summary_path} is for DMAX = {s['dmax']}, the budget for DMAX = 64")
    failed = False

    def chk(name, value, op, limit, unit, why):
        nonlocal failed
        if (value <= limit) if op == "<=" else (value >= limit):
            print(f"synth-check: ok      {name:<26} {value} {unit} (budget {op} {limit} {unit})")
        else:
            print(f"synth-check: FAILED  {name:<26} {value} {unit}, budget {op} {limit} {unit}: {why}",
                  file=sys.stderr)
            failed = True
    chk("gates (NAND2 eq)", v["nand2"], "<=", v["max_nand2"], "",
        "the engine exceeds the gate budget (build/synth/report.md lists the blocks)")
    chk(f"worst slack at {clock if clock is not None else '?'} MHz", v["slack"], ">=", v["min_slack"], "ns",
        "timing is not met (build/synth/sta.log has the critical path, sta_endpoints.log every endpoint)")
    chk("on-chip memory (engine)", v["mem"], "<=", v["max_mem"], "kB",
        "the memories exceed the budget (build/synth/report.md lists them per module)")
    # The whole IP (engine and SoC wrapper, mcadsw_top) where the summary has it.
    if "soc_total_nand2_eq" in s:
        chk("gates with the SoC wrapper", s["soc_total_nand2_eq"], "<=", v["max_nand2"], "",
            "the engine with its AXI4-Lite registers and AXI4 master exceeds the gate budget (build/synth/report.md)")
    if "soc_worst_slack_ns" in s:
        chk("SoC wrapper slack", s["soc_worst_slack_ns"], ">=", v["min_slack"], "ns",
            "the register block or the AXI4 master misses the clock (build/synth/soc/sta.log)")
    # Optional: macros with an asynchronous read port (no SRAM offers one).
    if "async_read_macros_max" in budget:
        if "async_read_macros" not in s:
            return fail2(f"'async_read_macros' missing from {summary_path}")
        chk("async-read macros", s["async_read_macros"], "<=", budget["async_read_macros_max"], "",
            "a memory is read asynchronously; real SRAMs register the address (build/synth/report.md, Memories)")
    if want_clock is not None and clock is not None and abs(clock - want_clock) >= 0.05:
        print(f"synth-check: FAILED  the SDC clock is {clock} MHz, the budget is for {want_clock} MHz",
              file=sys.stderr)
        failed = True
    if failed:
        print(f"synth-check: FAILED against {budget_path} ({summary_path})", file=sys.stderr)
        return 1
    print(f"synth-check: passed ({summary_path} within {budget_path})")
    return 0


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
        p.add_argument("--yosys", default="yosys", help="Yosys executable")
        p.add_argument("--liberty", default=LIBERTY)
        p.add_argument("--gen-rtl-pkg", help="the package generator (default BUILD/bin/gen_rtl_pkg)")
        if name == "fpga":
            p.add_argument("--top", default="mcadsw_top", help="another module (mcadsw_regs: a quick check)")
        if name == "check":
            p.add_argument("--summary", help="check this summary only (no synthesis)")
            p.add_argument("--budget", default=str(CON / "budget.json"))
    a = ap.parse_args()
    # Empty values (make synth DMAX= PAR=) are the defaults.
    a.dmax, a.par = a.dmax or "64", a.par or "1"
    a.gen_rtl_pkg = a.gen_rtl_pkg or str(Path(a.build) / "bin" / "gen_rtl_pkg")
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))
    if a.cmd == "check":
        return check(a)
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
