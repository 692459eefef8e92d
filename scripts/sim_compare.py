#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

"""Compares two `make sim` summaries (build/sim/summary.json) case by case: a
restructuring step must leave every case bit-exact with the same cycles, words
and bursts. Exits 1 on any difference, a case missing on either side, or a
mismatch in the new run.

    scripts/sim_compare.py BEFORE.json AFTER.json
"""
import json
import sys

FIELDS = ("cycles", "words_read", "words_written", "stall_cycles", "read_bursts",
          "write_bursts", "mismatches", "bus_violations")


def load(path):
    with open(path, encoding="utf-8") as f:
        return {c["case"]: c for c in json.load(f)}


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    before, after = load(argv[1]), load(argv[2])
    bad = 0
    for name in sorted(set(before) | set(after)):
        if name not in after or name not in before:
            print(f"{name}: only in {'before' if name in before else 'after'}")
            bad += 1
            continue
        diffs = [f"{k} {before[name].get(k)} -> {after[name].get(k)}" for k in FIELDS
                 if before[name].get(k) != after[name].get(k)]
        if after[name].get("mismatches", 1) != 0:
            diffs.append("not bit-exact")
        if diffs:
            print(f"{name}: " + ", ".join(diffs))
            bad += 1
    n = len(set(before) | set(after))
    print(f"sim_compare: {n - bad} of {n} cases equal" + ("" if bad else " (cycles, words, bursts, bit-exact)"))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
