#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""make mutate: mutation testing of the RTL. How much would the tests catch?

  make mutate N=200 SEED=1            the N mutants Yosys's `mutate -list N -seed SEED`
                                      spreads over the design, each run against the kill suite
  make mutate N=200 SEED=1 SAMPLE=12  a seeded sample of 12 of those N (CI), drawn from
                                      those tests/mutate/survivors.txt does not give as
                                      equivalent
  JOBS=k                              mutants run in parallel (default: the cores)
  MUTANTS="3 17"                      only these mutants of the list, again (after a new
                                      test); the other results of the last run are kept
  REPORT_ONLY=1                       the summary of the last run again (after editing
                                      tests/mutate/survivors.txt)
  NO_RECT=1                           leave the rectifier out of the mutant list: no mutant
                                      in the cells under u_engine.u_rectifier (the
                                      mcadsw_rect* modules and the FIFOs inside them); the N mutants are spread over the
                                      rest. Default 0 (the whole design). (A few cells that
                                      Yosys's optimisation makes after flattening carry no
                                      instance path and stay in the list.)
  TIMEOUT=300                         seconds a kill-suite stage (below)
  REKEY=1                             after an RTL change that moved lines but kept the
                                      draw: the survivors list's keys carried over (below)
  python3 flow/mutate.py [--n N] [--seed S] [--sample K] [--jobs J] [--mutants "3 17"]
                         [--report-only] [--rekey] [--no-rect 0|1] [--timeout S] [--build DIR]

Flow: Yosys reads the RTL as synthesis does (-DSYNTHESIS, -Irtl for the `include of
rtl/mcadsw_assert.svh in rtl/rect/), elaborates mcadsw_top (the engine, its register block
and AXI4 master: every RTL module), flattens it and applies every mutant of the list behind
a select (`mutate -ctrl mutsel W k`: mutant k is active when mutsel == k, 0 is the design as
written; the port becomes a variable set from the plusarg +mcadsw_mutant=K, below). The
design is made again when the RTL, N, SEED, NO_RECT or Yosys change. Verilator builds that
one model into the engine harness (sim/CMakeLists.txt, MCADSW_MUTANT_VERILOG; the build's
parallelism is CMake's, CMAKE_BUILD_PARALLEL_LEVEL), and the harness passes the environment
variable MCADSW_MUTANT on as that plusarg. So N mutants cost one model build; the design with
mutsel = 0 must pass each stage of the kill suite before mutants run it (the engine stage
first, for every mutant; the later stages, and the design as written through them, only when
a mutant passes the engine stage).

Kill suite, in this order, stopping at the first failure (GoogleTest --gtest_fail_fast):
  1. rtl_engine_test (tests/rtl/engine_test.cpp): crops of real pairs in every mode
     (left / right / LR, raw / sub-pixel), D from 2 to DMAX, strides, back-to-back frames,
     reset and start while busy, aborts, every configuration error code (not its death
     test: the design is read for synthesis, without the RTL's simulation assertions);
  2. rtl_axi_test (tests/rtl/axi_test.cpp): AXI4 bursts, tiled input, response errors,
     abort with bursts in flight, 4 KiB;
  3. mcadsw_sim_random --cases 40 --seed 2026 --fail-fast: random sizes, D, modes, strides,
     latencies, interrupts, each frame against the reference.
  4. cycles, after each stage: the frames' cycle counts it printed (engine and AXI test
     lines, random cases) against those of the design as written (its run, below): a mutant
     that changes only timing changed the CYCLES counter a user reads (the reference has no
     cycle model, so the design as written is the oracle for timing, as make sim's cycle
     comparison is).
A mutant is killed when a stage fails, crashes (an RTL assertion, a combinational loop the
model cannot settle) or runs out of its time: TIMEOUT seconds a stage (default 300), or twice
the slowest stage of the design as written when that is more (a loaded machine: CI runs this
beside the synthesis, and the engine stage alone takes about 140 s on an idle one). The
design as written gets 4 x TIMEOUT a stage. A stage out of time gets SIGTERM, its whole
process group, and SIGKILL 10 s later. The harness's own cycle limits end a hung frame long
before. The block tests (census, weight generator, cost aggregator, WTA, post, registers)
verilate the blocks as written, so they cannot see a mutant of the flattened engine; they
are not in the suite.

Survivors: tests/mutate/survivors.txt lists survivors by key (the `mutate` command without
-ctrl) with a kind and the reason: equivalent (cannot change any output; not counted in the
score) or open (could, but no test shows it yet; counted as survived).
A key names source lines and Yosys's running cell numbers, so any RTL change gives new keys.
When the design is made again the flow keeps the draw before as list.prev.ys. REKEY=1 makes
the design, compares the two draws mutant by mutant without what moves with the lines (the
-src attributes, the line numbers in cell names, Yosys's running numbers: draw_key), and when
they are the same mutations in the same order (an RTL change that moved lines or wires but
left the logic and the hierarchy: the analysis still holds) writes each listed survivor's
new key into the list; when they differ it says so (exit 2): a new draw, to run in full and
review. Then `make mutate N=200 SEED=1` confirms the outcomes.
Output in BUILD/mutate: summary.json (total, killed, survived, equivalent, open, unlisted,
score = killed / (total - equivalent), per module counts, the survivors; flow/mutate_summary.py),
mutants.tsv (number, module, key), results/ and outcomes.tsv (number, outcome, the test
that killed it, seconds), results.tsv (those with module and key, a listed survivor's
outcome its kind), logs/ (each mutant's kill-suite output), baseline.log (the design as
written's).
Exit 0; 1 when a survivor is in neither kind of the list; 2 on an error (bad input, Yosys,
the build, the design as written failing a stage).
"""
import argparse
import difflib
import hashlib
import os
import re
import shutil
import signal
import subprocess
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor, as_completed
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from flowlib import FlowError, PREFIX, ROOT, Run, log, rtl_list, tail  # noqa: E402
from mutate_summary import summarize  # noqa: E402

SURVIVORS = ROOT / "tests" / "mutate" / "survivors.txt"
# The kill suite in its order: (stage, program of the mutant build, arguments).
STAGES = [
    ("engine", "rtl_engine_test_mut", ["--gtest_fail_fast", "--gtest_brief=1", "--gtest_filter=-*DeathTest*"]),
    ("axi", "rtl_axi_test_mut", ["--gtest_fail_fast", "--gtest_brief=1"]),
    ("random", "mcadsw_sim_random_mut", ["--cases", "40", "--seed", "2026", "--fail-fast"]),
]
# A frame's cycle count as a stage prints it: the engine and AXI tests' frame lines, the
# random cases and their total.
CYCLE_LINE = re.compile(r"^(case +[0-9]+ |[0-9]+x[0-9]+ D=[0-9]+: |sim-random: )")
FAILED_LINE = re.compile(r"^\[  FAILED  \] [A-Za-z0-9_./]+|^case +([0-9]+) .*FAILED")


def sample_picks(n, seed, sample, skip=()):
    """SAMPLE mutant numbers of 1 .. N for SEED, in ascending order, none of SKIP: drawn
    by the linear congruential generator state = (state * 1103515245 + 12345) mod 2^31,
    k = state mod N + 1 (from state = SEED), a number drawn or skipped before drawn again.
    This generator is what the shell script before this program computed, and CI's sample
    (N=200 SEED=1 SAMPLE=12) must stay the mutants it is: do not replace it by Python's
    random module. SEED < 2^31 keeps every product below 2^63, as the shell's arithmetic."""
    seen, picks, state = set(skip), [], seed
    if sample > n - len(seen & set(range(1, n + 1))):
        raise ValueError(f"cannot draw {sample} of {n} mutants with {len(seen)} left out")
    while len(picks) < sample:
        state = (state * 1103515245 + 12345) % 2147483648
        k = state % n + 1
        if k not in seen:
            seen.add(k)
            picks.append(k)
    return sorted(picks)


def equivalent_mutants(list_text, mutants):
    """The numbers of MUTANTS (rows number, module, key of mutants.tsv) whose key the
    survivors list (its text) gives as equivalent, in the rows' order."""
    eq = set()
    for line in list_text.split("\n"):
        f = line.split("\t")
        if f[0].startswith("mutate ") and len(f) > 1 and f[1] == "equivalent":
            eq.add(f[0])
    return [int(k) for k, _, key in mutants if key in eq]


def mutant_keys(list_text):
    """The keys of Yosys's list (list.ys text), in its order: each `mutate` command without
    its -ctrl argument."""
    return [re.sub(r" -ctrl \S+ [0-9]+ [0-9]+", "", ln.strip(), count=1)
            for ln in list_text.splitlines() if ln.startswith("mutate ")]


def draw_key(key):
    """A mutant's key without what moves when RTL lines move but the logic does not: the
    -src arguments, the line numbers in Yosys's cell names ($and$rtl/m.sv:512$3905) and
    Yosys's running numbers ($procmux$76192)."""
    key = re.sub(r" -src \S+", "", key.strip())
    key = re.sub(r"(\.s?v):[0-9]+", r"\1:L", key)
    return re.sub(r"\$[0-9]+", "$N", key)


def rekey(prev_list, cur_list, list_text):
    """The survivors list (its text) with the key of each listed mutant of the previous draw
    (prev_list, the text of Yosys's list.ys) replaced by the same mutant's key in the current
    draw (cur_list), when the two draws are the same mutations in the same order (draw_key
    equal, mutant by mutant). Returns (text, number of keys replaced); FlowError (exit 2) when
    the draws differ."""
    prev, cur = mutant_keys(prev_list), mutant_keys(cur_list)
    if len(prev) != len(cur):
        raise FlowError(f"the draws differ: {len(prev)} mutants before, {len(cur)} now", 2)
    differ = [k + 1 for k, (a, b) in enumerate(zip(prev, cur)) if draw_key(a) != draw_key(b)]
    if differ:
        raise FlowError(f"the draws differ in {len(differ)} of {len(cur)} mutants (the first: "
                        f"{differ[0]}): a new draw; run it in full and review the survivors", 2)
    new = dict(zip(prev, cur))
    out, n = [], 0
    for line in list_text.split("\n"):
        f = line.split("\t")
        if f[0].startswith("mutate ") and f[0] in new and new[f[0]] != f[0]:
            f[0] = new[f[0]]
            n += 1
        out.append("\t".join(f))
    return "\n".join(out), n


def mutant_modules(instances_text, list_text):
    """Rows (number, module, key) of mutants.tsv: each mutant of Yosys's list (list.ys) with
    the module of the innermost instance on its cell's path (instances.txt: '-- module M'
    then M's instance paths) and its key, the `mutate` command without -ctrl."""
    mod, m = {}, ""
    for line in instances_text.splitlines():
        f = line.split()
        if f[:2] == ["--", "module"]:
            m = f[2]
        elif line:
            mod[line.rsplit("/", 1)[-1].rsplit(".", 1)[-1]] = m
    rows = []
    for key in mutant_keys(list_text):
        f = key.split()
        cell = f[f.index("-cell") + 1] if "-cell" in f[:-1] else ""
        who = "mcadsw_top"
        for s in cell.split("."):
            s = re.sub(r"^\\", "", re.sub(r"^\$flatten", "", s))
            who = mod.get(s, who)
        rows.append((str(len(rows) + 1), who, key))
    return rows


def stage_cycles(path, stage):
    """The cycle-count lines of STAGE's section ('== STAGE: ...') of a kill-suite log."""
    on, lines = False, []
    for line in Path(path).read_text(errors="replace").splitlines():
        if line.startswith("== "):
            on = line.split()[1:2] == [stage + ":"]
        elif on and CYCLE_LINE.match(line):
            lines.append(line)
    return lines


def first_new_line(base, lines):
    """The first of LINES that a diff against BASE shows as new (diff's first '>' line),
    or None."""
    for tag, _, _, j1, _ in difflib.SequenceMatcher(None, base, lines, autojunk=False).get_opcodes():
        if tag in ("replace", "insert"):
            return lines[j1]
    return None


def first_failure(path):
    """The first failed test of a log: its GoogleTest name, or 'case N' of the random frames."""
    for line in Path(path).read_text(errors="replace").splitlines():
        m = FAILED_LINE.match(line)
        if m:
            return f"case {m.group(1)}" if m.group(1) else m.group()[len("[  FAILED  ] "):]
    return ""


class Stopped(Exception):
    """The run is being stopped (an error or an interrupt elsewhere)."""


class Suite:
    """The kill suite's programs in BINDIR, run JOBS at a time (threads, each waiting for its
    stage's process group) with TIMEOUT seconds a stage (0: none)."""

    def __init__(self, out, bindir, jobs, timeout):
        self.out, self.bindir, self.jobs, self.timeout = out, bindir, jobs, timeout
        self.run = Run()
        self.stopping = threading.Event()

    def cmd(self, stage):
        _, prog, args = next(s for s in STAGES if s[0] == stage)
        return [str(self.bindir / prog)] + args

    def run_stage(self, stage, k, log_path, limit):
        """STAGE on mutant K (0: the design as written), its output appended to LOG_PATH;
        (exit status as a shell gives it, whether it ran out of time). After LIMIT seconds
        (0: no limit) its process group gets SIGTERM, 10 s later SIGKILL (Run.wait)."""
        if self.stopping.is_set():
            raise Stopped()
        with open(log_path, "a") as f:
            p = self.run.start(self.cmd(stage), cwd=str(ROOT), env={"MCADSW_MUTANT": str(k)},
                               stdout=f, stderr=subprocess.STDOUT)
        if self.stopping.is_set():             # stopped while this one started
            try:
                os.killpg(p.pid, signal.SIGKILL)
            except OSError:
                pass
        rc, _, timed_out = self.run.wait(p, limit or None)
        if self.stopping.is_set():
            raise Stopped()
        if timed_out and rc != 0:
            return (137 if rc == -signal.SIGKILL else 124), True
        return (rc if rc >= 0 else 128 - rc), False

    def parallel(self, items, fn, done=None):
        """fn(item) for each of ITEMS, JOBS at a time; done(item, result) here as each ends.
        An error or an interrupt stops the stages still running (their process groups)."""
        pool = ThreadPoolExecutor(max_workers=self.jobs)
        futures = {pool.submit(fn, it): it for it in items}
        try:
            for f in as_completed(futures):
                r = f.result()
                if done:
                    done(futures[f], r)
        except BaseException:
            self.stopping.set()
            pool.shutdown(wait=False, cancel_futures=True)
            self.run.stop()
            raise
        finally:
            pool.shutdown(wait=True)

    def kill_suite(self, k, log_path, stages):
        """Mutant K through STAGES of the suite, in its order (LOG_PATH starts afresh with
        the suite's first stage, else the earlier ones are in it): (outcome, test)."""
        if stages[0] == STAGES[0][0]:
            log_path.write_text("")
        for stage, _, _ in STAGES:
            if stage not in stages:
                continue
            with open(log_path, "a") as f:
                f.write(f"== {stage}: {' '.join(self.cmd(stage))}\n")
            rc, timed_out = self.run_stage(stage, k, log_path, self.timeout)
            if rc != 0:
                if timed_out:
                    what = f"{stage}:timeout"
                elif rc > 128:
                    what = f"{stage}:signal{rc - 128}"
                else:
                    what = f"{stage}:{first_failure(log_path) or f'exit{rc}'}"
                return "killed", what.replace(" ", "_")
            # Timing: each frame's cycle count (the CYCLES counter a user reads) against the
            # same stage of the design as written; a count that differs is a changed output.
            new = first_new_line(stage_cycles(self.out / "baseline.log", stage), stage_cycles(log_path, stage))
            if new is not None:
                with open(log_path, "a") as f:
                    f.write(f"== cycles: differ from the design as written: {new}\n")
                return "killed", "cycles:" + new.split(":")[0].replace(" ", "_")[:40]
        return "survived", "-"

    def baseline(self, stages):
        """The design as written through STAGES (as many at once as there are jobs; each
        section appended to baseline.log): every one must pass. Then a mutant's stage may
        take twice the slowest stage of the design as written, when that is more."""
        t0 = time.time()
        index = [i for i, s in enumerate(STAGES) if s[0] in stages]

        def one(i):
            stage = STAGES[i][0]
            part = self.out / f"baseline_{i}.log"
            part.write_text(f"== {stage}: {' '.join(self.cmd(stage))}\n")
            ts = time.time()
            rc, _ = self.run_stage(stage, 0, part, 4 * self.timeout)
            with open(part, "a") as f:
                f.write(f"== seconds {int(time.time() - ts)}\n== exit {rc}\n")
        self.parallel(index, one)
        for i in index:
            part = self.out / f"baseline_{i}.log"
            with open(self.out / "baseline.log", "a") as f:
                f.write(part.read_text(errors="replace"))
            if tail(part, 1) != ["== exit 0"]:
                raise FlowError(f"the unmutated model fails the kill suite's {STAGES[i][0]} stage "
                                f"(log: {self.out}/baseline.log): fix this first", 2)
            part.unlink()
        log(f"the design as written (mutsel = 0) passes the kill suite's stages {' '.join(stages)} "
            f"in {int(time.time() - t0)} s")
        slowest = max((int(ln.split()[2]) for ln in tail(self.out / "baseline.log", 10**6)
                       if re.match(r"== seconds [0-9]+$", ln)), default=0)
        if 2 * slowest > self.timeout:
            log(f"its slowest stage took {slowest} s: a mutant's stage may take {2 * slowest} s "
                f"(not {self.timeout})")
            self.timeout = 2 * slowest

    def run_stages(self, picks, stages, final):
        """Each of PICKS through STAGES; results/K: number, outcome, the test that killed
        it, seconds (the earlier stages' added). A mutant's line when it is killed, or
        survives the FINAL stages; a progress line as each one ends."""
        t0, count = time.time(), [0]

        def one(k):
            res = self.out / "results" / str(k)
            before = int(res.read_text().split("\t")[3]) if res.is_file() else 0
            t = time.time()
            outcome, test = self.kill_suite(k, self.out / "logs" / f"mutant_{k}.log", stages)
            res.write_text(f"{k}\t{outcome}\t{test}\t{int(time.time() - t) + before}\n")
            return outcome, test

        def done(k, result):
            outcome, test = result
            if outcome != "survived" or final:
                print(f"mutate: mutant {k:>4}  {outcome:<8} {test}")
            count[0] += 1
            el = time.time() - t0
            if count[0] < len(picks):
                log(f"{count[0]}/{len(picks)} done, about {el / count[0] * (len(picks) - count[0]):.0f} s left")
            else:
                log(f"{count[0]}/{len(picks)} done in {el:.0f} s")
        self.parallel(picks, one, done)


def design_stamp(mods, n, seed, width, no_rect):
    """The mutant design's stamp: sha1 of the package, the assertion include and MODS (the
    RTL files, as rtl/...), then "N SEED WIDTH NO_RECT" and `yosys -V` (the shell script's
    stamp, byte for byte, so a design it wrote is reused)."""
    h = hashlib.sha1()
    for f in ["rtl/mcadsw_pkg.sv", "rtl/mcadsw_assert.svh"] + mods:
        h.update((ROOT / f).read_bytes())
    h.update(f"{n} {seed} {width} {no_rect}\n".encode())
    h.update(subprocess.run(["yosys", "-V"], capture_output=True).stdout)
    return h.hexdigest()


def plusarg_select(text, width):
    """Yosys's Verilog of the mutant design with the port mutsel[WIDTH-1:0] turned into a
    variable set from the plusarg +mcadsw_mutant=K (0 when absent)."""
    lines = []
    for line in text.split("\n"):
        if line.endswith(", mutsel);"):
            line = line[:-len(", mutsel);")] + ");"
        if line == f"  input [{width - 1}:0] mutsel;":
            line = (f"  reg [{width - 1}:0] mutsel;\n"
                    '  initial if (!$value$plusargs("mcadsw_mutant=%d", mutsel)) mutsel = 0;')
        elif line == f"  wire [{width - 1}:0] mutsel;":
            continue
        lines.append(line)
    return "\n".join(lines)


def mutant_design(out, n, seed, no_rect):
    """Step 1: the flattened mcadsw_top with N mutants behind mutsel (made again when its
    stamp changes: the RTL, N, SEED, the select's width, NO_RECT, Yosys's version)."""
    for t in ("yosys", "cmake"):
        if not shutil.which(t):
            raise FlowError(f"'{t}' not found in PATH (run scripts/bootstrap.sh, or make mutate, which runs it)", 2)
    mods = ["rtl/" + f for f in rtl_list(no_pkg=True)]
    pkgs = ("rtl/mcadsw_pkg.sv", "rtl/rect/mcadsw_rect_pkg.sv")      # packages: no instances
    width = 1
    while (1 << width) - 1 < n:
        width += 1
    stamp = design_stamp(mods, n, seed, width, no_rect)
    design = out / (f"mutants_n{n}_s{seed}" + ("_norect" if no_rect else "") + ".v")
    stamp_file = out / "design.stamp"
    if design.is_file() and stamp_file.is_file() and stamp_file.read_text().strip() == stamp:
        return design
    # NO_RECT=1: the mutant list is drawn from every cell but those of the rectifier's
    # instance (flattened names $flatten\u_engine.\u_rectifier.* and u_engine.u_rectifier.*).
    # The clock gates (mcadsw_clock_gate, in the engine) are read transparent
    # (-DMCADSW_NO_CLOCK_GATES: the clock passes, no cell), so the draw is that of the design
    # without gates; docs/verification.md says why no mutant is lost that way.
    mut_sel = ""
    if no_rect:
        mut_sel = "select -del" + "".join(f" c:$flatten\\u_engine.\\{i}.* c:u_engine.{i}.*"
                                          for i in ("u_rectifier",)) + ";"
    log(f"Yosys: elaborating mcadsw_top, {n} mutants (seed {seed}{', not in the rectifier' if no_rect else ''}) "
        f"behind mutsel[{width - 1}:0]")
    for f in ("instances.txt", "design.stamp"):
        (out / f).unlink(missing_ok=True)
    if (out / "list.ys").is_file():      # the draw before, for REKEY=1
        (out / "list.ys").replace(out / "list.prev.ys")
    # Instance name -> module, for the per-module counts. The type exactly m (a pattern
    # t:*m* would also count the instances of every module whose name contains m:
    # mcadsw_rect those of all mcadsw_rect_*): the module itself, or a parameterised copy,
    # $paramod\m\PARAM=... or $paramod$<hash>\m.
    inst = out / "instances.txt"
    inst_cmds = "".join(f"tee -q -a {inst} log -- module {m}; "
                        f"tee -q -a {inst} select -list t:{m} t:$paramod\\{m}\\* t:$paramod$*\\{m}; "
                        for m in (Path(f).stem for f in mods if f not in pkgs))
    t0 = time.time()
    script = "\n".join([f"read_verilog -sv -DSYNTHESIS -DMCADSW_NO_CLOCK_GATES -Irtl rtl/mcadsw_pkg.sv {' '.join(mods)}",
                        "hierarchy -check -top mcadsw_top", inst_cmds, "prep -flatten -top mcadsw_top", mut_sel,
                        f"mutate -list {n} -seed {seed} -ctrl mutsel {width} 1 -o {out}/list.ys",
                        "select -clear", f"script {out}/list.ys", "opt_clean", f"write_verilog -noattr {design}.tmp"])
    if subprocess.run(["yosys", "-q", "-l", str(out / "yosys.log"), "-p", script], cwd=ROOT,
                      stdout=subprocess.DEVNULL).returncode != 0:
        raise FlowError(f"Yosys failed (log: {out}/yosys.log)", 2)
    # mutsel as a port would be an input of the model, and Verilator re-evaluates the logic
    # that depends on inputs every time they change (3x slower): make it a variable the
    # model sets once from the plusarg +mcadsw_mutant=K (the harness passes MCADSW_MUTANT
    # on, sim/engine_bench.cpp).
    tmp = Path(f"{design}.tmp")
    text = plusarg_select(tmp.read_text(), width)
    design.write_text(text)
    tmp.unlink()
    if text.count("mcadsw_mutant=") != 1 or re.search(r"input .*mutsel", text):
        raise FlowError(f"could not turn the mutsel port of {design} into a plusarg", 2)
    listed = sum(ln.startswith("mutate ") for ln in (out / "list.ys").read_text().splitlines())
    if listed != n:
        raise FlowError(f"Yosys listed {listed} mutants, not {n}", 2)
    if no_rect and re.search(r"-cell (\$flatten\\)?u_engine\.\\?u_rectifier\.",
                             (out / "list.ys").read_text()):
        raise FlowError(f"NO_RECT=1 but Yosys listed a mutant in the rectifier ({out}/list.ys)", 2)
    stamp_file.write_text(stamp + "\n")
    log(f"design written in {int(time.time() - t0)} s ({design})")
    return design


def build_model(out, design):
    """Step 2: the model and the kill suite's programs, at -O1 as for `make gls`: the
    generated model of the flattened design compiles in about 30 s. Returns their folder."""
    cmake = out / "cmake"
    # Verilator's CMake package learns which files Verilator writes from its run when CMake
    # configures; a new design may split into more files at the build's run of Verilator,
    # which the build then does not compile (the link fails). A model whose file list is older
    # than the design starts afresh, with Verilator run at configure time.
    vdir = cmake / "sim" / "CMakeFiles" / "vmutant.dir"
    lists = list(vdir.glob("*.dir/*_copy.cmake"))
    if vdir.is_dir() and (not lists or min(p.stat().st_mtime for p in lists) < design.stat().st_mtime):
        shutil.rmtree(vdir)
    with open(out / "cmake.log", "w") as f:
        rc = subprocess.run(["cmake", "-S", str(ROOT), "-B", str(cmake), "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                             "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG", f"-DMCADSW_MUTANT_VERILOG={design}",
                             "-DMCADSW_BLOCK_BENCHES=none", "-DMCADSW_CORE_MODEL=OFF"],
                            stdout=f, stderr=subprocess.STDOUT).returncode
    if rc != 0:
        print("\n".join(tail(out / "cmake.log", 20)))
        raise FlowError(f"cmake configure failed (log: {out}/cmake.log)", 2)
    t0 = time.time()
    log(f"building the mutant model and the kill suite (Verilator, {cmake})")
    with open(out / "build.log", "w") as f:
        rc = subprocess.run(["cmake", "--build", str(cmake), "--target"] + [s[1] for s in STAGES],
                            stdout=f, stderr=subprocess.STDOUT).returncode
    if rc != 0:
        print("\n".join(tail(out / "build.log", 30)))
        raise FlowError(f"build failed (log: {out}/build.log)", 2)
    log(f"built in {int(time.time() - t0)} s")
    return cmake / "bin"


def run_mutants(a, out):
    """Steps 1 to 5: design, model, mutants.tsv, the picks through the kill suite. Returns
    the seconds spent running the design as written and the mutants."""
    design = mutant_design(out, a.n, a.seed, a.no_rect)
    bindir = build_model(out, design)
    rows = mutant_modules((out / "instances.txt").read_text(), (out / "list.ys").read_text())
    (out / "mutants.tsv").write_text("".join("\t".join(r) + "\n" for r in rows))

    # Which mutants: a list, a seeded sample, or all.
    if a.mutants:
        picks = a.mutants
    elif a.sample > 0:
        # The sample skips the mutants the list already gives as equivalent (reviewed: they
        # survive by construction, and each costs the whole kill suite, about 10 minutes on
        # CI's loaded machine, to show nothing new); it draws further ones in their place.
        equiv = equivalent_mutants(SURVIVORS.read_text(), rows)
        avail = a.n - len(equiv)
        if a.sample > avail:
            raise FlowError(f"SAMPLE {a.sample}: only {avail} of the {a.n} mutants are not listed as equivalent", 2)
        picks = sample_picks(a.n, a.seed, a.sample, equiv)
        if equiv:
            log(f"the sample leaves out {len(equiv)} mutants listed as equivalent ({' '.join(map(str, equiv))})")
    else:
        picks = list(range(1, a.n + 1))
    (out / "no_rect").write_text(f"{a.no_rect}\n")

    log(f"{len(picks)} of {a.n} mutants, {a.jobs} at a time, kill suite: engine tests, AXI tests, "
        "40 random frames, cycle counts")
    if a.mutants:          # run these again, keep the other results of the last run
        for k in picks:
            (out / "results" / str(k)).unlink(missing_ok=True)
            (out / "logs" / f"mutant_{k}.log").unlink(missing_ok=True)
    else:
        shutil.rmtree(out / "logs", ignore_errors=True)
        shutil.rmtree(out / "results", ignore_errors=True)
    (out / "logs").mkdir(exist_ok=True)
    (out / "results").mkdir(exist_ok=True)
    (out / "baseline.log").write_text("")

    # The engine stage for every pick, the design as written first; then the AXI and random
    # stages for those that passed it (the suite's order, stopping at the first failure, as
    # one run would; a sample's mutants mostly fail the engine stage, and the later stages
    # of the design as written cost ten minutes of a loaded CI machine).
    first, rest = [STAGES[0][0]], [s[0] for s in STAGES[1:]]
    suite = Suite(out, bindir, a.jobs, a.timeout)
    tstart = time.time()
    try:
        suite.baseline(first)
        suite.run_stages(picks, first, final=False)
        later = [k for k in picks if (out / "results" / str(k)).read_text().split("\t")[1] == "survived"]
        if later:
            log(f"{len(later)} mutants pass the {first[0]} stage: the stages {' '.join(rest)}")
            suite.baseline(rest)
            suite.run_stages(later, rest, final=True)
    finally:
        suite.run.stop()
    elapsed = int(time.time() - tstart)
    (out / "run_seconds").write_text(f"{elapsed}\n")
    return elapsed


def parse(argv):
    """The options, checked as the make variables they come from (FlowError, exit 2)."""
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--n", default="200", help="mutants in Yosys's list (make N=, default 200)")
    ap.add_argument("--seed", default="1", help="Yosys's seed, and the sample's (SEED=, default 1)")
    ap.add_argument("--sample", default="0", help="a seeded sample of this many (SAMPLE=, default 0: all)")
    ap.add_argument("--jobs", default=str(len(os.sched_getaffinity(0))), help="mutants at a time (JOBS=)")
    ap.add_argument("--mutants", default="", help='only these, e.g. "3 17" (MUTANTS=)')
    ap.add_argument("--report-only", action="store_true", help="the last run's summary again (REPORT_ONLY=1)")
    ap.add_argument("--rekey", action="store_true",
                    help="carry the survivors list's keys over to an unchanged draw (REKEY=1)")
    ap.add_argument("--no-rect", default="0", help="1: no mutant in the rectifier (NO_RECT=)")
    ap.add_argument("--timeout", default="300", help="seconds a kill-suite stage (TIMEOUT=, default 300)")
    ap.add_argument("--build", default=str(ROOT / "build"), help="build folder (BUILD_DIR=; output in its mutate/)")
    a = ap.parse_args(argv)

    def number(s):
        return int(s) if re.fullmatch(r"[0-9]+", s) else None
    n, seed, sample, jobs, timeout = (number(x) for x in (a.n, a.seed, a.sample, a.jobs, a.timeout))
    if n is None or not 1 <= n <= 65535:
        raise FlowError(f"N must be 1 to 65535, not '{a.n}'", 2)
    if seed is None or seed >= 2**31:
        raise FlowError(f"SEED must be a number (0 to 2147483647), not '{a.seed}'", 2)
    if sample is None or sample > n:
        raise FlowError(f"SAMPLE must be 0 (all) to N, not '{a.sample}'", 2)
    if jobs is None or jobs < 1:
        raise FlowError(f"JOBS must be 1 or more, not '{a.jobs}'", 2)
    if a.no_rect not in ("0", "1"):
        raise FlowError(f"NO_RECT must be 0 or 1, not '{a.no_rect}'", 2)
    if timeout is None:
        raise FlowError(f"TIMEOUT must be a number of seconds (0: no limit), not '{a.timeout}'", 2)
    mutants = [number(x) for x in a.mutants.split()]
    if not all(k is not None and 1 <= k <= n for k in mutants):
        raise FlowError(f"MUTANTS must be numbers of 1 to N ({n}), not '{a.mutants}'", 2)
    a.n, a.seed, a.sample, a.jobs, a.timeout, a.no_rect = n, seed, sample, jobs, timeout, int(a.no_rect)
    a.mutants = list(dict.fromkeys(mutants))
    return a


def main(argv):
    PREFIX[0] = "mutate"
    sys.stdout.reconfigure(line_buffering=True)
    try:
        a = parse(argv)
        out = Path(a.build).resolve() / "mutate"
        if not SURVIVORS.is_file():
            raise FlowError(f"no list of survivors at {SURVIVORS}", 2)
        out.mkdir(parents=True, exist_ok=True)
        start_all = time.time()
        if a.rekey:
            mutant_design(out, a.n, a.seed, a.no_rect)
            if not (out / "list.prev.ys").is_file():
                raise FlowError(f"no draw before in {out} (list.prev.ys): REKEY=1 needs the mutation "
                                "run of the RTL before the change in this build folder", 2)
            text, n = rekey((out / "list.prev.ys").read_text(), (out / "list.ys").read_text(),
                            SURVIVORS.read_text())
            SURVIVORS.write_text(text)
            log(f"the same {a.n} mutations as the draw before: {n} keys of "
                f"{SURVIVORS.relative_to(ROOT)} rewritten; make mutate N={a.n} SEED={a.seed} confirms the outcomes")
            return 0
        if a.report_only:
            if not ((out / "results").is_dir() and (out / "mutants.tsv").is_file()):
                raise FlowError(f"no results in {out}: run make mutate first", 2)

            def saved(name):      # a number the last run wrote, else 0
                m = re.fullmatch(r"\s*([0-9]+)\s*", (out / name).read_text() if (out / name).is_file() else "")
                return int(m.group(1)) if m else 0
            elapsed, no_rect = saved("run_seconds"), saved("no_rect")     # as the last run had it
        else:
            elapsed, no_rect = run_mutants(a, out), a.no_rect
        # Step 6: the summary (flow/mutate_summary.py): survivors found in the committed list
        # are equivalent or open; results.tsv, summary.json; 1 on an unlisted survivor.
        outcomes = [ln for r in (out / "results").iterdir() for ln in r.read_text().splitlines(True)]
        outcomes.sort(key=lambda ln: (int(ln.split("\t")[0]) if ln.split("\t")[0].isdigit() else 0, ln))
        (out / "outcomes.tsv").write_text("".join(outcomes))
        if not a.report_only:
            log(f"{int(time.time() - start_all)} s in all, {elapsed} s running the design as written and the mutants")
        rc = summarize(out, SURVIVORS, SURVIVORS.relative_to(ROOT), a.n, a.seed, a.sample, elapsed, a.jobs, no_rect)
        log(f"{out / 'summary.json'}")
        return rc
    except FlowError as e:
        print(f"mutate: {e}", file=sys.stderr, flush=True)
        return e.code
    except KeyboardInterrupt:
        print("mutate: interrupted", file=sys.stderr, flush=True)
        return 130


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
