#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""Licence check of the repository (ctest license_headers).

Runs REUSE's own linter (`reuse lint`, https://reuse.software: every file has a
copyright and a licence, every licence named has its text under LICENSES/), and adds
the project's rule on top: a file of a kind that can carry a comment (RTL, C++, Python,
shell, CMake, Tcl, Yosys and abc scripts, Makefile, docs, ...) states its licence in its
own header; only the kinds that cannot (images, JSON, data files) are annotated in
REUSE.toml.

    scripts/license_check.py [--root DIR] [--reuse PATH]

Exits 0 when both hold; 1 with the offending files named; 2 when reuse is missing.
"""
import argparse
import json
import pathlib
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent

# What REUSE.toml may license: files that have no room for a comment, or data a program
# writes. Anything else must carry its own SPDX-License-Identifier line.
ANNOTATED_SUFFIXES = {".png", ".json", ".svg", ".yml", ".csv"}
ANNOTATED_NAMES = {"SHA256SUMS"}


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", default=str(ROOT), help="repository to check (default: this one)")
    ap.add_argument("--reuse", default=None, help="the reuse program (default: the tool "
                    "environment's, .venv/bin/reuse, then PATH)")
    args = ap.parse_args(argv)
    root = pathlib.Path(args.root)

    reuse = args.reuse or shutil.which("reuse", path=str(ROOT / ".venv" / "bin")) or shutil.which("reuse")
    if not reuse:
        print("license_check: reuse not found (run scripts/bootstrap.sh)", file=sys.stderr)
        return 2
    run = subprocess.run([reuse, "--root", str(root), "lint", "--json"], capture_output=True, text=True)
    try:
        report = json.loads(run.stdout)
    except json.JSONDecodeError:
        print(run.stdout + run.stderr, file=sys.stderr)
        print("license_check: reuse lint gave no report", file=sys.stderr)
        return 2

    bad = []
    if not report["summary"]["compliant"]:
        # The linter's own words for what is wrong (missing licences, unused ones, files
        # without copyright or licence).
        text = subprocess.run([reuse, "--root", str(root), "lint"], capture_output=True, text=True).stdout
        bad.append("reuse lint: not compliant\n" + text)
    for f in report["files"]:
        path = pathlib.PurePosixPath(f["path"])
        if path.suffix in ANNOTATED_SUFFIXES or path.name in ANNOTATED_NAMES:
            continue
        own = [e for e in f["spdx_expressions"] if e["source_type"] == "file-header"]
        if not own:
            bad.append(f"{path}: no SPDX-License-Identifier line of its own "
                       f"(a file of this kind carries it in its header)")
    for line in bad:
        print(line)
    n = report["summary"]["files_total"]
    if bad:
        print(f"license_check: FAILED ({len(bad)} problem(s) in {n} files)")
        return 1
    print(f"license_check: {n} files, each with its licence "
          f"({', '.join(report['summary']['used_licenses'])}); REUSE compliant")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
