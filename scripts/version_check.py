#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""The project's version against what must agree with it (ctest version_consistent).

    scripts/version_check.py VERSION      (VERSION: CMake's PROJECT_VERSION)

- the register map (sw_ref/include/mcadsw/regs.hpp kVersionMajor, kVersionMinor, which
  the VERSION register reads): the project's MAJOR equals the map's, its MINOR is at
  least the map's (CHANGELOG.md, "Versions");
- CHANGELOG.md: its first release heading is `## [VERSION] - YYYY-MM-DD` and names the
  register map version it carries;
- CITATION.cff: `version: VERSION`.
Exits 1 naming each disagreement.
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent


def main(argv):
    if len(argv) != 1 or not re.fullmatch(r"\d+\.\d+\.\d+", argv[0]):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    version = argv[0]
    major, minor, _ = (int(x) for x in version.split("."))
    bad = []

    regs = (ROOT / "sw_ref/include/mcadsw/regs.hpp").read_text()
    def const(name):
        m = re.search(rf"\b{name}\s*=\s*(\d+)\s*;", regs)
        if not m:
            bad.append(f"regs.hpp: no {name}")
            return -1
        return int(m.group(1))
    map_major, map_minor = const("kVersionMajor"), const("kVersionMinor")
    if major != map_major:
        bad.append(f"project {version}: MAJOR {major} is not the register map's {map_major}")
    if minor < map_minor:
        bad.append(f"project {version}: MINOR {minor} is below the register map's {map_minor}")

    log = (ROOT / "CHANGELOG.md").read_text()
    releases = re.findall(r"^## \[(\d+\.\d+\.\d+)\] - (\d{4}-\d{2}-\d{2})\n(.*?)(?=^## |\Z)", log, re.M | re.S)
    if not releases:
        bad.append("CHANGELOG.md: no release heading `## [X.Y.Z] - YYYY-MM-DD`")
    else:
        top, _, body = releases[0]
        if top != version:
            bad.append(f"CHANGELOG.md: the newest release is {top}, the project is {version}")
        elif f"Register map {map_major}.{map_minor}" not in body:
            bad.append(f"CHANGELOG.md: release {top} does not say `Register map {map_major}.{map_minor}`")

    cff = (ROOT / "CITATION.cff").read_text()
    m = re.search(r"^version:\s*\"?([^\s\"]+)", cff, re.M)
    if not m or m.group(1) != version:
        bad.append(f"CITATION.cff: version {m.group(1) if m else '(none)'}, the project is {version}")

    for b in bad:
        print(b)
    if bad:
        return 1
    print(f"version_check: {version}, register map {map_major}.{map_minor}, CHANGELOG.md and "
          "CITATION.cff agree")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
