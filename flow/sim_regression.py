#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""The `make sim` regression: the Verilated engine on the bundled pairs (and a small crop,
quick to trace with WAVES=1), every disparity compared with the reference; raw mode, the
sub-pixel mode (16-bit output, docs/algorithm.md 12.6), the right view as base (12.1; no error
figure: the bundled ground truth is the left view's), the LR mode (12.2-12.5: output, mask and
both scratch maps compared), column-tiled input planes and raw camera pairs rectified by the
engine. Runs two cases at a time with a line as each ends (k/N, the time left), then prints one
row per case, writes BUILD/sim/summary.json and exits non-zero on any mismatch, timeout or error.

  python3 flow/sim_regression.py --build BUILD_DIR [--case NAME] [--waves 1] [--out DIR]

--case: that case only; --waves 1: also OUT/CASE.fst and a gtkwave save file OUT/CASE.gtkw
grouping the signals by block (with --case); --out: the outputs' folder (default BUILD/sim).
"""
import argparse
import json
import math
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor, as_completed
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from flowlib import FlowError, log, PREFIX, ROOT, run_main  # noqa: E402

# name, set, pair, D ("DMAX": the build's), ground-truth scale, further options
CASES = [
    ("cif_tsukuba", "cif", "tsukuba", 64, 16, ""),
    ("cif_venus", "cif", "venus", 64, 8, ""),
    ("cif_teddy", "cif", "teddy", 64, 4, ""),
    ("cif_cones", "cif", "cones", 64, 4, ""),
    ("tsukuba", "middlebury", "tsukuba", 16, 16, ""),
    ("venus", "middlebury", "venus", 20, 8, ""),
    ("teddy", "middlebury", "teddy", 60, 4, ""),
    ("cones", "middlebury", "cones", 60, 4, ""),
    ("tsukuba_random_latency", "middlebury", "tsukuba", 16, 16, "--random-latency 1"),
    ("teddy_crop", "cif", "teddy", 64, 4, "--crop 100,100,74,38"),
    ("cif_teddy_sub", "cif", "teddy", 64, 4, "--subpixel"),
    ("tsukuba_sub", "middlebury", "tsukuba", 16, 16, "--subpixel"),
    ("venus_sub", "middlebury", "venus", 20, 8, "--subpixel"),
    ("teddy_sub", "middlebury", "teddy", 60, 4, "--subpixel"),
    ("cones_sub", "middlebury", "cones", 60, 4, "--subpixel"),
    ("teddy_crop_sub_stride", "cif", "teddy", 64, 4, "--crop 100,100,74,38 --subpixel --out-stride 1000 --random-latency 2"),
    ("cif_teddy_right", "cif", "teddy", 64, 4, "--right"),
    ("tsukuba_right_sub", "middlebury", "tsukuba", 16, 16, "--right --subpixel"),
    ("venus_right", "middlebury", "venus", 20, 8, "--right"),
    ("teddy_right_sub", "middlebury", "teddy", 60, 4, "--right --subpixel"),
    ("cones_right", "middlebury", "cones", 60, 4, "--right"),
    ("cif_teddy_lr", "cif", "teddy", 64, 4, "--lr"),
    ("cif_teddy_lr_sub", "cif", "teddy", 64, 4, "--lr --subpixel"),
    ("tsukuba_lr", "middlebury", "tsukuba", 16, 16, "--lr"),
    ("venus_lr", "middlebury", "venus", 20, 8, "--lr"),
    ("teddy_lr", "middlebury", "teddy", 60, 4, "--lr"),
    ("cones_lr_sub", "middlebury", "cones", 60, 4, "--lr --subpixel"),
    ("teddy_crop_lr_sub_latency", "cif", "teddy", 64, 4, "--crop 100,100,74,38 --lr --subpixel -T 3 --random-latency 4"),
    # Column-tiled input planes (read bursts, docs/memory_map.md), at zero latency and with a
    # DDR-like memory (30 wait states, an AR at most every 8 clocks), raster for comparison.
    ("cif_tsukuba_tiled", "cif", "tsukuba", 64, 16, "--tiled"),
    ("cif_tsukuba_ddr", "cif", "tsukuba", 64, 16, "--latency 30 --ar-interval 8"),
    ("cif_tsukuba_tiled_ddr", "cif", "tsukuba", 64, 16, "--tiled --latency 30 --ar-interval 8"),
    ("cones_right_tiled", "middlebury", "cones", 60, 4, "--right --tiled --tile-stride 1600 --random-latency 5"),
    ("teddy_crop_lr_tiled", "cif", "teddy", 64, 4, "--crop 100,100,74,38 --lr --tiled --random-latency 6"),
    # Disparities up to about 120 (data/cif_x2: 2x upscaled Teddy and Cones) at D = the
    # build's DMAX (64 by default, 128 with make sim DMAX=128).
    ("cif_x2_teddy_dDMAX", "cif_x2", "teddy", "DMAX", 2, ""),
    ("cif_x2_cones_dDMAX", "cif_x2", "cones", "DMAX", 2, ""),
    # VGA (640x480, data/vga_x2): cycles and frame rate of the wider frames.
    ("vga_x2_teddy_dDMAX", "vga_x2", "teddy", "DMAX", 2, ""),
    # Raw camera frames rectified by the engine (docs/blocks/rectifier.md; data/raw: cameras
    # A, B, C made from the pairs above, their calibration files): the rectified planes,
    # validity bitmaps and depth compared; no error figure (the invalid code is no disparity).
    # B at zero latency is the speed bar's case (2.70 M cycles), tiled with the DDR-like memory
    # the second bar (2.95 M); C has invalid strips (sub-pixel: 0xFFFF there); the LR mode
    # with its marks (dR 255, dL flagged before the post stage; the code after it).
    ("cif_teddy_rect_b", "raw/B/cif", "teddy", 64, 4, ""),
    ("cif_teddy_rect_b_tiled_ddr", "raw/B/cif", "teddy", 64, 4, "--tiled --latency 30 --ar-interval 8"),
    ("cif_teddy_rect_c_sub", "raw/C/cif", "teddy", 64, 4, "--subpixel --step 8"),
    ("teddy_rect_a_right_s32", "raw/A/middlebury", "teddy", 60, 4, "--right --step 32 --random-latency 7"),
    ("cif_teddy_rect_b_lr", "raw/B/cif", "teddy", 64, 4, "--lr"),
    ("cif_teddy_rect_c_lr_sub", "raw/C/cif", "teddy", 64, 4, "--lr --subpixel --random-latency 8"),
]

# The wave save file's groups: title, scope (ENG: the engine inside the model's top,
# rtl/mcadsw_top.sv), signals.
ENG = "mcadsw_top.u_engine"
WAVE_GROUPS = [
    ("Registers (AXI4-Lite)", "mcadsw_top.u_regs",
     "s_awvalid_i s_awready_o s_wvalid_i s_wready_o s_bvalid_o s_bready_i s_arvalid_i s_rvalid_o start_o irq_o"),
    ("AXI4 master", "mcadsw_top.u_axi_master",
     "m_arvalid_o m_arready_i m_araddr_o m_arlen_o m_rvalid_i m_rlast_i m_awvalid_o m_awready_i m_awaddr_o "
     "m_awlen_o m_wvalid_o m_wready_i m_wlast_o m_bvalid_i wr_idle_o drain_i"),
    ("Top", ENG, "start_i busy_o done_o error_o mem_req_o mem_gnt_i mem_we_o mem_addr_o mem_rvalid_i mem_wr_idle_i"),
    ("Scheduler", f"{ENG}.u_scheduler", "prep_start_o prep_bank_o prep_done_i agg_bank_o job_valid_o job_ready_i job_row_o"),
    ("Memory controller", f"{ENG}.u_fetch.u_mem_ctrl", "rd_req_i rd_gnt_o rd_rvalid_o wr_req_i wr_gnt_o"),
    ("Census left", f"{ENG}.u_census_l", "state_q pix_valid_i pix_ready_o wcnt_q ki_q ring_free_i done_o"),
    ("Census right", f"{ENG}.u_census_r", "state_q pix_valid_i pix_ready_o wcnt_q ki_q ring_free_i done_o"),
    ("Weight generator", f"{ENG}.u_weight_gen", "state_q pix_valid_i pix_ready_o done_o r_q occ_q row_ready_o row_take_i"),
    ("Cost aggregator", f"{ENG}.u_cost_agg", "busy_q row_q d_q grp_q h2_valid_q disp_valid_o disp_grp_o"),
    ("Depth FIFO", f"{ENG}.u_depth_fifo", "count_q ready_q wr_req_o wr_gnt_i wr_addr_o wr_be_o"),
    ("Post stage (LR)", f"{ENG}.u_post", "state_q y_q early_q wq_count mem_req_o mem_gnt_i mem_we_o mem_addr_o"),
]


def cmake_cache(build, key):
    """A CMake cache variable of BUILD, or None."""
    try:
        for line in (build / "CMakeCache.txt").read_text().splitlines():
            if line.startswith(key + ":"):
                return line.split("=", 1)[1]
    except OSError:
        pass
    return None


def case_cmd(binp, out, case, waves):
    """mcadsw_sim's command line for CASE."""
    name, cset, pair, d, scale, extra = case
    src = ROOT / "data" / cset / pair
    cmd = [str(binp), str(src / "left.png"), str(src / "right.png"), "-d", str(d), "--name", name]
    if cset.startswith("raw/"):      # a raw camera pair: rectified with its calibration
        cmd += ["--calib", str(src / "calib.yml")]
    elif "--right" not in extra.split():
        cmd += ["--gt", str(src / "gt.png"), "--scale", str(scale), "--masks", str(src)]
    cmd += ["--out", str(out / f"{name}.png"), "--json", str(out / f"{name}.json")]
    if waves:
        cmd += ["--waves", str(out / f"{name}.fst")]
    return cmd + extra.split()


def run_case(binp, out, case, waves):
    name = case[0]
    t0 = time.time()
    with open(out / f"{name}.log", "w") as o, open(out / f"{name}.err", "w") as e:
        subprocess.run(case_cmd(binp, out, case, waves), stdout=o, stderr=e)
    return name, time.time() - t0


def exact(out, name):
    try:
        return "BIT-EXACT" in (out / f"{name}.log").read_text().split()
    except OSError:
        return False


def fst_firsts(fst):
    """First change time (ps) of each signal in FST (fstminer -m 1)."""
    r = subprocess.run(["fstminer", "-d", str(fst), "-m", "1"], capture_output=True, text=True)
    first = {}
    for line in r.stdout.splitlines():
        f = line.split()
        if len(f) >= 2 and f[0].startswith("#"):
            first.setdefault(f[1], int(f[0][1:]))
    return first


def fst_names(fst):
    """Full signal names as the FST holds them (vectors with their range: mem_addr_o[31:0])."""
    r = subprocess.run(["fst2vcd", str(fst)], capture_output=True, text=True)
    scope, names = [], []
    for line in r.stdout.splitlines():
        f = line.split()
        if not f:
            continue
        if f[0] == "$enddefinitions":
            break
        if f[0] == "$scope":
            scope.append(f[2])
        elif f[0] == "$upscope":
            scope.pop()
        elif f[0] == "$var":
            names.append(".".join(scope) + "." + f[4] + (f[5] if f[5] != "$end" else ""))
    return names


def write_gtkw(out, name):
    """The gtkwave save file: opens on the first block's preparation (from the first
    prep_start to the first prep_done, a tenth more on each side, marker at prep_done;
    gtkwave shows 2^-zoom time units in 200 pixels: zoom = -log2(span * 200 / 1000) for a
    1000-pixel wave pane), the signals grouped by block, values in hex."""
    fst = out / f"{name}.fst"
    first = fst_firsts(fst)
    t0, t1 = first.get(f"TOP.{ENG}.prep_start"), first.get(f"TOP.{ENG}.u_scheduler.prep_done")
    names = fst_names(fst)
    lines = [f'[dumpfile] "{fst}"', "[size] 1600 900"]
    if t0 is not None and t1 is not None:
        m = (t1 - t0) / 10
        lines += [f"[timestart] {int(max(t0 - m, 0))}", f"*{-math.log2((t1 - t0 + 2 * m) / 5):.6f} {t1}"]
    for title, scope, sigs in WAVE_GROUPS:
        lines += ["@800200", f"-{title}", "@22"]
        for s in sigs.split():
            full = f"TOP.{scope}.{s}"
            hit = next((n for n in names if n == full or n.startswith(full + "[")), None)
            if hit is None:
                raise FlowError(f"no signal {full} in the waves")
            lines.append(hit)
        lines += ["@1000200", f"-{title}"]
    gtkw = out / f"{name}.gtkw"
    gtkw.write_text("\n".join(lines) + "\n")
    print(f"waves: {fst}, one cycle = 10.526 ns (95 MHz); gtkwave save file {gtkw} opens on the")
    print("       first block's preparation" + (f" (marker at prep_done, {t1 / 1e6:.1f} us)" if t1 else "")
          + f"; open with: make wave CASE={name}")


def main(argv):
    PREFIX[0] = "sim_regression"
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--build", default=str(ROOT / "build"), help="the configuration's build directory")
    ap.add_argument("--case", default="", help="run only this case")
    ap.add_argument("--waves", default="0", help="1: an FST of the case (and a gtkwave save file with --case)")
    ap.add_argument("--out", help="the outputs' folder (default BUILD/sim)")
    a = ap.parse_args(argv)
    build = Path(a.build).resolve()
    waves = a.waves == "1"
    binp = build / "bin" / "mcadsw_sim"
    if not binp.is_file():
        raise FlowError(f"{binp} is not built")
    out = Path(a.out).resolve() if a.out else build / "sim"
    out.mkdir(parents=True, exist_ok=True)
    dmax = cmake_cache(build, "MCADSW_DMAX") or "64"
    cases = [(name.replace("DMAX", dmax), cset, pair, dmax if d == "DMAX" else d, scale, extra)
             for name, cset, pair, d, scale, extra in CASES]
    selected = [c for c in cases if not a.case or c[0] == a.case]
    # A build without the rectifier (CMake MCADSW_RECT=OFF, make sim RECT=0) leaves out the
    # rectified cases, and says so.
    if cmake_cache(build, "MCADSW_RECT") == "OFF":
        skipped = [c[0] for c in selected if c[1].startswith("raw/")]
        selected = [c for c in selected if not c[1].startswith("raw/")]
        if skipped:
            log(f"a build without the rectifier: {len(skipped)} rectified case(s) left out ({' '.join(skipped)})")
            if not selected:
                return 0
    if not selected:
        raise FlowError(f"unknown case '{a.case}'; cases:\n" + "\n".join(f"  {c[0]}" for c in cases), 2)

    print(f"== make sim: Verilated engine vs reference, {len(selected)} case(s), 2 at a time (logs in {out}) ==",
          flush=True)
    t0, spent, k = time.time(), 0.0, 0
    with ThreadPoolExecutor(max_workers=2) as pool:
        jobs = [pool.submit(run_case, binp, out, c, waves) for c in selected]
        for job in as_completed(jobs):
            name, secs = job.result()
            k += 1
            spent += secs
            left = (len(selected) - k) * spent / k / 2
            print(f"sim: {k}/{len(selected)} {name} {'bit-exact' if exact(out, name) else 'FAILED'} "
                  f"({secs:.0f} s; about {left:.0f} s left)", flush=True)
    status = 0
    rows = []
    for c in selected:
        name = c[0]
        if not exact(out, name):
            status = 1
        for ext, keep in (("log", lambda ln: True), ("err", lambda ln: not ln.startswith("  ..."))):
            p = out / f"{name}.{ext}"
            if p.is_file():
                for ln in p.read_text(errors="replace").splitlines():
                    if keep(ln):
                        print(ln)
        j = out / f"{name}.json"
        if j.is_file():
            rows.append(json.loads(j.read_text()))
    (out / "summary.json").write_text(json.dumps(rows, indent=1) + "\n")
    print(f"summary: {out / 'summary.json'}")
    if waves and a.case:
        write_gtkw(out, a.case)
    if status:
        print("make sim: FAILED (see the rows above)")
        return 1
    print(f"make sim: all {len(selected)} case(s) bit-exact in {time.time() - t0:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(run_main(main, sys.argv[1:], "sim_regression"))
