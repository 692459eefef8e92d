#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""The speed flows without a model (seconds): `make bench-sim` (flow/bench_sim.py) against
stand-in mcadsw_sim executables (a script printing mcadsw_sim's result line), and the shares of
`make profile-sim` (flow/profile_sim.py) from a small perf report written here.
  - bad input: each gives exit 2 and one clear message;
  - two models with the same cycles: medians and their ratio in bench_sim.json;
  - two models whose cycles differ, or a frame that is not bit-exact: a failure that says so;
  - a perf report: each symbol in its part, Verilog functions by module, shares summing to 100 %.
"""
import json
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "flow"))
import profile_sim  # noqa: E402

FAILS = []


def check(name, ok, detail=""):
    print(f"{'ok  ' if ok else 'FAIL'} {name}{': ' + detail if detail and not ok else ''}")
    if not ok:
        FAILS.append(name)


def fake_sim(path, cycles, seconds, exact=True):
    """An executable printing mcadsw_sim's result line."""
    path.parent.mkdir(parents=True, exist_ok=True)
    verdict = "BIT-EXACT" if exact else "MISMATCH at (3, 4): rtl 7 ref 8"
    path.write_text("#!/bin/sh\n"
                    f"echo 'left.png  352x288  D=64  {cycles} cycles  42.7 fps@95MHz  {verdict}  "
                    f"({seconds} s, {int(cycles / seconds / 1e3)} kcycles/s)'\n")
    path.chmod(0o755)
    return path


def bench(build, *args):
    p = subprocess.run([sys.executable, str(ROOT / "flow" / "bench_sim.py"), "--build", str(build)] + list(args),
                       capture_output=True, text=True)
    return p.returncode, p.stdout + p.stderr


def main():
    with tempfile.TemporaryDirectory() as t:
        t = Path(t)
        a = t / "a"
        fake_sim(a / "bin" / "mcadsw_sim", 2226986, 5.0)
        for name, args, msg in (("runs 0", ["--runs", "0"], "RUNS must be at least 1"),
                                ("unknown frame", ["--frames", "raw,qvga"], "qvga not of raw, lr, rect"),
                                ("baseline neither file nor commit", ["--baseline", "no-such-ref-xyz"],
                                 "neither an executable nor a git commit")):
            rc, out = bench(a, *args)
            check(f"bad input, {name}", rc == 2 and msg in out, f"exit {rc}: {out[-300:]}")
        rc, out = bench(t / "empty")
        check("bad input, no model", rc == 2 and "is missing" in out, f"exit {rc}: {out[-300:]}")

        b = fake_sim(t / "b" / "mcadsw_sim", 2226986, 10.0)
        rc, out = bench(a, "--runs", "3", "--frames", "raw", "--baseline", str(b))
        js = a / "bench_sim" / "bench_sim.json"
        ok = rc == 0 and js.is_file()
        if ok:
            raw = json.loads(js.read_text())["frames"]["raw"]
            ok = abs(raw["ratio_loop"] - 0.5) < 1e-9 and len(raw["this build"]["runs"]) == 3
        check("A/B: medians and the ratio 0.5", ok, out[-400:])
        c = fake_sim(t / "c" / "mcadsw_sim", 2226987, 10.0)
        rc, out = bench(a, "--runs", "1", "--frames", "raw", "--baseline", str(c))
        check("A/B: different cycle counts fail", rc != 0 and "cycle counts differ" in out, out[-300:])
        d = fake_sim(t / "d" / "bin" / "mcadsw_sim", 2226986, 5.0, exact=False)
        rc, out = bench(d.parent.parent, "--runs", "1", "--frames", "raw")
        check("a frame not bit-exact fails", rc != 0 and "did not end bit-exact" in out, out[-300:])

    report = """# Samples: 1K of event 'cpu-clock'
#
    40.00%  [.] Vmcadsw_top___024root___nba_sequent__TOP__12__PROF__mcadsw_vert_agg__l101
    20.00%  [.] Vmcadsw_top___024root___nba_comb__TOP__6__PROF__mcadsw_census__l119
    10.00%  [.] Vmcadsw_top___024root___eval_body__nba
    10.00%  [.] VerilatedContext::assertCtlGet
     8.00%  [.] mcadsw::sim::AxiMemory::read_burst
     7.00%  [.] mcadsw::vertical_aggregate
     5.00%  [k] __get_user_8
"""
    text = profile_sim.summarise(report, "1K")
    want = {"model: Verilog blocks": "60.0", "model: scheduling and glue": "10.0", "Verilator runtime": "10.0",
            "harness (memory model, driver, bench)": "8.0", "reference model": "7.0",
            "other (C++ library, kernel)": "5.0"}
    for part, pct in want.items():
        check(f"profile share of {part}", f"{pct} %  {part}" in text, text)
    check("profile, Verilog functions by module",
          "40.0 %  mcadsw_vert_agg" in text and "20.0 %  mcadsw_census" in text, text)

    # --callgrind: each model function to the instance its body names most.
    annotate = """--------------------------------------------------------------------------------
1,000 (100.0%)  PROGRAM TOTALS
--------------------------------------------------------------------------------
  500 (50.00%)  ???:Vmcadsw_top___024root___nba_sequent__TOP__12(Vmcadsw_top___024root*) [/x/mcadsw_sim]
  200 (20.00%)  ???:Vmcadsw_top___024root___nba_comb__TOP__1(Vmcadsw_top___024root*) [/x/mcadsw_sim]
  100 (10.00%)  ???:Vmcadsw_top___024root___eval_body__nba(Vmcadsw_top___024root*) [/x/mcadsw_sim]
   50 ( 5.00%)  ???:Vmcadsw_top___024root___nba_sequent__TOP__3(Vmcadsw_top___024root*) [/x/mcadsw_sim]
  100 (10.00%)  ???:VerilatedContext::assertCtlGet(VerilatedAssertCtlQuery, unsigned char) const [/x/mcadsw_sim]
   50 ( 5.00%)  ???:mcadsw::sim::AxiMemory::sample(Vmcadsw_top&) [/x/mcadsw_sim]
"""
    va = "mcadsw_top__DOT__u_engine__DOT__u_cost_agg__DOT__g_vert__BRA__0__KET____DOT__u_vert_agg__DOT__s"
    bodies = {"Vmcadsw_top___024root___nba_sequent__TOP__12": f"x = {va}; y = {va};\n"
              "z = vlSelfRef.mcadsw_top__DOT__u_regs__DOT__q;",
              "Vmcadsw_top___024root___nba_comb__TOP__1": "vlSelfRef.mcadsw_top__DOT__u_regs__DOT__rdata = 0;",
              "Vmcadsw_top___024root___eval_body__nba": f"if (x) {va} = 1;",
              "Vmcadsw_top___024root___nba_sequent__TOP__3": "vlSelfRef.clk_i = 0;"}
    total, parts, insts = profile_sim.attribute(annotate, bodies)
    check("callgrind: the total is the functions' sum", total == 1000, str(total))
    check("callgrind: a function goes to the instance it names most",
          insts.get("u_engine.u_cost_agg.g_vert[0]") == 500 and insts.get("u_regs") == 200, str(dict(insts)))
    check("callgrind: the scheduler's functions and those naming no instance are glue",
          parts["model: scheduling and glue"] == 150 and parts["model: RTL blocks"] == 700, str(dict(parts)))
    check("callgrind: runtime and harness apart", parts["Verilator runtime"] == 100
          and parts["harness (memory model, driver, bench)"] == 50, str(dict(parts)))
    return 1 if FAILS else 0


if __name__ == "__main__":
    sys.exit(main())
