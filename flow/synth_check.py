# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

"""make synth-check: the synthesis summary against constraints/budget.json (run
by flow/synth.py check)."""
import json
import sys
from pathlib import Path

from flowlib import FlowError


def check(a, synth):
    """The summary against constraints/budget.json: fails when the engine has more
    NAND2 equivalents than nand2_eq_max, a worst slack at the SDC clock below
    wns_ns_min (negative: 95 MHz missed), more on-chip memory than memory_kB_max,
    or (when the budget sets async_read_macros_max) more macros with an
    asynchronous read port; the SoC wrapper's total and slack where the summary
    has them; the rectifier's figures (rect_*) against its own limits where the
    budget has them. The engine's gates and memory are without the rectifier
    (flow/synth.py keeps its group out of them). Without --summary, runs synth(a)
    (DMAX = 64, incrementally) first."""
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
    # Memory: the engine's without the LR mode's post stage (reported apart)
    # and the rectifier where the summary has it, otherwise all of it.
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
    # The rectifier: inside the engine, reported apart from it and out of the
    # engine's figures above; its own gate and memory budget, the engine's clock (the
    # worst endpoint inside its instances in the engine's STA) and the synchronous-macro
    # rule.
    if "rect_nand2_eq_max" in budget or "rect_memory_kB_max" in budget:
        for k in ("rect_nand2_eq", "rect_memory_kB", "rect_worst_slack_ns", "rect_async_read_macros"):
            if not isinstance(s.get(k), (int, float)):
                return fail2(f"'{k}' missing from {summary_path} or not a number (the budget has the "
                             f"rectifier's limits)")
        chk("rectifier gates (NAND2 eq)", s["rect_nand2_eq"], "<=", budget.get("rect_nand2_eq_max", 0), "",
            "the rectifier exceeds its gate budget (build/synth/report.md, Rectifier)")
        chk("rectifier memory", s["rect_memory_kB"], "<=", budget.get("rect_memory_kB_max", 0), "kB",
            "the rectifier's tile buffers exceed its memory budget")
        chk("rectifier slack", s["rect_worst_slack_ns"], ">=", v["min_slack"], "ns",
            "the rectifier misses the clock (build/synth/sta_endpoints.log: endpoints u_rectifier.*)")
        chk("rectifier async-read macros", s["rect_async_read_macros"], "<=", 0, "",
            "a rectifier memory is read asynchronously")
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
