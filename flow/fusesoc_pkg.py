#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""FuseSoC generator of the engine's configuration package (mcadsw.core, generator
mcadsw_pkg): writes mcadsw_pkg.sv for the parameters asked for and a core that holds it.

The package is what `make rtl-pkg`, `make sim-build` and the synthesis flows write: the
output of the project's package generator, sw_ref/cli/gen_rtl_pkg.cpp, from the constants
of sw_ref/include/mcadsw/params.hpp (the single source the C++ reference reads too). The
generator program is one C++ file over headers, so it is compiled here (about a second,
the C++ compiler named by $CXX, else c++) rather than asking for a CMake build first.

FuseSoC calls it with one argument, the input YAML file (GAPI 1.0):
  files_root   the mcadsw core's folder (the repository)
  vlnv         the generated core's name
  parameters   dmax (1 .. 128, default 64), par (1, 2, 4; default 1),
               fpga (the FPGA target's memory shapes; default false),
               rect (the rectifier; default true)
and writes, in its working folder, mcadsw_pkg.sv, <name>.core and FUSESOC_IGNORE. A bad
parameter stops it with gen_rtl_pkg's message and a non-zero exit (FuseSoC then stops).
"""
import os
import subprocess
import sys

import yaml

KNOWN = {"dmax": int, "par": int, "fpga": bool, "rect": bool}


def main(argv):
    if len(argv) != 1:
        print("usage: fusesoc_pkg.py INPUT.yml (FuseSoC calls it)", file=sys.stderr)
        return 2
    with open(argv[0]) as f:
        gen = yaml.safe_load(f)
    root = gen["files_root"]
    params = gen.get("parameters") or {}
    unknown = sorted(set(params) - set(KNOWN))
    if unknown:
        print(f"mcadsw_pkg generator: unknown parameter(s) {', '.join(unknown)}; "
              f"known: {', '.join(KNOWN)}", file=sys.stderr)
        return 2
    for k, v in params.items():
        if not isinstance(v, KNOWN[k]) or (KNOWN[k] is int and isinstance(v, bool)):
            print(f"mcadsw_pkg generator: {k}={v!r} is not {KNOWN[k].__name__}", file=sys.stderr)
            return 2
    exe = os.path.abspath("gen_rtl_pkg")
    cxx = os.environ.get("CXX", "c++")
    subprocess.run([cxx, "-std=c++17", "-O1", "-I", os.path.join(root, "sw_ref", "include"),
                    os.path.join(root, "sw_ref", "cli", "gen_rtl_pkg.cpp"), "-o", exe], check=True)
    args = [exe, "--dmax", str(params.get("dmax", 64)), "--par", str(params.get("par", 1))]
    if params.get("fpga", False):
        args.append("--fpga")
    if not params.get("rect", True):
        args.append("--no-rect")
    pkg = subprocess.run(args, check=False, capture_output=True, text=True)
    if pkg.returncode != 0:
        sys.stderr.write(pkg.stderr)
        return pkg.returncode
    with open("mcadsw_pkg.sv", "w") as f:
        f.write(pkg.stdout)
    name = gen["vlnv"]
    core = {"name": name,
            "description": "mcadsw_pkg for " + ", ".join(f"{k}={v}" for k, v in sorted(params.items())),
            "filesets": {"pkg": {"files": ["mcadsw_pkg.sv"], "file_type": "systemVerilogSource"}},
            "targets": {"default": {"filesets": ["pkg"]}}}
    with open(name.split(":")[2] + ".core", "w") as f:
        f.write("CAPI=2:\n" + yaml.safe_dump(core, sort_keys=False))
    # FuseSoC reads this core from here itself; a later search of a library that holds this
    # folder (the repository's build/) must not find it as a core of its own.
    open("FUSESOC_IGNORE", "w").close()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
