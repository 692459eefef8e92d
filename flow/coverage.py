#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""make coverage: Verilator line and toggle coverage of the engine RTL under the regression
stimulus. Builds a coverage-instrumented model in BUILD_DIR (default build/cov;
-DMCADSW_COVERAGE=ON), runs the engine tests (faults, invalid configurations, small pairs), the
random differential regression (N cases, default 40, seed 2026) and bundled pairs through the
harness, as many at a time as there are cores, merges the per-run files and reports line and
toggle coverage per module. Then checks the toggle points left at 0 against
tests/coverage/untoggled.txt (each listed with its reason; scripts/untoggled_check.awk) and the
total toggle coverage against --min-toggle percent (default 90): an unlisted point, a stale
line or less coverage fails (exit 1).

  python3 flow/coverage.py [--build BUILD_DIR] [--n CASES] [--min-toggle PERCENT]

Outputs BUILD_DIR/coverage/: merged.dat, coverage.info (lcov), annotated/ (sources with
per-line counts), summary.txt.
"""
import argparse
import os
import shutil
import subprocess
import sys
import time
from collections import defaultdict
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from flowlib import FlowError, cmake_build, log, PREFIX, ROOT, run_main, tail  # noqa: E402

# The coverage model is built with Debian's Verilator 5.006, not the tool environment's 5.052:
# 5.052's runtime counts the toggles of a signal wider than 64 bits wrongly (its
# VL_COV_TOGGLE_CHG_ST_W credits bit 32 k + j with the changes of bit j of the lower words;
# docs/tool_notes.md 2 has the reproduction), so its toggle figures and the list's would be
# wrong wherever a bus is wide.
VROOT = Path("/usr/share/verilator")
VCOV = Path("/usr/bin/verilator_coverage")
N_LISTED = 40   # tests/coverage/untoggled.txt is for this stimulus


def stimulus(build, n):
    """The runs, longest first: (title, log name, commands run one after the other)."""
    b, d = build / "bin", ROOT / "data"
    sim = str(b / "mcadsw_sim")
    return [
        ("engine tests (faults, invalid configurations)", "engine_test", [[str(b / "rtl_engine_test")]]),
        (f"{n} random cases (seed 2026)", "random",
         [[str(b / "mcadsw_sim_random"), "--cases", str(n), "--seed", "2026"]]),
        ("AXI tests (bursts, response errors, abort, the register window)", "axi_test", [[str(b / "rtl_axi_test")]]),
        ("Tsukuba D=16 with random latency, CIF Teddy crop D=64, camera C's raw Teddy rectified (LR)", "pairs", [
            [sim, f"{d}/middlebury/tsukuba/left.png", f"{d}/middlebury/tsukuba/right.png", "-d", "16",
             "--random-latency", "3"],
            [sim, f"{d}/cif/teddy/left.png", f"{d}/cif/teddy/right.png", "-d", "64", "--crop", "60,40,120,60"],
            [sim, f"{d}/raw/C/cif/teddy/left.png", f"{d}/raw/C/cif/teddy/right.png", "-d", "24",
             "--calib", f"{d}/raw/C/cif/teddy/calib.yml", "--step", "8", "--crop", "16,16,96,48", "--lr",
             "--subpixel"]]),
    ]


def run_stimulus(out, name, cmds, env):
    """CMDS one after the other into OUT/NAME.log; the first failing exit code, or 0."""
    with open(out / f"{name}.log", "w") as f:
        for cmd in cmds:
            rc = subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT, env=env).returncode
            if rc != 0:
                return rc
    return 0


def summary(merged):
    """Line and toggle coverage per module from MERGED: each C line names its page
    (v_line/<module>, v_toggle/<module>, v_branch/<module>: branches count as lines, as
    --coverage-line does) and ends with its count. Returns (text, toggle percent)."""
    tot, hit = defaultdict(int), defaultdict(int)
    for line in merged.read_text(errors="replace").splitlines():
        if not line.startswith("C "):
            continue
        count = int(line.rsplit(None, 1)[-1])
        page = line.split("\001page\002", 1)[1].split("\001", 1)[0]
        kind, mod = (page.split("/") + [""])[:2]
        kind = "v_line" if kind == "v_branch" else kind
        for key in ((mod, kind), ("", kind)):
            tot[key] += 1
            hit[key] += count > 0

    def pct(key):
        t = tot[key]
        return f"{100 * hit[key] / t:5.1f} % ({hit[key]}/{t})" if t else "      -"
    rows = [f"{'module':<24} {'line':<24} toggle"]
    for mod in sorted({m for m, _ in tot if m}):
        rows.append(f"{mod:<24} {pct((mod, 'v_line')):<24} {pct((mod, 'v_toggle'))}")
    rows.append(f"{'TOTAL':<24} {pct(('', 'v_line')):<24} {pct(('', 'v_toggle'))}")
    t = tot[("", "v_toggle")]
    return "\n".join(rows) + "\n", (100 * hit[("", "v_toggle")] / t if t else 0.0)


def main(argv):
    PREFIX[0] = "coverage"
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--build", default=str(ROOT / "build" / "cov"), help="the coverage build (default build/cov)")
    ap.add_argument("--n", type=int, default=N_LISTED, help="random cases (default 40)")
    ap.add_argument("--min-toggle", type=float, default=90.0, help="least toggle coverage, percent (default 90)")
    a = ap.parse_args(argv)
    if a.n < 1:
        raise FlowError(f"N must be at least 1, not {a.n}", 2)
    build = Path(a.build).resolve()
    out = build / "coverage"
    if not (VROOT / "verilator-config.cmake").is_file() or not os.access(VCOV, os.X_OK):
        raise FlowError(f"Debian's Verilator missing at {VROOT} (run scripts/bootstrap.sh)", 2)
    log(f"building the instrumented model ({build})")
    build.mkdir(parents=True, exist_ok=True)
    cmake_build(build, ["-DMCADSW_COVERAGE=ON", f"-DMCADSW_VERILATOR_ROOT={VROOT}", "-DMCADSW_BLOCK_BENCHES=none",
                        "-DMCADSW_CORE_MODEL=OFF"],
                ["mcadsw_sim", "mcadsw_sim_random", "rtl_engine_test", "rtl_axi_test"], build / "coverage_build.log")
    shutil.rmtree(out, ignore_errors=True)
    (out / "runs").mkdir(parents=True)
    env = dict(os.environ, MCADSW_COVERAGE_DIR=str(out / "runs"))   # a .dat file a run, merged below
    runs = stimulus(build, a.n)
    t0 = time.time()
    with ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
        jobs = []
        for title, name, cmds in runs:
            log(title)
            jobs.append(pool.submit(run_stimulus, out, name, cmds, env))
        codes = [j.result() for j in jobs]
    failed = False
    for (title, name, _), rc in zip(runs, codes):
        if rc != 0:
            print("\n".join(tail(out / f"{name}.log", 20)))
            print(f"coverage: {title} failed ({out / f'{name}.log'})", file=sys.stderr)
            failed = True
    if failed:
        return 1
    log(f"stimulus run in {time.time() - t0:.0f} s")

    dats = sorted(str(p) for p in (out / "runs").glob("*.dat"))
    merged = out / "merged.dat"
    for cmd, dest in (([str(VCOV), "--write", str(merged)] + dats, None),
                      ([str(VCOV), "--write-info", str(out / "coverage.info"), str(merged)], None),
                      ([str(VCOV), "--annotate", str(out / "annotated"), str(merged)], out / "annotate.log")):
        with open(dest or os.devnull, "w") as f:
            if subprocess.run(cmd, stdout=f).returncode != 0:
                raise FlowError(f"{' '.join(cmd[:2])} failed")
    text, toggle = summary(merged)
    status = 0
    if a.n == N_LISTED:
        chk = subprocess.run(["awk", "-f", str(ROOT / "scripts" / "untoggled_check.awk"),
                              str(ROOT / "tests" / "coverage" / "untoggled.txt"), str(merged)],
                             capture_output=True, text=True)
        text += chk.stdout
        status = 1 if chk.returncode != 0 else 0
    else:
        text += f"untoggled points not checked: tests/coverage/untoggled.txt is for the default stimulus (N={N_LISTED})\n"
    (out / "summary.txt").write_text(text)
    print(text, end="")
    log(f"annotated sources in {out / 'annotated'}, lcov data {out / 'coverage.info'}")
    if toggle < a.min_toggle:
        print(f"coverage: toggle coverage {toggle:.1f} % is below {a.min_toggle:g} %", file=sys.stderr)
        status = 1
    if status:
        print("coverage: FAILED (tests/coverage/untoggled.txt: list each new untoggled point with its reason, "
              "delete stale lines)", file=sys.stderr)
    return status


if __name__ == "__main__":
    sys.exit(run_main(main, sys.argv[1:], "coverage"))
