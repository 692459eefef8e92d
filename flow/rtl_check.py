#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""Checks that every RTL file is accepted by the three tools the project uses.

  python3 flow/rtl_check.py lint      verilator --lint-only -Wall, each module as top; no
                                      always block in the engine core (wiring only); behind
                                      the clock gates no synchronous reset
  python3 flow/rtl_check.py selftest  the clock-gate reset check on a small engine
  python3 flow/rtl_check.py yosys     Yosys 0.23 read_verilog -sv + hierarchy + proc
  python3 flow/rtl_check.py iverilog  Icarus Verilog 11, -g2012
  python3 flow/rtl_check.py all       the three, and the wrapper
  python3 flow/rtl_check.py board     verilator --lint-only -Wall of the board shells
                                      (rtl/board/*.sv, each with the SoC under it; the ECP5
                                      primitives they instantiate from tests/fpga/ecp5_cells_stub.sv)
  python3 flow/rtl_check.py wrapper   the vendor-tool wrapper rtl/mcadsw_axi.v (Verilog-2001, not in
                                      rtl/mcadsw.f): verilator -Wall with .v files read as IEEE
                                      1364-2001, Yosys 0.23's plain Verilog parser with mcadsw_top's
                                      ports as a black box's (hierarchy -check), Icarus elaborating
                                      the whole IP under it

A second argument, a package file, replaces rtl/mcadsw_pkg.sv: another configuration's (the
FPGA target's, build/rtl/fpga/mcadsw_pkg.sv, elaborates the branches the default package leaves
out); a package with RECT = 0 is checked with the file list without the rectifier
(flowlib.rtl_list no_rect). Exits non-zero on any warning or error. Used by `make lint` and by
ctest.
"""
import os
import re
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from flowlib import FlowError, ROOT, rtl_list, run_main, VENV_BIN  # noqa: E402

RTL = ROOT / "rtl"
# The packages, read in this order before the modules and never linted as a top: the
# engine's, then the rectifier's (it imports the engine's). rtl/mcadsw.f lists both first.
PKGS = ["mcadsw_pkg.sv", "rect/mcadsw_rect_pkg.sv"]
# The engine core: instances and wires only (the lint step fails on an always block in it,
# and when it grows past WIRING_LINES lines: glue that grows belongs in a block).
WIRING = "mcadsw_engine.sv"
WIRING_LINES = 360
# Yosys 0.23 parses a unary operator before a size cast as part of the size: `-(N)'(x)` as a
# cast to the size -(N) (it read -(13)'(2) as +2), `~N'(x)` as a cast to the size ~N (it read
# ~12'(3) as 1); both found by gate-level simulation. Verilator and Icarus apply the operator
# to the cast value, so the netlist would differ from the simulated RTL. Write ~(N'(x)),
# 0 - N'(x). (A minus at the start of a line continues the expression above: binary.)
UNARY_CAST = re.compile(r"((^|[=(,?:+*/&|^~!<>-])\s*[~!]|[=(,?:+*/&|^~!<>-]\s*-)\s*"
                        r"([A-Za-z_][A-Za-z_0-9]*|[0-9]+|\([^()]*\))'\(")


def statement(code, pos):
    """The statement of code starting at pos: a begin ... end block (nested ones counted), or
    up to its semicolon (an if's else branches included)."""
    m = re.compile(r"\s*begin\b").match(code, pos)
    if m:
        depth = 1
        for t in re.compile(r"\b(begin|end)\b").finditer(code, m.end()):
            depth += 1 if t.group(1) == "begin" else -1
            if depth == 0:
                return code[pos:t.end()]
        return code[pos:]
    end = pos
    while True:
        semi = code.find(";", end)
        if semi < 0:
            return code[pos:]
        end = semi + 1
        if not re.compile(r"\s*else\b").match(code, end):
            return code[pos:end]


def uncommented(path):
    """The text of a source file without its comments (the line breaks kept)."""
    return re.sub(r"//[^\n]*|/\*.*?\*/", lambda m: "\n" * m.group(0).count("\n"), path.read_text(), flags=re.S)


class Check:
    def __init__(self, alt_pkg):
        self.alt_pkg = str(Path(alt_pkg).resolve()) if alt_pkg else None
        if self.alt_pkg and not Path(self.alt_pkg).is_file():
            raise FlowError(f"package {alt_pkg} not found", 2)
        self.no_rect = bool(self.alt_pkg and re.search(r"localparam int RECT +=  *0;", Path(self.alt_pkg).read_text()))
        listed = rtl_list(no_pkg=True, no_rect=self.no_rect)
        self.mods = [f for f in listed if f not in PKGS]
        for p in PKGS[1:]:
            if p not in listed:
                raise FlowError(f"rtl/{p} is not in rtl/mcadsw.f")
        # The list is the one every tool reads: a source file it does not name is an error
        # (rtl/rect/rect.f, the rectifier's own list, which no build or test reads, is not read
        # here; rect/mcadsw_rect_none.sv replaces the rect/ modules without the rectifier, and
        # the rect/ modules it replaces are not in that list).
        for f in sorted(p.relative_to(RTL).as_posix() for p in list(RTL.glob("*.sv")) + list(RTL.glob("rect/*.sv"))):
            if f == "rect/mcadsw_rect_none.sv" or (self.no_rect and f.startswith("rect/")):
                continue
            if f not in PKGS + self.mods:
                raise FlowError(f"rtl/{f} is not in rtl/mcadsw.f")
        self.waivers = ["lint_waivers.vlt"] if (RTL / "lint_waivers.vlt").is_file() else []
        self.files = [self.alt_pkg or PKGS[0]] + PKGS[1:] + self.mods
        self.what = (f" (package {self.alt_pkg}{', without the rectifier' if self.no_rect else ''})"
                     if self.alt_pkg else "")

    @staticmethod
    def run(cmd):
        r = subprocess.run(cmd, cwd=RTL, capture_output=True, text=True)
        return r.returncode, r.stdout + r.stderr

    def lint_top(self, top, *more):
        """verilator -Wall of the RTL (and MORE) with TOP as the top: (ok, messages)."""
        rc, out = self.run([str(VENV_BIN / "verilator"), "--lint-only", "-Wall", "--assert", "-I.", *self.waivers,
                            *self.files, *more, "--top-module", top])
        if rc != 0:
            return False, out + f"rtl_check: verilator lint FAILED for {top}\n"
        return "%Warning" not in out, out if "%Warning" in out else ""

    @staticmethod
    def tops_of(f):
        """The modules a file declares (one, named as the file, but for rect/mcadsw_rect_none.sv)."""
        return re.findall(r"^module ([a-z_0-9]*)", (RTL / f).read_text(), re.M)

    def lint(self):
        # Each top in its own Verilator process, as many at a time as the machine has cores
        # (make lint stays within the pre-stop hook's time); messages printed once all ran.
        tops = [t for f in self.mods for t in self.tops_of(f)]
        with ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
            results = list(pool.map(self.lint_top, tops))
        for _, out in results:
            if out:
                print(out, end="")
        if not all(ok for ok, _ in results):
            return False
        print(f"rtl_check: verilator --lint-only -Wall clean on {len(self.mods)} modules{self.what}")
        return self.wiring()

    def wiring(self):
        """The engine is wiring: instances, wires and assigns; a process belongs in the block
        that owns it (docs/architecture.md). And the configuration travels as the one bundle
        the package declares (CFG_*, generated from regs.hpp): no module has a port of its own
        for a field of it (cfg_<field>_i / _o)."""
        code = uncommented(RTL / WIRING)
        found = [i + 1 for i, line in enumerate(code.split("\n")) if re.search(r"\balways(_ff|_comb|_latch)?\b", line)]
        if found:
            print(f"rtl_check: rtl/{WIRING} is wiring, but has an always block (line {', '.join(map(str, found))}): "
                  "move it into the block that owns it")
            return False
        lines = len((RTL / WIRING).read_text().splitlines())
        if lines > WIRING_LINES:
            print(f"rtl_check: rtl/{WIRING} is wiring, but has {lines} lines (at most {WIRING_LINES}): "
                  "move what is not instances and wires into the block that owns it")
            return False
        pkg = Path(self.alt_pkg).read_text() if self.alt_pkg else (RTL / PKGS[0]).read_text()
        fields = [f.lower() for f in re.findall(r"localparam int CFG_([A-Z0-9_]+?)\s*=", pkg)
                  if not f.endswith("_W") and f != "BITS"]
        if not fields:
            raise FlowError("the package declares no configuration bundle (CFG_*): regenerate it (make rtl-pkg)", 2)
        port = re.compile(r"\b(input|output)\b[^;,()]*\bcfg_(" + "|".join(fields) + r")_[io]\b")
        bad = []
        for f in self.mods:
            bad += [f"rtl/{f}: cfg_{m.group(2)}" for m in port.finditer(uncommented(RTL / f))]
        if bad:
            print("rtl_check: configuration fields retyped as ports (they travel in the bundle cfg_i / cfg_o, "
                  f"mcadsw_pkg::CFG_*): {'; '.join(bad)}")
            return False
        return self.gated_resets()

    def gated_resets(self, code=None, sources=None):
        """Behind the engine's clock gates every reset is asynchronous: a gate is closed
        during reset, so a synchronous reset there would never act (docs/architecture.md 1.3,
        Clocks). The blocks whose clk_i is a gate's clk_o, and every module under them, may
        have no `always_ff @(posedge clk_i)` that reads rst_ni. code and sources (module name
        -> code) replace the engine's and the RTL's, for the self-test."""
        if code is None:
            code = uncommented(RTL / WIRING)
            sources = {}
            for f in self.mods:
                text = uncommented(RTL / f)
                for name in re.findall(r"^\s*module\s+(\w+)", text, re.M):
                    sources[name] = (f"rtl/{f}", text)
        gclks = re.findall(r"\bmcadsw_clock_gate\b[^;]*?\.clk_o\s*\(\s*(\w+)\s*\)", code, re.S)
        if not gclks:
            raise FlowError(f"rtl/{WIRING}: no mcadsw_clock_gate instance found (the check reads its clk_o)", 2)
        inst = re.compile(r"\b(mcadsw_\w+)\s*(?:#\s*\(|\w+\s*\()")
        todo = []
        for g in gclks:
            for m in re.finditer(r"\.clk_i\s*\(\s*" + g + r"\s*\)", code):
                found = [i.group(1) for i in inst.finditer(code[:m.start()]) if i.group(1) in sources]
                if found:
                    todo.append(found[-1])
        seen, bad = set(), []
        while todo:
            mod = todo.pop()
            if mod in seen:
                continue
            seen.add(mod)
            where, text = sources[mod]
            body = text[re.search(r"^\s*module\s+" + mod + r"\b", text, re.M).start():]
            body = body[:body.find("endmodule")]
            todo += [i.group(1) for i in inst.finditer(body) if i.group(1) in sources and i.group(1) != mod]
            for m in re.finditer(r"\balways_ff\s*@\s*\(\s*posedge\s+clk_i\s*\)", body):
                if re.search(r"\brst_ni\b", statement(body, m.end())):
                    line = text[:text.find(body)].count("\n") + body[:m.start()].count("\n") + 1
                    bad.append(f"{where}:{line} ({mod})")
        if not seen:
            raise FlowError(f"rtl/{WIRING}: no block found on a gated clock ({', '.join(gclks)})", 2)
        if bad:
            print("rtl_check: a synchronous reset behind a clock gate, which never acts while the gate is closed "
                  f"(make it asynchronous): {'; '.join(bad)}")
            return False
        print(f"rtl_check: behind the clock gates ({', '.join(gclks)}) {len(seen)} modules, every reset asynchronous")
        return True

    def selftest(self):
        """gated_resets on a small engine: a gate, a block behind it and a module under that;
        it must pass an asynchronous reset and a clocked block without a reset, and find a
        synchronous reset in a begin-end block and in an if's else."""
        eng = ("mcadsw_clock_gate u_g (.clk_i, .en_i (e), .off_i (1'b0), .clk_o (gclk));\n"
               "mcadsw_free u_f (.clk_i, .rst_ni);\nmcadsw_blk #(.A (1)) u_b (.clk_i (gclk), .rst_ni);\n")
        free = ("f.sv", "module mcadsw_free;\n always_ff @(posedge clk_i) if (!rst_ni) q <= 0;\nendmodule\n")
        blk = ("b.sv", "module mcadsw_blk;\n mcadsw_sub u_s (.clk_i, .rst_ni);\n"
               " always_ff @(posedge clk_i or negedge rst_ni) if (!rst_ni) x <= 0; else x <= 1;\nendmodule\n")
        cases = [("asynchronous", True, " always_ff @(posedge clk_i) y <= z;\n"
                  " always_ff @(posedge clk_i or negedge rst_ni) if (!rst_ni) w <= 0;\n"),
                 ("synchronous in begin-end", False,
                  " always_ff @(posedge clk_i) begin if (a) begin y <= 0; end else if (!rst_ni) y <= 1; end\n"),
                 ("synchronous in an else", False, " always_ff @(posedge clk_i) if (a) y <= z; else y <= rst_ni;\n")]
        ok = True
        for name, want, body in cases:
            src = {"mcadsw_free": free, "mcadsw_blk": blk,
                   "mcadsw_sub": ("s.sv", "module mcadsw_sub;\n" + body + "endmodule\n")}
            got = self.gated_resets(eng, src)
            print(f"rtl_check: self-test, {name}: {'passed' if got else 'found'}"
                  f" ({'as expected' if got == want else 'WRONG'})")
            ok = ok and got == want
        return ok

    def yosys(self):
        bad = []
        for f in self.files:          # code only: comments stripped, line numbers kept
            for n, line in enumerate((RTL / f).read_text().splitlines(), 1):
                if UNARY_CAST.search(line.split("//")[0]):
                    bad.append(f"{f}:{n}:{line}")
        if bad:
            print("\n".join(bad))
            print("rtl_check: unary operator before a size cast, -(N)'(x) or ~N'(x), which Yosys 0.23 misreads; "
                  "write ~(N'(x)) or 0 - N'(x)", file=sys.stderr)
            return False
        # One Yosys process, one pass: the files parsed (each module elaborated with its
        # default parameters), then `hierarchy` without a top keeps every module and derives
        # each parameter set the modules instantiate, and `proc` runs on them all. Yosys's
        # messages name the file and line; each large hierarchy is elaborated once, not once
        # per module above it.
        tops = [t for f in self.mods for t in self.tops_of(f)]
        script = f"read_verilog -sv {' '.join(self.files)}; hierarchy -check; proc; tee -o /dev/stdout ls"
        rc, out = self.run(["yosys", "-q", "-p", script])
        if rc != 0:
            print(out, end="")
            print("rtl_check: yosys FAILED", file=sys.stderr)
            return False
        if "warning" in out.lower():
            print(out, end="")
            print("rtl_check: yosys warned", file=sys.stderr)
            return False
        missing = [t for t in tops if not re.search(rf"^\s+{t}$", out, re.M)]
        if missing:
            print(out, end="")
            print(f"rtl_check: yosys did not elaborate {', '.join(missing)}", file=sys.stderr)
            return False
        print(f"rtl_check: yosys 0.23 parses and elaborates {len(self.mods)} modules{self.what}")
        return True

    def icarus(self, *more, top=None):
        with tempfile.TemporaryDirectory() as tmp:
            rc, out = self.run(["iverilog", "-g2012", "-Wall", "-Wno-timescale", "-I.", *(["-s", top] if top else []),
                                "-o", f"{tmp}/a.out", *self.files, *more])
        what = f" for {top}" if top else ""
        if rc != 0 or out:
            print(out, end="")
            print(f"rtl_check: iverilog {'FAILED' if rc else 'warned'}{what}", file=sys.stderr)
            return False
        return True

    def iverilog(self):
        if not self.icarus():
            return False
        print(f"rtl_check: iverilog -g2012 compiles {len(self.files)} files{self.what}")
        return True

    def board(self):
        shells = sorted(RTL.glob("board/*.sv"))
        for f in shells:
            ok, out = self.lint_top(f.stem, str(f), str(ROOT / "tests" / "fpga" / "ecp5_cells_stub.sv"))
            print(out, end="")
            if not ok:
                return False
        print(f"rtl_check: verilator --lint-only -Wall clean on {len(shells)} board shells{self.what}")
        return True

    def wrapper(self):
        ok, out = self.lint_top("mcadsw_axi", "+1364-2001ext+v", "mcadsw_axi.v")
        print(out, end="")
        if not ok:
            return False
        rc, out = self.run(["yosys", "-q", "-p", f"read_verilog -sv {self.files[0]} {self.files[1]}; read_verilog -sv "
                            "-lib mcadsw_top.sv; read_verilog mcadsw_axi.v; hierarchy -check -top mcadsw_axi"])
        if rc != 0 or "warning" in out.lower():
            print(out, end="")
            print(f"rtl_check: yosys (Verilog-2001 parser) {'FAILED' if rc else 'warned'} for mcadsw_axi",
                  file=sys.stderr)
            return False
        if not self.icarus("mcadsw_axi.v", top="mcadsw_axi"):
            return False
        print("rtl_check: the wrapper mcadsw_axi.v clean under verilator -Wall (Verilog-2001), yosys 0.23 "
              f"read_verilog and iverilog{self.what}")
        return True


def main(argv):
    what = argv[0] if argv else "all"
    steps = {"lint": ["lint"], "yosys": ["yosys"], "iverilog": ["iverilog"], "board": ["board"],
             "wrapper": ["wrapper"], "selftest": ["selftest"], "all": ["lint", "yosys", "iverilog", "wrapper"]}
    if what not in steps or len(argv) > 2:
        print(f"usage: {sys.argv[0]} lint|yosys|iverilog|board|wrapper|selftest|all [PACKAGE]", file=sys.stderr)
        return 2
    if not (VENV_BIN / "verilator").is_file():
        raise FlowError(f"no tool environment at {VENV_BIN.parent} (run scripts/bootstrap.sh)", 2)
    # The pinned Verilator first on PATH (as scripts/tools.sh puts it for the shell scripts).
    os.environ["PATH"] = f"{VENV_BIN}{os.pathsep}{os.environ.get('PATH', '')}"
    chk = Check(argv[1] if len(argv) > 1 else None)
    ok = True
    for step in steps[what]:
        ok = getattr(chk, step)() and ok
        if not ok:
            break
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(run_main(main, sys.argv[1:], "rtl_check"))
