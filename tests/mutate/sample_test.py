#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""make mutate's seeded sample and its bad input (ctest mutate_sample_and_bad_input).

The sample (flow/mutate.py sample_picks) is the linear congruential generator
state = (state * 1103515245 + 12345) mod 2^31, k = state mod N + 1, from state = SEED; CI's
sample depends on it. Its draws are checked against ones computed by hand, with the mutants
the survivors list gives as equivalent skipped and drawn again in their place. Then bad
input to flow/mutate.py: one message naming the setting, exit 2, before Yosys runs. Then a
stage out of time: stopped, and killed when it ignores the stop. And REKEY=1's key
comparison and carry-over.
  tests/mutate/sample_test.py     (a few seconds; Python 3 standard library only)
"""
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent.parent
sys.path.insert(0, str(ROOT / "flow"))
import mutate  # noqa: E402

fails = 0


def check(name, got, want):
    global fails
    if got == want:
        print(f"ok   {name}: {got}")
    else:
        print(f"FAIL {name}: {got}, wanted {want}")
        fails += 1


# Seed 1: states 1103527590, 377401575, 662824084, 1147902781, 2035015474, 368800899,
# 1508029952 (each (s * 1103515245 + 12345) mod 2^31 of the one before).
# N = 10: k = 1, 6, 5, 2, 5 (drawn already), 10, 3.
check("N=10 SEED=1 SAMPLE=5", mutate.sample_picks(10, 1, 5), [1, 2, 5, 6, 10])
check("N=10 SEED=1 SAMPLE=5, 6 equivalent", mutate.sample_picks(10, 1, 5, [6]), [1, 2, 3, 5, 10])
# N = 200: k = 191, 176, 85, 182, 75, ...
check("N=200 SEED=1 SAMPLE=3", mutate.sample_picks(200, 1, 3), [85, 176, 191])
check("N=200 SEED=1 SAMPLE=3, 176 equivalent", mutate.sample_picks(200, 1, 3, [176]), [85, 182, 191])
# Seed 2: (2 * 1103515245 + 12345) mod 2^31 = 59559187, 59559187 mod 200 + 1 = 188.
check("N=200 SEED=2 SAMPLE=1", mutate.sample_picks(200, 2, 1), [188])
# CI's sample (N=200 SEED=1 SAMPLE=12) with mutants 67 and 109 listed as equivalent, as
# they are on the RTL of this test's writing (the shell script before flow/mutate.py drew
# the same).
check("CI's sample", mutate.sample_picks(200, 1, 12, [67, 109]),
      [22, 48, 52, 75, 85, 87, 100, 153, 176, 182, 186, 191])

# Equivalent mutants: by key, only those whose kind is equivalent.
rows = [("1", "m", "mutate -mode inv -cell a"), ("2", "m", "mutate -mode inv -cell b"),
        ("3", "m", "mutate -mode inv -cell c")]
survivors = ("# a comment\nmutate -mode inv -cell b\tequivalent\twhy\n"
             "mutate -mode inv -cell c\topen\twhy not\nmutate -mode inv -cell z\tequivalent\tanother RTL\n")
check("equivalents of a list", mutate.equivalent_mutants(survivors, rows), [2])

# REKEY=1: a key without what moves with RTL lines; a survivors list carried over to a draw
# of the same mutations with moved lines and renumbered cells; a different draw refused.
check("draw_key", mutate.draw_key("mutate -mode inv -module t -cell $flatten\\u_e.$and$rtl/m.sv:512$3905 "
                                  "-port A -portbit 7 -src rtl/m.sv:512.6-512.9 -src rtl/e.sv:40.1-44.4"),
      "mutate -mode inv -module t -cell $flatten\\u_e.$and$rtl/m.sv:L$N -port A -portbit 7")
prev = ("mutate -ctrl mutsel 2 1 -mode inv -cell $procmux$10 -port A -portbit 3 -src rtl/m.sv:40.1-40.9\n"
        "mutate -ctrl mutsel 2 2 -mode const0 -cell $and$rtl/m.sv:41$11 -port Y -portbit 0 -src rtl/m.sv:41.2-41.8\n")
cur = ("mutate -ctrl mutsel 2 1 -mode inv -cell $procmux$20 -port A -portbit 3 -src rtl/m.sv:38.1-38.9\n"
       "mutate -ctrl mutsel 2 2 -mode const0 -cell $and$rtl/m.sv:39$21 -port Y -portbit 0 -src rtl/m.sv:39.2-39.8\n")
listed = ("# comment\nmutate -mode const0 -cell $and$rtl/m.sv:41$11 -port Y -portbit 0 -src rtl/m.sv:41.2-41.8"
          "\tequivalent\twhy\nmutate -mode inv -cell other\topen\tanother draw's\n")
check("rekey, the same draw", mutate.rekey(prev, cur, listed),
      ("# comment\nmutate -mode const0 -cell $and$rtl/m.sv:39$21 -port Y -portbit 0 -src rtl/m.sv:39.2-39.8"
       "\tequivalent\twhy\nmutate -mode inv -cell other\topen\tanother draw's\n", 1))
try:
    mutate.rekey(prev, cur.replace("-portbit 3", "-portbit 4"), listed)
    check("rekey, another draw", "no error", "FlowError")
except mutate.FlowError as e:
    check("rekey, another draw", (e.code, str(e)), (2, "the draws differ in 1 of 2 mutants (the first: 1): "
                                                      "a new draw; run it in full and review the survivors"))

# Bad input: exit 2, the message on stderr; nothing is built.
with tempfile.TemporaryDirectory() as build:
    for args, message in (
            (["--n", "200", "--sample", "201"], "mutate: SAMPLE must be 0 (all) to N, not '201'"),
            (["--seed", "x1"], "mutate: SEED must be a number (0 to 2147483647), not 'x1'"),
            (["--n", "0"], "mutate: N must be 1 to 65535, not '0'"),
            (["--jobs", "0"], "mutate: JOBS must be 1 or more, not '0'"),
            (["--no-rect", "2"], "mutate: NO_RECT must be 0 or 1, not '2'"),
            (["--timeout", "5m"], "mutate: TIMEOUT must be a number of seconds (0: no limit), not '5m'"),
            (["--n", "20", "--mutants", "3 21"], "mutate: MUTANTS must be numbers of 1 to N (20), not '3 21'"),
            (["--report-only"], f"mutate: no results in {build}/mutate: run make mutate first")):
        r = subprocess.run([sys.executable, str(ROOT / "flow" / "mutate.py"), "--build", build] + args,
                           capture_output=True, text=True)
        check(" ".join(args), (r.returncode, r.stderr.strip()), (2, message))

# A stage out of time (flowlib.Run.wait, which make mutate's stages use): SIGTERM to its
# process group after the limit, SIGKILL a grace period later when SIGTERM is ignored.
import flowlib  # noqa: E402
run = flowlib.Run()
p = run.start(["sleep", "30"])
rc, _, late = run.wait(p, limit_s=0.5, kill_after_s=1)
check("a stage out of time: SIGTERM", (rc, late), (-15, True))
p = run.start(["bash", "-c", "trap '' TERM; sleep 30 & wait; sleep 30"])
rc, _, late = run.wait(p, limit_s=0.5, kill_after_s=1)
check("a stage that ignores SIGTERM: SIGKILL", (rc, late), (-9, True))
p = run.start(["true"])
check("a stage in time", run.wait(p, limit_s=5)[::2], (0, False))
run.stop()

sys.exit(1 if fails else 0)
