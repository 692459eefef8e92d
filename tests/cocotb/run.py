#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""ctest cocotb_mcadsw_axi: the wrapper mcadsw_axi under cocotbext-axi's models in Icarus
Verilog (tests/cocotb/test_mcadsw_axi.py), one small frame per mode:

    tests/cocotb/run.py BUILD_DIR [MODE ...]      (modes: raw subpixel lr rect; default all)
    tests/cocotb/run.py BUILD_DIR --waves DIR     the datasheet's timing diagrams as WaveJSON
                                                  into DIR (tests/cocotb/waves.py; make docs-waves)

For each mode, BUILD_DIR/bin/mcadsw_sim runs the frame on the Verilated SoC, compares it
with the C++ reference (exit 1 and no test if it differs) and dumps the memory image, the
driver's register writes and the output (--dump); then cocotb runs the frame on the
wrapper with random back-pressure and compares every output byte. Icarus, not Verilator:
cocotb 2 needs Verilator 5.036 or later, the pinned 5.052 would do, but Icarus builds the
model in seconds where Verilator's build of the SoC takes minutes, and these frames are
small. Environment: MCADSW_SEED (default 1), MCADSW_PAUSE (a channel's pause probability a
cycle, default 0.3), KEEP_DIR (keep the work folder there).
"""
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile

from cocotb_tools.check_results import get_results
from cocotb_tools.runner import get_runner

ROOT = pathlib.Path(__file__).resolve().parents[2]
TEDDY = ROOT / "data" / "cif" / "teddy"
RAW = ROOT / "data" / "raw" / "C" / "cif" / "teddy"
# Small frames (Icarus runs this SoC at a few hundred cycles a second, cocotb's models halve
# that): the raw mode on tests/icarus/run.sh's Teddy crop, 22x12 at D = 10 (two output
# blocks, about 3 100 cycles); the other modes on 16x8 at D = 8 (sub-pixel about 1 900, LR
# three passes about 4 100, the rectified frame of camera C's raw views, step 8, about 2 900).
TINY = ["--crop", "150,120,16,8", "-d", "8"]
MODES = {
    "raw": [str(TEDDY / "left.png"), str(TEDDY / "right.png"), "--crop", "150,120,22,12", "-d", "10"],
    "subpixel": [str(TEDDY / "left.png"), str(TEDDY / "right.png"), *TINY, "--subpixel"],
    "lr": [str(TEDDY / "left.png"), str(TEDDY / "right.png"), *TINY, "--lr"],
    "rect": [str(RAW / "left.png"), str(RAW / "right.png"), "-d", "8", "--crop", "16,8,16,8",
             "--calib", str(RAW / "calib.yml"), "--step", "8"],
}
# The timing diagrams' frame: column-tiled input planes, so the reads are bursts.
WAVES = [str(TEDDY / "left.png"), str(TEDDY / "right.png"), *TINY, "--tiled"]


def rtl_files():
    out = subprocess.run([str(ROOT / "scripts" / "rtl_files.sh")], check=True, capture_output=True,
                         text=True).stdout.split()
    return out + [str(ROOT / "rtl" / "mcadsw_axi.v")]


def main(argv):
    if not argv:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    build = pathlib.Path(argv[0]).resolve()
    waves = None
    if len(argv) == 3 and argv[1] == "--waves":
        waves = pathlib.Path(argv[2]).resolve()
        argv = argv[:1]
    modes = ["waves"] if waves else (argv[1:] or list(MODES))
    bad = [m for m in modes if m not in MODES and not waves]
    if bad:
        print(f"cocotb: unknown mode(s) {', '.join(bad)}; known: {', '.join(MODES)}", file=sys.stderr)
        return 2
    keep = os.environ.get("KEEP_DIR")
    work = pathlib.Path(keep) if keep else pathlib.Path(tempfile.mkdtemp(prefix="mcadsw_cocotb_"))
    work.mkdir(parents=True, exist_ok=True)
    try:
        for m in modes:
            d = work / m
            d.mkdir(exist_ok=True)
            r = subprocess.run([str(build / "bin" / "mcadsw_sim"), *(WAVES if waves else MODES[m]), "--dump", str(d)],
                               capture_output=True, text=True)
            print(f"cocotb ({m}): mcadsw_sim {r.stdout.strip().splitlines()[-1] if r.stdout.strip() else ''}")
            if r.returncode != 0 or "BIT-EXACT" not in r.stdout:
                sys.stderr.write(r.stdout + r.stderr)
                print(f"cocotb ({m}): the Verilated SoC is not bit-exact with the reference: no test",
                      file=sys.stderr)
                return 1
        runner = get_runner("icarus")
        runner.build(sources=rtl_files(), includes=[str(ROOT / "rtl")], hdl_toplevel="mcadsw_axi",
                     build_args=["-g2012"], build_dir=str(work / "sim_build"), timescale=("1ns", "1ps"),
                     always=True)
        if waves:
            xml = runner.test(hdl_toplevel="mcadsw_axi", hdl_toplevel_lang="verilog", test_module="waves",
                              test_dir=str(pathlib.Path(__file__).parent), build_dir=str(work / "sim_build"),
                              results_xml=str(work / "waves.xml"),
                              extra_env={"MCADSW_DUMP": str(work / "waves"), "MCADSW_WAVES": str(waves)})
            n, fails = get_results(pathlib.Path(xml))
            print(f"cocotb (waves): {'written to ' + str(waves) if n and not fails else 'FAILED'}")
            return 0 if n and not fails else 1
        failed = 0
        for m in modes:
            xml = runner.test(hdl_toplevel="mcadsw_axi", hdl_toplevel_lang="verilog", test_module="test_mcadsw_axi",
                              test_dir=str(pathlib.Path(__file__).parent), build_dir=str(work / "sim_build"),
                              results_xml=str(work / f"{m}.xml"),
                              extra_env={"MCADSW_DUMP": str(work / m),
                                         "MCADSW_SEED": os.environ.get("MCADSW_SEED", "1"),
                                         "MCADSW_PAUSE": os.environ.get("MCADSW_PAUSE", "0.3")})
            n, fails = get_results(pathlib.Path(xml))
            print(f"cocotb ({m}): {n - fails} of {n} passed")
            failed += fails if n else 1
        return 1 if failed else 0
    finally:
        if not keep:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
