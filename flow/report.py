#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""make report: one page with the engine's quality and cost next to the paper and next to
OpenCV's matchers, every figure measured by this run (or quoted from the paper, and marked so).

  python3 flow/report.py [--build BUILD_DIR]   writes BUILD_DIR/report/report.md and PNG figures

Runs: mcadsw_report (Middlebury errors, figures), bench_ref (reference and OpenCV MDE/s, Google
Benchmark), mcadsw_sim (CIF frame at D = 64, raw and LR; a Tsukuba frame with and without FST
tracing for the simulation speed). Synthesis figures are taken from BUILD_DIR/synth/summary.json
when `make synth` has been run (40 min, so not rerun here); the report says when they are
missing.
"""
import argparse
import csv
import datetime
import json
import os
import platform
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from flowlib import FlowError, log, PREFIX, ROOT, run_main, VENV_BIN  # noqa: E402

CIF_PIXELS = 352 * 288
PAIRS = [("CIF Teddy", 64, "cif_teddy_D64"), ("Tsukuba", 16, "tsukuba_D16"), ("Venus", 20, "venus_D20"),
         ("Teddy", 60, "teddy_D60"), ("Cones", 60, "cones_D60")]


def run(cmd, stdout_path, stderr_path=None):
    """CMD with its output into STDOUT_PATH (and STDERR_PATH); a FlowError when it fails."""
    with open(stdout_path, "w") as out, open(stderr_path or os.devnull, "w") as err:
        rc = subprocess.run([str(c) for c in cmd], stdout=out, stderr=err if stderr_path else None).returncode
    if rc != 0:
        raise FlowError(f"{Path(cmd[0]).name} failed (exit {rc}; output in {stdout_path})", 2)


def bench_figures(path):
    """Google Benchmark's CSV: name (without /real_time) -> (MDE/s, real time in ms)."""
    rows = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            name = row["name"].removesuffix("/real_time")
            rows[name] = (float(row["MDE/s"]) if row.get("MDE/s") else None, float(row["real_time"]))
    return rows


def fmt(v, spec=".1f"):
    return "n/a" if v is None else format(v, spec)


def synthesis_rows(synth):
    """The synthesis table's rows from `make synth`'s summary, or the line saying it is missing."""
    if not synth.is_file():
        return ["", "Synthesis figures: not available, `make synth` has not been run in this build directory."]
    s = json.loads(synth.read_text())
    g = lambda k: "" if s.get(k) is None else s[k]  # noqa: E731
    rows = [f"| gates (NAND2 eq, memories excluded; DMAX {g('dmax')}) | {g('nand2_eq')} | "
            "562 642 (Table III, UMC 90 nm) |"]
    if g("memory_kB_engine") != "":
        rows += [f"| on-chip memory of the engine | {g('memory_kB_engine')} kB | 21.3 kB |",
                 f"| LR post stage (beyond the paper): gates, memory | {g('post_stage_nand2_eq')} NAND2 eq, "
                 f"{g('post_stage_memory_kB')} kB | |"]
    else:
        rows.append(f"| on-chip memory | {g('memory_kB')} kB | 21.3 kB |")
    slack = g("worst_slack_ns") if g("worst_slack_ns") != "" else g("wns_ns")  # older summaries: WNS only
    day = datetime.datetime.fromtimestamp(synth.stat().st_mtime, datetime.timezone.utc).strftime("%Y-%m-%d")
    rows += [f"| worst slack at 95 MHz (OSU 0.18 um) | {slack} ns | |",
             f"| achievable clock | {g('fmax_mhz')} MHz | 95 MHz (90 nm) |", "",
             f"Synthesis figures from `{synth}`, written by `make synth` on {day} (not rerun by `make report`)."]
    return rows


def main(argv):
    PREFIX[0] = "report"
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--build", default=str(ROOT / "build"), help="the build directory (default build/)")
    a = ap.parse_args(argv)
    build = Path(a.build).resolve()
    out, binp, data = build / "report", build / "bin", ROOT / "data"
    for b in ("mcadsw_report", "bench_ref", "mcadsw_sim"):
        if not os.access(binp / b, os.X_OK):
            raise FlowError(f"{binp / b} is not built (run: make build)")
    out.mkdir(parents=True, exist_ok=True)

    log("Middlebury pairs, reference and OpenCV matchers")
    run([binp / "mcadsw_report", data, out], out / "quality.md")
    log("speed (Google Benchmark)")
    run([binp / "bench_ref", "--benchmark_filter=^BM_(DisparityMap|Baseline)/", "--benchmark_format=csv",
         "--benchmark_min_time=0.5"], out / "bench.csv", out / "bench.log")
    bench = bench_figures(out / "bench.csv")

    sims = {}

    def sim(name, left, right, d, *more):
        run([binp / "mcadsw_sim", left, right, "-d", str(d), "--name", name, "--json", out / f"{name}.json",
             *more], out / f"{name}.log")
        sims[name] = json.loads((out / f"{name}.json").read_text())

    cif, tsu = data / "cif" / "teddy", data / "middlebury" / "tsukuba"
    log("CIF frame at D = 64 in the Verilated engine")
    sim("cif", cif / "left.png", cif / "right.png", 64)
    log("CIF frame at D = 64 in the LR mode (left map, right map, post stage)")
    sim("cif_lr", cif / "left.png", cif / "right.png", 64, "--lr")
    log("Tsukuba D = 16, tracing off and on")
    sim("trace_off", tsu / "left.png", tsu / "right.png", 16)
    sim("trace_on", tsu / "left.png", tsu / "right.png", 16, "--waves", out / "trace_on.fst")
    fst = out / "trace_on.fst"
    fst_mb = (fst.stat().st_size + (1 << 20) - 1) >> 20
    fst.unlink()

    c = sims["cif"]
    cycles, lr_cycles = c["cycles"], sims["cif_lr"]["cycles"]
    kcs = lambda r: f"{r['cycles'] / r['sim_seconds'] / 1e3:.0f}"  # noqa: E731
    verilator = subprocess.run([str(VENV_BIN / "verilator"), "--version"], capture_output=True,
                               text=True).stdout.split()
    lines = [
        "# MCADSW engine report", "",
        f"Generated by `make report` on {datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d} "
        f"({platform.machine()}, {os.cpu_count()} cores). Every figure is",
        "measured by that run unless marked *paper* (Chang et al., TCSVT 2010).", "",
        "## Disparity quality (Middlebury v2, bad pixels > 1, %)", "",
        "The engine's output equals the bit-exact reference's (`make sim` compares every pixel), so the",
        "MCADSW row is the RTL's. Native sizes, D = 16 / 20 / 60 / 60. OpenCV settings (dense output, left",
        "border padded by the search range so no pixel lacks candidates, invalid pixels filled from the left):", "",
        "- SGBM (3WAY and HH): colour input, blockSize 5, P1 = 8*3*5^2, P2 = 32*3*5^2, preFilterCap 63,",
        "  uniquenessRatio 0, speckle filter off, disp12MaxDiff -1; numDisparities = D rounded up to 16.",
        "- BM: grayscale input, blockSize 9, textureThreshold 0, uniquenessRatio 0, speckle filter off.",
        "  (`sw_ref/src/baselines.cpp`)", "",
        (out / "quality.md").read_text().rstrip("\n"),
        "| *paper* MCADSW (Table II, one error rate per pair) | | 2.80 | | | 0.64 | | | 13.70 | | | 10.1 | | 6.8 |",
        "| *paper* original ADSW (Table II) | | 1.85 | | | 1.19 | | | 13.3 | | | 9.79 | | 6.5 |", "",
        "Figures: for each pair the left view and the ground truth, then per method its disparity map and",
        "its error map (red: bad non-occluded pixel, yellow: bad occluded pixel, dark: not evaluated).", ""]
    for p in ("tsukuba", "venus", "teddy", "cones"):
        lines += [f"![{p}]({p}.png)", ""]
    lines += ["## Software speed (MDE/s = width x height x D / s, wall clock, all cores)", "",
              "| pair | D | reference (bit-exact) | OpenCV SGBM 3WAY | OpenCV SGBM HH | OpenCV BM | reference / SGBM 3WAY |",
              "|---|---|---|---|---|---|---|"]
    for label, d, key in PAIRS:
        ref = bench.get(f"BM_DisparityMap/{key}", (None, None))
        sg = bench.get(f"BM_Baseline/sgbm3way_{key}", (None, None))
        hh = bench.get(f"BM_Baseline/sgbm_hh_{key}", (None, None))
        bm = bench.get(f"BM_Baseline/bm_{key}", (None, None))
        ratio = f"{ref[0] / sg[0]:.2f}x" if ref[0] and sg[0] else "n/a"
        lines.append(f"| {label} | {d} | {fmt(ref[0])} ({fmt(ref[1])} ms) | {fmt(sg[0])} ({fmt(sg[1])} ms) | "
                     f"{fmt(hh[0])} | {fmt(bm[0])} | {ratio} |")
    lines += ["", "Raw results: `bench.csv` (`bench_ref`, Google Benchmark).", "",
              "## Hardware (Verilated RTL; synthesis)", "", "| figure | this engine | paper |", "|---|---|---|",
              f"| cycles per CIF frame, D = 64 | {cycles} | ~2.25 M (Sec. V-F) |",
              f"| frames/s at 95 MHz | {95e6 / cycles:.1f} | 42 (Table III) |",
              f"| cycles per CIF frame, D = 64, LR mode (beyond the paper) | {lr_cycles} ({lr_cycles / cycles:.2f} x raw, "
              f"{95e6 / lr_cycles:.1f} fps at 95 MHz) | |",
              f"| MDE/s at 95 MHz | {CIF_PIXELS * 64 * 95e6 / cycles / 1e6:.1f} | 272.5 (Table IV) |",
              f"| external reads per base-image pixel (32-bit words) | {c['words_read'] / CIF_PIXELS:.2f} | "
              "5.17 (Sec. IV, left view only) |",
              f"| external traffic at 30 CIF frames/s (reads + writes) | "
              f"{(c['words_read'] + c['words_written']) * 4 * 30 / 1e6:.1f} MB/s | |"]
    lines += synthesis_rows(build / "synth" / "summary.json")
    lines += ["", f"## Simulation speed (Verilator {verilator[1] if len(verilator) > 1 else '?'})", "",
              "| run | cycles | seconds | kcycles/s |", "|---|---|---|---|",
              f"| CIF Teddy D = 64, tracing off | {cycles} | {c['sim_seconds']} | {kcs(c)} |"]
    for name, label in (("trace_off", "Tsukuba D = 16, tracing off"),
                        ("trace_on", f"Tsukuba D = 16, FST tracing on ({fst_mb} MB)")):
        r = sims[name]
        lines.append(f"| {label} | {r['cycles']} | {r['sim_seconds']} | {kcs(r)} |")
    (out / "report.md").write_text("\n".join(lines) + "\n")
    log(f"{out / 'report.md'}")
    return 0


if __name__ == "__main__":
    sys.exit(run_main(main, sys.argv[1:], "report"))
