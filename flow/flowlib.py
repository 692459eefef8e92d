# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

"""What every step of the synthesis and FPGA flow shares (flow/synth.py): the
paths, the error type and messages, stamps for reusing a step's outputs, the
RTL file list, the package generator and the process runner with its
memory-aware pool. Python 3 standard library only."""
import hashlib
import os
import re
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
FLOW = ROOT / "flow"
CON = ROOT / "constraints"
RAM_MODEL = ROOT / "sim" / "gls" / "mcadsw_ram_model.v"
LIBERTY = "/usr/share/qflow/tech/osu018/osu018_stdcells.lib"


def stamp_of(*parts):
    """sha256 of strings, bytes and files (by content) in order."""
    h = hashlib.sha256()
    for p in parts:
        if isinstance(p, Path):
            h.update(f"== {p.name}\n".encode() + (p.read_bytes() if p.is_file() else b"(missing)"))
        else:
            h.update(p if isinstance(p, bytes) else str(p).encode())
    return h.hexdigest()


def reusable(stamp_file, stamp, outputs):
    """Whether a stage's outputs are those of a successful run with this stamp;
    if not, the stamp goes (it is written again after the stage succeeds)."""
    ok = (stamp_file.is_file() and stamp_file.read_text().strip() == stamp
          and all(o.is_file() for o in outputs))
    if not ok:
        stamp_file.unlink(missing_ok=True)
    return ok


class FlowError(Exception):
    """A failure with its message (printed as 'synth: <message>') and exit code."""

    def __init__(self, message, code=1):
        super().__init__(message)
        self.code = code


def run_main(main, argv, name):
    """A flow program's exit code: MAIN(ARGV)'s, or a FlowError's after its message
    ("NAME: message") on stderr."""
    try:
        return main(argv)
    except FlowError as e:
        print(f"{name}: {e}", file=sys.stderr)
        return e.code


VENV_BIN = ROOT / ".venv" / "bin"   # the pinned tool environment (scripts/bootstrap.sh)


def tool(name):
    """A program of the tool environment, or a FlowError naming how to get it."""
    p = VENV_BIN / name
    if not p.is_file():
        raise FlowError(f"{p} missing (run scripts/bootstrap.sh, which installs requirements.txt)", 2)
    return str(p)


PREFIX = ["synth"]   # of every message: synth or fpga


def log(msg):
    print(f"{PREFIX[0]}: {msg}", flush=True)


def tail(path, n):
    try:
        return Path(path).read_text(errors="replace").splitlines()[-n:]
    except OSError:
        return []


def indent(lines):
    return "".join(f"  | {line}\n" for line in lines)


def cmake_build(build, options, targets, log_path, src=ROOT):
    """Configure SRC into BUILD (Ninja, Release, the -D OPTIONS) and build TARGETS on every
    core, both into LOG_PATH; a FlowError with the log's last lines when either fails."""
    with open(log_path, "w") as f:
        for what, cmd in (("configure", ["cmake", "-S", str(src), "-B", str(build), "-G", "Ninja",
                                         "-DCMAKE_BUILD_TYPE=Release"] + list(options)),
                          ("build", ["cmake", "--build", str(build), "-j", str(os.cpu_count() or 1),
                                     "--target"] + list(targets))):
            f.flush()
            if subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT).returncode != 0:
                raise FlowError(f"cmake {what} of {build} failed (log {log_path}):\n" + indent(tail(log_path, 30)))


def rtl_list(no_pkg=False, no_rect=False):
    """The files of rtl/mcadsw.f, relative to the RTL folder; no_rect: the engine without
    the rectifier (rtl/rect/'s modules replaced by rect/mcadsw_rect_none.sv, as
    scripts/rtl_files.sh --no-rect)."""
    files = []
    for line in (ROOT / "rtl" / "mcadsw.f").read_text().splitlines():
        line = line.split("//")[0].strip()
        if not line or (no_pkg and line == "mcadsw_pkg.sv"):
            continue
        if no_rect and line.startswith("rect/") and line != "rect/mcadsw_rect_pkg.sv":
            continue
        files.append(line)
    if no_rect:
        files.append("rect/mcadsw_rect_none.sv")
    return files


def project_version():
    """The project's version, CMake's project(mcadsw VERSION x.y.z) in CMakeLists.txt."""
    m = re.search(r"project\(mcadsw VERSION (\d+\.\d+\.\d+)", (ROOT / "CMakeLists.txt").read_text())
    if not m:
        raise SystemExit("no `project(mcadsw VERSION x.y.z` in CMakeLists.txt")
    return m.group(1)


def write_or_check(path, text, check, how):
    """A generated file: written (check False), or compared with TEXT (check True): on a
    difference the unified diff on stdout, a line naming HOW to regenerate it on stderr, and
    1; else 0."""
    import difflib
    import sys
    rel = Path(path).relative_to(ROOT)
    if not check:
        Path(path).write_text(text)
        return 0
    old = Path(path).read_text() if Path(path).is_file() else ""
    if old != text:
        sys.stdout.writelines(difflib.unified_diff(old.splitlines(True), text.splitlines(True),
                                                   str(rel), "generated"))
        print(f"{rel} is stale: run {how}", file=sys.stderr)
        return 1
    print(f"{rel} is up to date")
    return 0


# ---- Processes --------------------------------------------------------------------------
class Run:
    """Processes of this run: each in its own process group (stopped as a group),
    waited with os.wait4 for its peak memory; all of them sampled each second."""

    def __init__(self):
        self.procs = {}   # pid -> Popen, kept until os.wait4 reaped it (else Popen's own
                          # clean-up could reap it first and its exit status be lost)
        self.peak_sum_mb = 0
        self._stop = threading.Event()
        threading.Thread(target=self._sample, daemon=True).start()

    def _sample(self):
        me = os.getpid()
        while not self._stop.is_set():
            parent, rss = {}, {}
            for d in os.listdir("/proc"):
                if d.isdigit():
                    try:
                        f = Path(f"/proc/{d}/stat").read_text().rsplit(")", 1)[1].split()
                        parent[int(d)], rss[int(d)] = int(f[1]), int(f[21])
                    except (OSError, IndexError, ValueError):
                        pass
            total = 0
            for pid in parent:
                q = pid
                for _ in range(64):
                    if q == me:
                        total += rss[pid]
                        break
                    q = parent.get(q, 0)
                    if q <= 1:
                        break
            self.peak_sum_mb = max(self.peak_sum_mb, total * os.sysconf("SC_PAGE_SIZE") // 2**20)
            self._stop.wait(1)

    def start(self, cmd, cwd=None, env=None, stdout=None, stderr=None):
        p = subprocess.Popen(cmd, cwd=cwd, env={**os.environ, **(env or {})}, stdin=subprocess.DEVNULL,
                             stdout=stdout or subprocess.DEVNULL, stderr=stderr or subprocess.DEVNULL,
                             start_new_session=True)
        self.procs[p.pid] = p
        return p

    def reap(self, pid=-1):
        """Waits for one process of this run: (pid, exit code, peak MB)."""
        pid, status, ru = os.wait4(pid, 0)
        rc = os.waitstatus_to_exitcode(status)
        if pid in self.procs:
            self.procs.pop(pid).returncode = rc
        return pid, rc, ru.ru_maxrss // 1024

    def wait(self, p, limit_s=None, kill_after_s=10):
        """Waits for P (from start): (exit code, peak MB, whether it ran out of time).
        limit_s: after that many seconds its process group is sent SIGTERM, and SIGKILL
        kill_after_s later if it is still there (as `timeout -k`)."""
        timed_out = threading.Event()

        def signal_group(sig):
            if sig == signal.SIGTERM:
                timed_out.set()
            try:
                os.killpg(p.pid, sig)
            except OSError:
                pass
        timers = [threading.Timer(limit_s, signal_group, [signal.SIGTERM]),
                  threading.Timer(limit_s + kill_after_s, signal_group, [signal.SIGKILL])] if limit_s else []
        for t in timers:
            t.daemon = True
            t.start()
        try:
            _, rc, mb = self.reap(p.pid)
        finally:
            for t in timers:
                t.cancel()
        return rc, mb, timed_out.is_set()

    def run(self, cmd, out_path=None, err_path=None, limit_s=None, **kw):
        """Runs cmd to its end: (exit code, peak MB, seconds). limit_s: stopped (wait) after
        that many seconds; the caller tells by the seconds."""
        t0 = time.time()
        with open(out_path or os.devnull, "w") as o, open(err_path or os.devnull, "w") as e:
            p = self.start(cmd, stdout=o, stderr=e, **kw)
            rc, mb, _ = self.wait(p, limit_s)
        return rc, mb, int(time.time() - t0)

    def stop(self):
        for g in list(self.procs):
            try:
                os.killpg(g, signal.SIGTERM)
            except OSError:
                pass
        for g in list(self.procs):
            try:
                self.reap(g)
            except ChildProcessError:
                self.procs.pop(g, None)
        self._stop.set()


    def pool(self, queue, jobs, mem_mb, start, finish):
        """Runs the jobs of `queue` (each a dict with est_mb, its expected peak; 0:
        unknown, taken as 3500 MB) at most `jobs` at a time: a job starts when the
        expected peaks of the running jobs and its own stay within mem_mb and its
        own (plus 512 MB) is free on the machine now; the first job always starts.
        start(job) returns its Popen; finish(job, exit code, peak MB, seconds) runs
        as each one ends (an exception stops the pool's other processes)."""
        def est_mb(b):
            return b["est_mb"] if b["est_mb"] > 0 else 3500

        def mem_avail_mb():
            try:
                m = re.search(r"^MemAvailable:\s+(\d+)", Path("/proc/meminfo").read_text(), re.M)
                return int(m.group(1)) // 1024
            except (OSError, AttributeError):
                return 10**6

        pending, running = list(queue), {}
        while pending or running:
            while pending and len(running) < jobs:
                used = sum(est_mb(b) for b, _ in running.values())
                avail = mem_avail_mb()
                pick = next((b for b in pending if not running or
                             (used + est_mb(b) <= mem_mb and est_mb(b) + 512 <= avail)), None)
                if pick is None:
                    break
                pending.remove(pick)
                p = start(pick)
                running[p.pid] = (pick, time.time())
            pid, rc, mb = self.reap()
            if pid not in running:
                continue
            b, t0 = running.pop(pid)
            try:
                finish(b, rc, mb, int(time.time() - t0))
            except BaseException:
                self.stop()
                raise


def gen_package(gen, dmax, par, fpga=False, no_rect=False):
    """The package of the configuration from gen_rtl_pkg, the one check of DMAX
    and PAR (exit 2 with its message); FPGA: the FPGA target's; no_rect: without the
    rectifier (RECT = 0)."""
    if not (Path(gen).is_file() and os.access(gen, os.X_OK)):
        raise FlowError(f"gen_rtl_pkg not found at {gen} (make synth builds it; or: "
                        f"cmake --build build --target gen_rtl_pkg)", 2)
    r = subprocess.run([gen, "--dmax", dmax, "--par", par] + (["--fpga"] if fpga else [])
                       + (["--no-rect"] if no_rect else []), capture_output=True, text=True)
    if r.returncode != 0:
        raise FlowError(r.stderr.strip() or f"gen_rtl_pkg failed (exit {r.returncode})", 2)
    return r.stdout


def default_out(build, dmax, par, clock_gate_min=4):
    """The synthesis folder of a configuration (without clock gating: _ungated after it)."""
    ungated = "" if clock_gate_min else "_ungated"
    if par != "1":
        return Path(build) / f"synth_dmax{dmax}_par{par}{ungated}"
    return Path(build) / ("synth" + ungated if dmax == "64" else f"synth_dmax{dmax}{ungated}")

