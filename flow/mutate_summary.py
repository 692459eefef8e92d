# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

"""Summary of a `make mutate` run (flow/mutate.py, its last step).

Reads the mutant list (mutants.tsv: number, module, key), the outcomes
(outcomes.tsv: number, killed|survived, the test that killed it, seconds) and the
committed survivors list (tests/mutate/survivors.txt: key, kind, reason); writes
results.tsv (number, module, outcome, test, seconds, key; a listed survivor's
outcome is its kind, equivalent or open) and summary.json, prints the summary.
survived = open + unlisted; score = killed / (total - equivalent).
"""
import json
import sys
from pathlib import Path


def summarize(out, list_path, list_name, n, seed, sample, seconds, jobs, no_rect):
    """The summary of the run in OUT (build/mutate) against the survivors list at
    LIST_PATH (printed as LIST_NAME); N, SEED, SAMPLE, SECONDS, JOBS and NO_RECT (1: the
    rectifier was left out of the mutant list) go into summary.json as they are. Returns
    1 when a survivor is not in the list, else 0."""
    out = Path(out)

    kinds = {}
    for line in Path(list_path).read_text().splitlines():
        if line.startswith("mutate "):
            f = line.split("\t")
            kinds[f[0]] = f[1] if len(f) > 1 else ""
    mutants = {}
    for line in (out / "mutants.tsv").read_text().splitlines():
        k, mod, key = line.split("\t")[:3]
        mutants[k] = (mod, key)

    rows = []
    for line in (out / "outcomes.tsv").read_text().splitlines():
        if not line.strip():
            continue
        k, outcome, test, secs = (line.split("\t") + ["", "", ""])[:4]
        mod, key = mutants[k]
        kind = kinds.get(key, "")
        if outcome == "survived" and kind:
            outcome = kind                      # equivalent or open
        elif outcome == "killed" and kind:
            outcome = "killed_listed"
        rows.append({"mutant": int(k), "module": mod, "outcome": outcome, "test": test,
                     "seconds": secs, "key": key})
    rows.sort(key=lambda r: r["mutant"])
    with open(out / "results.tsv", "w") as f:
        for r in rows:
            f.write("\t".join(str(r[c]) for c in ("mutant", "module", "outcome", "test", "seconds", "key")) + "\n")

    per_module = {}
    killed = equivalent = open_ = unlisted = 0
    survivors, stale = [], []
    for r in rows:
        m = per_module.setdefault(r["module"], {"total": 0, "killed": 0, "survived": 0, "equivalent": 0})
        m["total"] += 1
        if r["outcome"] in ("killed", "killed_listed"):
            killed += 1
            m["killed"] += 1
            if r["outcome"] == "killed_listed":
                stale.append(r)
        elif r["outcome"] == "equivalent":
            equivalent += 1
            m["equivalent"] += 1
        else:
            m["survived"] += 1
            if r["outcome"] == "open":
                open_ += 1
            else:
                unlisted += 1
            survivors.append({"mutant": r["mutant"], "module": r["module"], "kind": r["outcome"],
                              "mutation": r["key"]})
    total = len(rows)
    score = 100.0 * killed / (total - equivalent) if total > equivalent else 100.0
    summary = {"n": n, "seed": seed, "sample": sample, "jobs": jobs, "seconds": seconds,
               "rectifier_excluded": bool(no_rect),
               "total": total, "killed": killed, "survived": open_ + unlisted, "equivalent": equivalent,
               "open": open_, "unlisted": unlisted, "score_percent": round(score, 1),
               "per_module": dict(sorted(per_module.items())), "survivors": survivors,
               "listed_but_killed": [r["mutant"] for r in stale]}
    (out / "summary.json").write_text(json.dumps(summary, indent=2) + "\n")

    print(f"mutate: {total} mutants: {killed} killed, {equivalent} equivalent, {open_} open (listed), "
          f"{unlisted} unlisted survivors; score {score:.1f} % (killed / non-equivalent; target >= 95 %)")
    if no_rect:
        print("mutate: the rectifier (u_engine.u_rectifier) was left out (NO_RECT=1)")
    print("mutate: per module (total killed survived equivalent):")
    for name, m in sorted(per_module.items()):
        print(f"  {name:<20s} {m['total']:4d} {m['killed']:4d} {m['survived']:4d} {m['equivalent']:4d}")
    for r in stale:
        print(f"mutate: warning: mutant {r['mutant']} is listed in {list_name} but was killed "
              f"({r['test']}): remove it")
    if unlisted:
        print(f"mutate: survivors not in {list_name} (kill them with a test, or list them: "
              f"equivalent or open, with the reason):", file=sys.stderr)
        for s in survivors:
            if s["kind"] == "survived":
                print(f"  mutant {s['mutant']} ({s['module']}): {s['mutation']}", file=sys.stderr)
    return 1 if unlisted else 0
