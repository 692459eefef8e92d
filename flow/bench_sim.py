#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""make bench-sim: how fast the Verilator model simulates. Times three CIF Teddy frames at D = 64
(raw, LR, and rectified from camera B's raw pair) in build/bin/mcadsw_sim, RUNS times each, and
prints each frame's median: the simulation loop's seconds and kcycles/s (as mcadsw_sim reports
them) and the process's wall time (with the image loading and the reference model). With
--baseline (a git commit, built once in BUILD_DIR/bench_sim/<commit>, or an mcadsw_sim executable) the
runs alternate between the two models, A then B, so that both see the same machine, and the
ratio of the medians is printed. A benchmark, not a test: nothing fails on a time; a run fails
only when a frame is not bit-exact or the two models' cycle counts differ.

  python3 flow/bench_sim.py [--runs 5] [--frames raw,lr,rect] [--baseline REF|EXE]

Writes BUILD_DIR/bench_sim/bench_sim.json.
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from flowlib import FlowError, cmake_build, log, PREFIX, ROOT, run_main  # noqa: E402

D = ROOT / "data"
FRAMES = {
    "raw": [f"{D}/cif/teddy/left.png", f"{D}/cif/teddy/right.png", "-d", "64"],
    "lr": [f"{D}/cif/teddy/left.png", f"{D}/cif/teddy/right.png", "-d", "64", "--lr"],
    "rect": [f"{D}/raw/B/cif/teddy/left.png", f"{D}/raw/B/cif/teddy/right.png", "-d", "64",
             "--calib", f"{D}/raw/B/cif/teddy/calib.yml"],
}
# mcadsw_sim's result line: "... N cycles ... BIT-EXACT ... (S s, K kcycles/s)".
RESULT = re.compile(r"(\d+) cycles .*\(([\d.]+) s, (\d+) kcycles/s\)")


def run_once(exe, args):
    """(cycles, loop seconds, wall seconds) of one run; raises unless it is bit-exact."""
    t0 = time.perf_counter()
    p = subprocess.run([str(exe)] + args, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    m = RESULT.search(p.stdout)
    if p.returncode != 0 or not m or "BIT-EXACT" not in p.stdout:
        raise FlowError(f"{exe} {' '.join(args)} did not end bit-exact (exit {p.returncode}):\n"
                        + (p.stdout + p.stderr)[-2000:])
    return int(m.group(1)), float(m.group(2)), wall


def build_baseline(ref, bench_dir):
    """mcadsw_sim of git commit REF, built once in BENCH_DIR/<commit>."""
    sha = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "--verify", f"{ref}^{{commit}}"],
                         capture_output=True, text=True)
    if sha.returncode != 0:
        raise FlowError(f"--baseline {ref}: neither an executable nor a git commit", 2)
    sha = sha.stdout.strip()[:12]
    src, bld = bench_dir / f"{sha}-src", bench_dir / sha
    exe = bld / "bin" / "mcadsw_sim"
    if exe.is_file():
        return exe, sha
    if not src.is_dir():
        subprocess.run(["git", "-C", str(ROOT), "worktree", "prune"], check=False)
        if subprocess.run(["git", "-C", str(ROOT), "worktree", "add", "--detach", str(src), sha],
                          stdout=subprocess.DEVNULL).returncode != 0:
            raise FlowError(f"git worktree add {src} {sha} failed")
    log(f"building the baseline model of {sha} in {bld} (once)")
    venv = ROOT / ".venv"
    if venv.is_dir() and not (src / ".venv").exists():
        (src / ".venv").symlink_to(venv)      # the pinned tools the commit's build finds there
    cmake_build(bld, ["-DMCADSW_BLOCK_BENCHES=none", "-DMCADSW_CORE_MODEL=OFF"], ["mcadsw_sim"],
                bench_dir / f"{sha}.build.log", src=src)
    if not exe.is_file():
        raise FlowError(f"the baseline's build made no {exe}")
    return exe, sha


def main(argv):
    PREFIX[0] = "bench-sim"
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--build", default=str(ROOT / "build"), help="the build whose bin/mcadsw_sim is timed")
    ap.add_argument("--runs", type=int, default=5, help="runs of each frame and model (default 5)")
    ap.add_argument("--frames", default="raw,lr,rect", help="of raw, lr, rect (default all three)")
    ap.add_argument("--baseline", default="", help="a git commit or an mcadsw_sim executable to compare with")
    a = ap.parse_args(argv)
    if a.runs < 1:
        raise FlowError(f"RUNS must be at least 1, not {a.runs}", 2)
    frames = [f for f in a.frames.split(",") if f]
    bad = [f for f in frames if f not in FRAMES]
    if bad or not frames:
        raise FlowError(f"--frames: {', '.join(bad) or '(none)'} not of {', '.join(FRAMES)}", 2)
    build = Path(a.build).resolve()
    exe = build / "bin" / "mcadsw_sim"
    if not exe.is_file():
        raise FlowError(f"{exe} is missing (make build)", 2)
    bench_dir = build / "bench_sim"
    bench_dir.mkdir(parents=True, exist_ok=True)
    models = [("this build", exe)]
    if a.baseline:
        b = Path(a.baseline)
        if b.is_file() and os.access(b, os.X_OK):
            models.append((str(b), b.resolve()))
        else:
            bexe, sha = build_baseline(a.baseline, bench_dir)
            models.append((f"baseline {sha}", bexe))
    res = {f: {name: [] for name, _ in models} for f in frames}
    total = len(frames) * a.runs * len(models)
    k, t_all = 0, time.time()
    for f in frames:
        for r in range(a.runs):
            for name, m in models:
                cycles, loop, wall = run_once(m, FRAMES[f])
                res[f][name].append({"cycles": cycles, "loop_s": loop, "wall_s": wall})
                k += 1
                left = (time.time() - t_all) / k * (total - k)
                print(f"bench-sim: {k}/{total} {f} run {r + 1} {name}: {cycles} cycles, loop {loop:.2f} s, "
                      f"wall {wall:.2f} s ({left:.0f} s left)", flush=True)
    summary = {"runs": a.runs, "models": {n: str(m) for n, m in models}, "frames": {}}
    print(f"\nbench-sim: medians of {a.runs} runs (the simulation loop; the process's wall time)")
    for f in frames:
        row = {}
        for name, _ in models:
            rs = res[f][name]
            cyc = {x["cycles"] for x in rs}
            if len(cyc) != 1:
                raise FlowError(f"{f}: {name}'s cycle counts differ between runs: {sorted(cyc)}")
            loop = statistics.median(x["loop_s"] for x in rs)
            wall = statistics.median(x["wall_s"] for x in rs)
            row[name] = {"cycles": cyc.pop(), "loop_s": loop, "wall_s": wall,
                         "kcycles_per_s": rs[0]["cycles"] / loop / 1e3, "runs": rs}
            print(f"  {f:<5} {name:<22} {row[name]['cycles']:>9} cycles  loop {loop:6.2f} s "
                  f"({row[name]['kcycles_per_s']:5.0f} kcycles/s)  wall {wall:6.2f} s")
        if len(models) == 2:
            a_, b_ = (row[n] for n, _ in models)
            if a_["cycles"] != b_["cycles"]:
                raise FlowError(f"{f}: the two models' cycle counts differ: {a_['cycles']} against {b_['cycles']}")
            row["ratio_loop"] = a_["loop_s"] / b_["loop_s"]
            row["ratio_wall"] = a_["wall_s"] / b_["wall_s"]
            print(f"  {f:<5} ratio (this build / baseline): loop {row['ratio_loop']:.3f}, wall {row['ratio_wall']:.3f}")
        summary["frames"][f] = row
    (bench_dir / "bench_sim.json").write_text(json.dumps(summary, indent=2) + "\n")
    log(f"{bench_dir / 'bench_sim.json'}")
    return 0


if __name__ == "__main__":
    sys.exit(run_main(main, sys.argv[1:], "bench-sim"))
