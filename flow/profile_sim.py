#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""make profile-sim: where a simulated frame's time goes. Builds the SoC model and its harness
(mcadsw_sim) with Verilator's --prof-cfuncs in BUILD_DIR (default build/prof;
-DMCADSW_PROFILE=ON: each C++ function of the model is named after the Verilog module and line
it comes from; otherwise the build of make sim), runs one frame (default: CIF Teddy, D = 64,
raw) under `perf record` (sampling: the model runs at its usual speed), and sums perf's samples:
the share of the time in the verilated model per Verilog module and in the model's scheduling
code, against the harness (memory model, driver, bench), the reference model, Verilator's
runtime and the C++ library.

  python3 flow/profile_sim.py [--build BUILD_DIR] [mcadsw_sim arguments]

Outputs BUILD_DIR/profile/: perf.data, perf.txt (perf report by symbol), summary.txt (the
shares).

With --callgrind: the model make sim runs (BUILD_DIR default build, no instrumentation), one
crop of the frame (default 120x60 at 60,40: 165 163 cycles) under valgrind's callgrind, which
counts instructions (repeatable on a busy machine). Each function of the model is given to the
RTL instance its code names most (Verilator merges the clocked blocks of several modules into
one function, so a share is that of the functions an instance dominates, not an exact split).
Outputs BUILD_DIR/profile_callgrind/: callgrind.out, annotate.txt, summary.txt.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import time
from collections import defaultdict
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from flowlib import FlowError, cmake_build, log, PREFIX, ROOT, run_main  # noqa: E402

DEFAULT_FRAME = ["data/cif/teddy/left.png", "data/cif/teddy/right.png", "-d", "64"]
DEFAULT_CROP = ["--crop", "60,40,120,60"]

# perf report --stdio --no-children --sort symbol: "  12.34%  [.] name".
LINE = re.compile(r"^\s*([\d.]+)%\s+\[[.k]\]\s+(.+)$")
# A function of the model under --prof-cfuncs: ..._PROF__<module>__l<line>(...) (Verilator
# 5: the module's name, then the source line of the block).
PROF = re.compile(r"__PROF__([A-Za-z0-9_]+?)__l(\d+)")


def classify(name):
    """(group, detail) of one function of perf's report."""
    m = PROF.search(name)
    if m:
        return "model: Verilog blocks", m.group(1)
    if name.startswith("Vmcadsw_top"):
        return "model: scheduling and glue", "(Verilator's eval, settle, triggers)"
    short = name.split("(")[0][:60]
    for group, pattern in (("Verilator runtime", r"\bVerilated|\bvl_|\bVL_|verilated"),
                           ("OpenCV (image I/O)", r"cv::|opencv"),
                           ("harness (memory model, driver, bench)", r"mcadsw::(sim|driver)::"),
                           ("reference model", r"mcadsw::")):
        if re.search(pattern, name):
            return group, short
    return "other (C++ library, kernel)", short


def summarise(report, samples):
    """The shares of perf's report (self samples by symbol) by group and by module: text."""
    groups, mods, harness = defaultdict(float), defaultdict(float), defaultdict(float)
    total = 0.0
    for line in report.splitlines():
        m = LINE.match(line)
        if not m:
            continue
        self_s, name = float(m.group(1)), m.group(2).strip()
        group, detail = classify(name)
        groups[group] += self_s
        total += self_s
        if group == "model: Verilog blocks":
            mods[detail] += self_s
        elif not group.startswith("model"):
            harness[f"{group}: {detail}"] += self_s
    if total <= 0:
        raise FlowError("perf's report is empty")
    rows = [f"{samples} samples (perf record, cpu-clock)", "", "by part:"]
    rows += [f"  {100 * s / total:5.1f} %  {g}" for g, s in sorted(groups.items(), key=lambda kv: -kv[1])]
    rows += ["", "the model's Verilog blocks by module:"]
    rows += [f"  {100 * s / total:5.1f} %  {m}" for m, s in sorted(mods.items(), key=lambda kv: -kv[1])]
    rows += ["", "outside the model, the largest functions:"]
    rows += [f"  {100 * s / total:5.1f} %  {f}" for f, s in sorted(harness.items(), key=lambda kv: -kv[1])[:15]]
    return "\n".join(rows) + "\n"


# callgrind_annotate's self cost of one function: "1,234 (12.34%)  file:function(args) [object]".
CG_LINE = re.compile(r"^\s*([\d,]+)\s+\(\s*[\d.]+%\)\s+(\S*?):(\S.*?)(?:\s+\[[^\]]*\])?$")
# A function of the verilated model's root class, and its body in the generated C++.
MODEL_FN = re.compile(r"(Vmcadsw_top___024root___\w+)\(")
FN_BODY = re.compile(r"^void (Vmcadsw_top___024root___\w+)\(Vmcadsw_top___024root\* vlSelf[^)]*\) \{\n(.*?)^\}",
                     re.S | re.M)
# A signal of the design in the generated code: its hierarchy, instances joined by __DOT__.
SIGNAL = re.compile(r"mcadsw_top__DOT__(\w+)")


def instance_of(body, depth=3):
    """The RTL instance (up to depth levels of u_/g_ names under the top) a function's body
    names most, or None when it names none."""
    counts = defaultdict(int)
    for m in SIGNAL.finditer(body):
        parts = [p for p in m.group(1).split("__DOT__") if p.startswith(("u_", "g_"))][:depth]
        if parts:
            counts[".".join(parts).replace("__BRA__", "[").replace("__KET__", "]")] += 1
    return max(counts, key=counts.get) if counts else None


def attribute(annotate, bodies):
    """Instructions by part and by RTL instance from callgrind_annotate's self costs (text) and
    the model's function bodies ({name: C++}): (total, {part: n}, {instance: n})."""
    parts, insts = defaultdict(int), defaultdict(int)
    total = 0
    for line in annotate.splitlines():
        m = CG_LINE.match(line)
        if not m or m.group(2) == "PROGRAM TOTALS":
            continue
        n, func = int(m.group(1).replace(",", "")), m.group(3)
        total += n
        fm = MODEL_FN.search(func)
        if fm:
            # The scheduler's own functions (_eval, _eval_body__nba, ...) name the signals whose
            # edges they test: scheduling, whatever they name.
            inst = None if "___eval" in fm.group(1) else instance_of(bodies.get(fm.group(1), ""))
            if inst:
                parts["model: RTL blocks"] += n
                insts[inst] += n
            else:
                parts["model: scheduling and glue"] += n
        else:
            group, _ = classify(func)
            parts["model: scheduling and glue" if group.startswith("model") else group] += n
    return total, parts, insts


def run_under(prefix, exe, args, out, what):
    """Runs exe with args under the profiler command prefix in out (run.log): its stdout."""
    log(f"running {exe.name} {' '.join(args)} under {what}")
    t0 = time.time()
    run = subprocess.run(prefix + [str(exe)] + args, cwd=out, capture_output=True, text=True)
    (out / "run.log").write_text(run.stdout + run.stderr)
    if run.returncode != 0:
        print(run.stdout + run.stderr)
        raise FlowError(f"the run failed (exit {run.returncode})")
    print(run.stdout, end="")
    log(f"run in {time.time() - t0:.1f} s (under {what})")
    return run.stdout


def callgrind(a):
    """--callgrind: instructions of the make sim model by RTL instance (summary text)."""
    build = Path(a.build).resolve() if a.build else ROOT / "build"
    exe = build / "bin" / "mcadsw_sim"
    for tool in ("valgrind", "callgrind_annotate"):
        if not shutil.which(tool):
            raise FlowError(f"{tool} (Debian package valgrind) is missing", 2)
    if not exe.exists():
        raise FlowError(f"no {exe}: build it first (make build)", 2)
    sources = [f for f in build.glob("sim/CMakeFiles/vengine.dir/Vmcadsw_top.dir/Vmcadsw_top___024root__*.cpp")]
    if not sources:
        raise FlowError(f"the model's generated C++ is not under {build}/sim/CMakeFiles/vengine.dir", 2)
    bodies = {}
    for f in sources:
        bodies.update({m.group(1): m.group(2) for m in FN_BODY.finditer(f.read_text())})
    out = build / "profile_callgrind"
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    args = a.sim_args or [str(ROOT / p) if "/" in p else p for p in DEFAULT_FRAME] + DEFAULT_CROP
    stdout = run_under(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out / 'callgrind.out'}"],
                       exe, args, out, "callgrind")
    ann = subprocess.run(["callgrind_annotate", "--threshold=100", str(out / "callgrind.out")],
                         capture_output=True, text=True)
    if ann.returncode != 0:
        raise FlowError(f"callgrind_annotate failed: {ann.stderr.strip()[-500:]}")
    (out / "annotate.txt").write_text(ann.stdout)
    total, parts, insts = attribute(ann.stdout, bodies)
    if total <= 0:
        raise FlowError("callgrind_annotate's report is empty")
    cyc = re.search(r"\b(\d+) cycles\b", stdout)
    rows = [f"{total:,} instructions (callgrind)"
            + (f", {int(cyc.group(1)):,} cycles: {total / int(cyc.group(1)):,.0f} a cycle" if cyc else ""),
            "", "by part:"]
    rows += [f"  {100 * n / total:5.1f} %  {g}" for g, n in sorted(parts.items(), key=lambda kv: -kv[1])]
    rows += ["", "the model's functions by the RTL instance they name most:"]
    rows += [f"  {100 * n / total:5.1f} %  {i}" for i, n in sorted(insts.items(), key=lambda kv: -kv[1])
             if 100 * n / total >= 0.1]
    text = "\n".join(rows) + "\n"
    (out / "summary.txt").write_text(text)
    print(text, end="")
    log(f"callgrind's annotation {out / 'annotate.txt'}, summary {out / 'summary.txt'}")
    return 0


def main(argv):
    PREFIX[0] = "profile-sim"
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--build", help="the profiling build (default build/prof; with --callgrind, build)")
    ap.add_argument("--callgrind", action="store_true",
                    help="make sim's model under callgrind, instructions by RTL instance (default: a crop)")
    ap.add_argument("sim_args", nargs="*", help="mcadsw_sim's arguments (default: CIF Teddy, D = 64, raw)")
    a = ap.parse_args(argv)
    if a.callgrind:
        return callgrind(a)
    a.build = a.build or str(ROOT / "build" / "prof")
    build = Path(a.build).resolve()
    out = build / "profile"
    if not shutil.which("perf"):
        raise FlowError("perf (Debian package linux-perf) is missing", 2)
    log(f"building the instrumented model ({build})")
    build.mkdir(parents=True, exist_ok=True)
    cmake_build(build, ["-DMCADSW_PROFILE=ON", "-DMCADSW_BLOCK_BENCHES=none", "-DMCADSW_CORE_MODEL=OFF"],
                ["mcadsw_sim"], build / "profile_build.log")
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    args = a.sim_args or [str(ROOT / p) if "/" in p else p for p in DEFAULT_FRAME]
    exe = build / "bin" / "mcadsw_sim"
    data = out / "perf.data"
    run_under(["perf", "record", "-q", "-F", "1000", "-e", "cpu-clock", "-o", str(data)], exe, args, out,
              "perf record")
    rep = subprocess.run(["perf", "report", "-i", str(data), "--stdio", "--no-children", "--sort", "symbol",
                          "--percent-limit", "0", "-g", "none"], capture_output=True, text=True)
    if rep.returncode != 0:
        raise FlowError(f"perf report failed: {rep.stderr.strip()[-500:]}")
    (out / "perf.txt").write_text(rep.stdout)
    m = re.search(r"# Samples: (\S+)", rep.stdout)
    text = summarise(rep.stdout, m.group(1) if m else "?")
    (out / "summary.txt").write_text(text)
    print(text, end="")
    log(f"perf's report {out / 'perf.txt'}, summary {out / 'summary.txt'}")
    return 0


if __name__ == "__main__":
    sys.exit(run_main(main, sys.argv[1:], "profile-sim"))
