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


def main(argv):
    PREFIX[0] = "profile-sim"
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--build", default=str(ROOT / "build" / "prof"), help="the profiling build (default build/prof)")
    ap.add_argument("sim_args", nargs="*", help="mcadsw_sim's arguments (default: CIF Teddy, D = 64, raw)")
    a = ap.parse_args(argv)
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
    log(f"running {exe.name} {' '.join(args)}")
    t0 = time.time()
    data = out / "perf.data"
    run = subprocess.run(["perf", "record", "-q", "-F", "1000", "-e", "cpu-clock", "-o", str(data), str(exe)] + args,
                         cwd=out, capture_output=True, text=True)
    (out / "run.log").write_text(run.stdout + run.stderr)
    if run.returncode != 0:
        print(run.stdout + run.stderr)
        raise FlowError(f"the run failed (exit {run.returncode})")
    print(run.stdout, end="")
    log(f"run in {time.time() - t0:.1f} s (under perf record)")
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
