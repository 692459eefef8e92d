#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""Bad input to `make synth` and `make fpga` (flow/synth.py synth, fpga) gives one clear message
and a non-zero exit, and leaves no summary.json of an earlier run behind as if it were the new
result (ctest synth_bad_input). No synthesis runs: the cases stop at the configuration check
(gen_rtl_pkg), the tool checks, at elaboration (a few seconds) or at the first block (Yosys
replaced by a stub that fails block runs). Then `make synth-check`'s checker on summaries within
and over a budget, and the reading of the engine's endpoint slacks per instance (the
rectifier's worst slack).
  tests/synth/bad_input.py [GEN_RTL_PKG]   (about 30 s; needs yosys, sta, the OSU018 liberty
                                           and gen_rtl_pkg, default build/bin/)
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent.parent
sys.path.insert(0, str(ROOT / "flow"))
import sta  # noqa: E402

PY = sys.executable            # the interpreter itself: the no_yosys case runs it with a bare PATH
DRIVER = str(ROOT / "flow" / "synth.py")
fails = 0


def fail(name, why, text=""):
    global fails
    fails += 1
    print(f"FAIL {name}: {why}")
    for line in text.splitlines()[-15:]:
        print(f"  | {line}")


def expect(work, name, want_rc, regex, cmd, stale=("summary.json", "mcadsw_engine_osu018.v"), env=None):
    """CMD (with {out} the output folder, holding stale result files STALE) exits WANT_RC, says
    REGEX on stderr and leaves none of STALE behind. Returns its stderr."""
    out = work / f"out_{name}"
    out.mkdir(parents=True, exist_ok=True)
    for f in stale:
        (out / f).write_text('{"stale": true}\n')
    t0 = time.time()
    r = subprocess.run([c.format(out=out) for c in cmd], capture_output=True, text=True, env=env)
    why = []
    if r.returncode != want_rc:
        why.append(f"exit {r.returncode}, wanted {want_rc}")
    hit = re.search(regex, r.stderr)
    if not hit:
        why.append(f"stderr lacks /{regex}/")
    why += [f"stale {f} left in OUT" for f in stale if (out / f).exists()]
    if why:
        fail(name, "; ".join(why), r.stderr)
    else:
        line = next(ln for ln in r.stderr.splitlines() if re.search(regex, ln))
        print(f"ok   {name} (exit {r.returncode}, {time.time() - t0:.0f} s): {line}")
    return r.stderr


def flows(work, gen):
    synth = [PY, DRIVER, "synth", "--out", "{out}", "--gen-rtl-pkg", gen]
    # Unknown or unsupported DMAX (1 .. 128), checked by gen_rtl_pkg.
    for name, arg, msg in [("dmax_zero", ["--dmax", "0"], "DMAX='0' is not supported: an integer from 1 to 128"),
                           ("dmax_text", ["--dmax", "abc"], "DMAX='abc' is not supported"),
                           ("dmax_above", ["--dmax", "129"], "DMAX='129' is not supported"),
                           ("dmax_neg", ["--dmax=-4"], "DMAX='-4' is not supported"),
                           ("dmax_zeros", ["--dmax", "064"], "DMAX='064' is not supported"),
                           # PAR: 1, 2 or 4, and DMAX a multiple of it.
                           ("par_three", ["--par", "3"], "PAR='3' is not supported: 1, 2 or 4"),
                           ("par_text", ["--par", "x"], "PAR='x' is not supported"),
                           ("par_dmax", ["--dmax", "18", "--par", "4"], "DMAX=18 is not a multiple of PAR=4"),
                           # The clock gating's group size (0: no gating).
                           ("gate_text", ["--clock-gate-min", "x"], "clock-gate-min 'x' is not a non-negative integer"),
                           ("gate_neg", ["--clock-gate-min=-1"], "clock-gate-min '-1' is not a non-negative integer")]:
        expect(work, name, 2, re.escape(msg), synth + arg)
    expect(work, "no_gen", 2, re.escape(f"gen_rtl_pkg not found at {work}/none"),
           [PY, DRIVER, "synth", "--out", "{out}", "--gen-rtl-pkg", f"{work}/none"])

    # make fpga (flow/synth.py fpga): the same checks (the same generator), before any synthesis.
    fpga = [PY, DRIVER, "fpga", "--out", "{out}", "--gen-rtl-pkg", gen]
    for name, arg, msg in [("fpga_dmax_zero", ["--dmax", "0"],
                            re.escape("fpga: gen_rtl_pkg: DMAX='0' is not supported: an integer from 1 to 128")),
                           ("fpga_dmax_text", ["--dmax", "x1"], re.escape("DMAX='x1' is not supported")),
                           ("fpga_par_three", ["--par", "3"], re.escape("PAR='3' is not supported: 1, 2 or 4")),
                           ("fpga_par_dmax", ["--dmax", "10", "--par", "4"],
                            re.escape("DMAX=10 is not a multiple of PAR=4")),
                           ("fpga_par_two", ["--par", "2"],
                            "the FPGA target takes one disparity a step .PAR=1., not PAR=2")]:
        expect(work, name, 2, msg, fpga + arg, stale=("summary.json", "report.md"))

    # A missing tool: a PATH with everything the driver needs except yosys.
    binp = work / "bin"
    binp.mkdir()
    if shutil.which("sta"):
        (binp / "sta").symlink_to(shutil.which("sta"))
    expect(work, "no_yosys", 2, re.escape("'yosys' not found in PATH"), synth, env=dict(os.environ, PATH=str(binp)))

    # A broken source: elaboration fails, the message names the file (Yosys's error).
    rtl = work / "rtl"
    shutil.copytree(ROOT / "rtl", rtl)
    fifo = rtl / "mcadsw_depth_fifo.sv"
    fifo.write_text(fifo.read_text().replace("endmodule", "  this is not verilog;\nendmodule", 1))
    err = expect(work, "broken_source", 1, "elaboration of mcadsw_engine failed", synth + ["--rtl", str(rtl)])
    if "mcadsw_depth_fifo.sv" not in err:
        fail("broken_source", "the message does not name mcadsw_depth_fifo.sv")

    # A failing block: a Yosys stub that elaborates with the real Yosys and fails every block
    # run with an error in the block's log.
    stub = work / "yosys_stub"
    stub.write_text(f"""#!{PY}
import os, sys
args = sys.argv[1:]
if any("elab.tcl" in a for a in args) or args == ["-V"]:
    os.execv({shutil.which("yosys")!r}, ["yosys"] + args)
if "-l" in args[:-1]:
    with open(args[args.index("-l") + 1], "w") as f:
        f.write("reading the design\\nERROR: simulated failure of this block (tests/synth/bad_input.py)\\n")
sys.exit(1)
""")
    stub.chmod(0o755)
    err = expect(work, "failing_block", 1, r"block '[a-z_]+' \(module mcadsw_[a-z_]+\) failed",
                 synth + ["--yosys", str(stub)])
    if "simulated failure of this block" not in err:
        fail("failing_block", "the log tail is not in the message")
    if "no summary.json written" not in err:
        fail("failing_block", "no final line")


def check_case(work, name, budget, summary, want_rc, has=(), lacks=(), failed_lines=None):
    """make synth-check's checker (flow/synth.py check) on SUMMARY against BUDGET."""
    (work / "budget.json").write_text(json.dumps(budget))
    (work / "summary.json").write_text(json.dumps(summary))
    r = subprocess.run([PY, DRIVER, "check", "--budget", str(work / "budget.json"), "--summary",
                        str(work / "summary.json")], capture_output=True, text=True)
    out = r.stdout + r.stderr
    why = [f"exit {r.returncode}, wanted {want_rc}"] if r.returncode != want_rc else []
    why += [f"lacks '{s}'" for s in has if s not in out] + [f"says '{s}'" for s in lacks if s in out]
    if failed_lines is not None and out.count("FAILED  ") != failed_lines:
        why.append(f"{out.count('FAILED  ')} FAILED lines, wanted {failed_lines}")
    if why:
        fail(f"synth_check {name}", "; ".join(why), out)
    else:
        print(f"ok   synth_check {name} (exit {r.returncode})")


def checker(work):
    # A budget of its own, independent of constraints/budget.json's figures.
    budget = {"nand2_eq_max": 563000, "wns_ns_min": 0, "memory_kB_max": 57.1, "clock_mhz": 95.0}
    base = {"dmax": 64, "nand2_eq": 500000, "memory_kB": 57.0, "clock_mhz": 95.0, "wns_ns": 0, "worst_slack_ns": 0.3}
    check_case(work, "gates and slack over budget", budget,
               dict(base, nand2_eq=600000, wns_ns=-0.2, worst_slack_ns=-0.2), 1,
               has=("FAILED  gates", "FAILED  worst slack"), lacks=("FAILED  on-chip memory",))
    check_case(work, "memory over budget", budget, dict(base, memory_kB=57.2), 1,
               has=("FAILED  on-chip memory",), lacks=("FAILED  gates",))
    check_case(work, "within budget", budget, base, 0)
    # The engine within budget, its SoC wrapper not: the total over the gate budget, a
    # wrapper block missing the clock.
    check_case(work, "SoC wrapper over budget", budget, dict(base, soc_total_nand2_eq=570000, soc_worst_slack_ns=-0.1),
               1, has=("FAILED  gates with the SoC wrapper", "FAILED  SoC wrapper slack"),
               lacks=("FAILED  gates (NAND2",))
    # A budget that forbids asynchronous-read macros: a summary with one fails, one without
    # the figure is an error (exit 2), one with none passes.
    b_async = dict(budget, async_read_macros_max=0)
    check_case(work, "asynchronous-read macro", b_async, dict(base, async_read_macros=1), 1,
               has=("FAILED  async-read macros",), lacks=("FAILED  on-chip memory",))
    check_case(work, "summary without the asynchronous-read count", b_async, base, 2,
               has=("async_read_macros' missing",))
    check_case(work, "no asynchronous-read macro", b_async, dict(base, async_read_macros=0), 0,
               has=("ok      async-read macros",))
    # A budget with the rectifier's limits: a summary without its figures is an error
    # (exit 2); its gates, memory and slack each fail on their own; within passes.
    b_rect = dict(budget, rect_nand2_eq_max=60000, rect_memory_kB_max=4.0)
    check_case(work, "summary without the rectifier's figures", b_rect, base, 2, has=("rect_nand2_eq' missing",))
    rect = dict(base, rect_nand2_eq=59000, rect_memory_kB=4.0, rect_worst_slack_ns=0.1, rect_async_read_macros=0)
    check_case(work, "rectifier within budget", b_rect, rect, 0, has=("ok      rectifier gates",))
    for key, value, what in [("rect_nand2_eq", 60001, "rectifier gates"), ("rect_memory_kB", 4.1, "rectifier memory"),
                             ("rect_worst_slack_ns", -0.01, "rectifier slack"),
                             ("rect_async_read_macros", 1, "rectifier async-read")]:
        check_case(work, f"{what} over budget", b_rect, dict(rect, **{key: value}), 1, has=(f"FAILED  {what}",),
                   failed_lines=1)
    # The rectifier's slack is null when the engine's STA had no endpoint of one of its
    # instances (flow/synth.py warns): an error (exit 2), not a pass.
    check_case(work, "rectifier slack null", b_rect, dict(rect, rect_worst_slack_ns=None), 2,
               has=("rect_worst_slack_ns' missing",))


STA_LOG = """max_delay/setup group clk

                                     Required   Actual
Endpoint                                Delay    Delay    Slack
---------------------------------------------------------------
u_rect_mark._7_/D (DFFPOSX1)            10.050   10.150   -0.100 (VIOLATED)
u_rect._100_/D (DFFPOSX1)               10.050    8.847    1.203 (MET)
u_rect.banks_0/WR_DATA[3] (MCADSW_RAM_S256_W16_A8_SYNC_WE)   10.000    3.000    7.000 (MET)
u_post._15412_/D (DFFPOSX1)             10.050   10.250   -0.200 (VIOLATED)
_2023_/D (DFFSR)                        10.180   10.490   -0.310 (VIOLATED)
mem_addr_o[31] (output)                  8.170    7.220    0.950 (MET)
u_rect_mark.clock_gate_0_and/B (AND2X2) 10.280    5.450    4.830 (MET)
"""


def endpoint_slack(work):
    # The rectifier's worst slack is read from the engine's sta_endpoints.log (flow/sta.py
    # endpoint_slack): every endpoint whose flattened name starts with the instance and a dot,
    # u_rect not taking u_rect_mark's; the violating ones per block instance.
    log = work / "sta_endpoints.log"
    log.write_text(STA_LOG)
    viol, inst = sta.endpoint_slack(str(log), ["u_rect", "u_rect_mark", "u_rect_check"])
    got = (sorted(viol.items()), sorted(inst.items()))
    want = ([("top", (1, -0.31)), ("u_post", (1, -0.2)), ("u_rect_mark", (1, -0.1))],
            [("u_rect", (2, 1.203)), ("u_rect_check", (0, None)), ("u_rect_mark", (2, -0.1))])
    if got == want:
        print("ok   sta endpoint_slack per instance (the rectifier's worst slack)")
    else:
        fail("sta endpoint_slack per instance", f"got {got}, wanted {want}")


def main(argv):
    gen = argv[0] if argv else os.environ.get("GEN_RTL_PKG", str(ROOT / "build" / "bin" / "gen_rtl_pkg"))
    if not os.access(gen, os.X_OK):
        print(f"bad_input: no gen_rtl_pkg at {gen} (cmake --build build --target gen_rtl_pkg)")
        return 1
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        flows(work, gen)
        checker(work)
        endpoint_slack(work)
    if fails:
        print(f"bad_input: {fails} case(s) failed")
        return 1
    print("bad_input: all cases passed")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
