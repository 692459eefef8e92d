#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""The datasheet: docs/datasheet.md, its timing diagrams and its HTML (make docs).

    flow/datasheet.py collect [--build DIR] [--only PREFIX ...]
                                              figures from the flows' summaries in DIR (default
                                              build/) into docs/datasheet/figures.json; with
                                              --only, the figures whose key starts with a
                                              PREFIX (e.g. xc7.), the others kept as they are
    flow/datasheet.py render [--html FILE]    docs/datasheet.md from docs/datasheet/template.md,
                                              the figures, the wrapper's ports, the register map
                                              and the timing diagrams (WaveJSON in
                                              docs/datasheet/waves/, rendered to SVG with
                                              wavedrom); FILE: the page as HTML too
    flow/datasheet.py check                   exit 1 when docs/datasheet.md or an SVG is stale
                                              (ctest datasheet_up_to_date)

No figure of the datasheet is typed: each {{fig:KEY}} of the template is a value that
`collect` read from a summary file a flow wrote (FIGURES below says which file, which key
and which command writes it), kept in figures.json with its source, command, the commit
the tree was at and the date, and listed in the datasheet's last section. A figure whose
summary was not there when collected is printed as "not collected" with its command. A
frame rate is a ratio of two collected figures ({{fps:CLOCK_KEY:CYCLES_KEY}}). The timing
diagrams are recorded from a simulation (tests/cocotb/waves.py, make docs-waves).
Placeholders: {{fig:KEY}}, {{fps:CLOCK:CYCLES}}, {{table:ports}}, {{table:registers}},
{{table:errors}}, {{table:sources}}, {{wave:NAME}}.
"""
import argparse
import datetime
import json
import pathlib
import re
import subprocess
import sys

import ipxact

ROOT = pathlib.Path(__file__).resolve().parent.parent
DOC = ROOT / "docs" / "datasheet.md"
DIR = ROOT / "docs" / "datasheet"
TEMPLATE = DIR / "template.md"
FIGURES = DIR / "figures.json"
WAVES = DIR / "waves"


def case(name, key):
    """An extractor of `key` of the case `name` of a make sim summary (a list of cases)."""
    def get(d):
        for c in d:
            if c.get("case") == name:
                return c[key]
        raise KeyError(name)
    return get


def item(*keys):
    def get(d):
        for k in keys:
            d = d[k]
        return d
    return get


SIM = "sim/summary.json"
SIM_FPGA = "dmax64_par1_fpga/sim/summary.json"
SYNTH = "synth/summary.json"
# key: (summary file under the build folder, extractor, unit, command that writes the file)
SOURCES = {
    "asic.engine_nand2_eq": (SYNTH, item("nand2_eq"), "NAND2 eq", "make synth-check"),
    "asic.soc_nand2_eq": (SYNTH, item("soc_total_nand2_eq"), "NAND2 eq", "make synth-check"),
    "asic.memory_kB": (SYNTH, item("memory_kB_engine"), "kB", "make synth-check"),
    "asic.post_memory_kB": (SYNTH, item("post_stage_memory_kB"), "kB", "make synth-check"),
    "asic.post_nand2_eq": (SYNTH, item("post_stage_nand2_eq"), "NAND2 eq", "make synth-check"),
    "asic.rect_nand2_eq": (SYNTH, item("rect_nand2_eq"), "NAND2 eq", "make synth-check"),
    "asic.rect_memory_kB": (SYNTH, item("rect_memory_kB"), "kB", "make synth-check"),
    "asic.clock_mhz": (SYNTH, item("clock_mhz"), "MHz", "make synth-check"),
    "asic.worst_slack_ns": (SYNTH, item("worst_slack_ns"), "ns", "make synth-check"),
    "asic.fmax_mhz": (SYNTH, item("fmax_mhz"), "MHz", "make synth-check"),
    "asic.flip_flops": (SYNTH, item("flip_flops"), "", "make synth-check"),
    "asic.cycles_raw": (SIM, case("cif_teddy", "cycles"), "cycles", "make sim"),
    "asic.cycles_lr": (SIM, case("cif_teddy_lr", "cycles"), "cycles", "make sim"),
    "asic.cycles_rect": (SIM, case("cif_teddy_rect_b", "cycles"), "cycles", "make sim"),
    "asic.words_read_raw": (SIM, case("cif_teddy", "words_read"), "words", "make sim"),
    "asic.words_written_raw": (SIM, case("cif_teddy", "words_written"), "words", "make sim"),
    "fpga.cycles_raw": (SIM_FPGA, case("cif_teddy", "cycles"), "cycles", "make sim FPGA=1"),
    "fpga.cycles_lr": (SIM_FPGA, case("cif_teddy_lr", "cycles"), "cycles", "make sim FPGA=1"),
    "fpga.cycles_rect": (SIM_FPGA, case("cif_teddy_rect_b", "cycles"), "cycles", "make sim FPGA=1"),
    "power.raw_mw": ("power/summary.json", lambda d: round(d["runs"]["raw"]["total_w"] * 1e3, 1), "mW",
                     "make power"),
    "power.idle_mw": ("power/summary.json", lambda d: round(d["runs"]["idle"]["total_w"] * 1e3, 1), "mW",
                      "make power"),
    "ecp5.lut4": ("fpga/ecp5/summary.json", item("need", "TRELLIS_COMB", "used"), "", "make fpga"),
    "ecp5.dp16kd": ("fpga/ecp5/summary.json", item("need", "DP16KD", "used"), "", "make fpga"),
    "ecp5.mult18": ("fpga/ecp5/summary.json", item("need", "MULT18X18D", "used"), "", "make fpga"),
    "ecp5.fmax_mhz": ("fpga/ecp5/summary.json", lambda d: min(v["achieved"] for v in d["fmax_mhz"].values()),
                      "MHz", "make fpga"),
    "xc7.luts": ("fpga/xc7/summary.json", item("lut"), "", "make fpga"),
    "xc7.bram36": ("fpga/xc7/summary.json", item("bram36_equivalent"), "", "make fpga"),
    "xc7.dsp48": ("fpga/xc7/summary.json", item("dsp48e1"), "", "make fpga"),
}


def git_head():
    try:
        head = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True,
                              text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"], cwd=ROOT,
                               capture_output=True, text=True, check=True).stdout.strip()
        return head + ("+changes" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def collect(build, only=None):
    old = json.loads(FIGURES.read_text()) if only and FIGURES.is_file() else {}
    figs = {}
    head = git_head()
    for key, (rel, get, unit, cmd) in SOURCES.items():
        if only and not any(key.startswith(o) for o in only) and key in old:
            figs[key] = old[key]
            continue
        path = build / rel
        entry = {"unit": unit, "source": "build/" + rel, "command": cmd}
        try:
            entry["value"] = get(json.loads(path.read_text()))
            entry["commit"] = head
            entry["date"] = datetime.datetime.fromtimestamp(path.stat().st_mtime,
                                                            datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
        except (OSError, ValueError, KeyError, TypeError, IndexError):
            entry["value"] = None
        figs[key] = entry
    FIGURES.write_text(json.dumps(figs, indent=1, sort_keys=True) + "\n")
    if only and not any(k.startswith(o) for k in SOURCES for o in only):
        raise SystemExit(f"datasheet: no figure key starts with {' or '.join(only)}")
    got = sum(1 for f in figs.values() if f["value"] is not None)
    print(f"datasheet: {got} of {len(figs)} figures collected from {build} into {FIGURES.relative_to(ROOT)}")
    for k, f in figs.items():
        if f["value"] is None:
            print(f"datasheet: {k}: no {f['source']} (run {f['command']})")


def fmt(v, unit=""):
    if isinstance(v, int):
        s = f"{v:,}".replace(",", " ")
    elif isinstance(v, float):
        s = f"{v:g}"
    else:
        s = str(v)
    return s + (" " + unit if unit and unit not in ("cycles", "words") else "")


def ports_table():
    """The wrapper's ports (flow/ipxact.py reads them) with their interface."""
    kinds = {"s_axi": "s_axi (AXI4-Lite slave)", "m_axi": "m_axi (AXI4 master)", "aclk": "clock",
             "aresetn": "reset, active low", "interrupt": "interrupt"}
    notes = {"interrupt": "level, active high"}
    rows = ["| port | direction | width | interface | note |", "|---|---|---|---|---|"]
    for name, d, width in ipxact.ports():
        bus, _ = ipxact.bus_of(name)
        rows.append(f"| `{name}` | {'input' if d == 'in' else 'output'} | {width} | {kinds[bus['name']]} | "
                    f"{notes.get(name, '')} |")
    return "\n".join(rows)


def regs_table(regs):
    rows = ["| offset | register | access | fields | meaning |", "|---|---|---|---|---|"]
    for r in regs["registers"]:
        fields = ", ".join(f"{f['name']}[{f['lsb'] + f['width'] - 1}:{f['lsb']}]" if f["width"] > 1
                           else f"{f['name']}[{f['lsb']}]" for f in r["fields"])
        rows.append(f"| 0x{r['offset']:02X} | {r['name']} | {r['access']} | {fields} | {r['doc']} |")
    return "\n".join(rows)


def errors_table(regs):
    rows = ["| code | name | meaning |", "|---|---|---|"]
    rows += [f"| {e['code']} | {e['name']} | {e['doc']} |" for e in regs["errors"]]
    return "\n".join(rows)


def sources_table(figs, used):
    rows = ["| figure | value | from | written by | summary written | tree when collected |",
            "|---|---|---|---|---|---|"]
    for k in sorted(used):
        f = figs[k]
        v = "not collected" if f["value"] is None else fmt(f["value"], f["unit"])
        got = f["value"] is not None
        rows.append(f"| `{k}` | {v} | `{f['source']}` | `{f['command']}` | {f['date'] if got else ''} | "
                    f"{f['commit'] if got else ''} |")
    return "\n".join(rows)


def render_svgs():
    """WaveJSON -> SVG with wavedrom; returns {name: svg text}."""
    import wavedrom
    out = {}
    for j in sorted(WAVES.glob("*.json")):
        out[j.stem] = wavedrom.render(j.read_text()).tostring()
    return out


def render(gen):
    figs = json.loads(FIGURES.read_text())
    regs = ipxact.regs_json(gen)
    text = TEMPLATE.read_text()
    used = set()

    def fig(m):
        k = m.group(1)
        if k not in figs:
            raise SystemExit(f"datasheet: {{{{fig:{k}}}}}: no such figure in {FIGURES.name}")
        used.add(k)
        f = figs[k]
        return f"not collected (`{f['command']}`)" if f["value"] is None else fmt(f["value"], f["unit"])

    def fps(m):
        clk, cyc = m.group(1), m.group(2)
        used.update((clk, cyc))
        a, b = figs[clk]["value"], figs[cyc]["value"]
        return "not collected" if a is None or b is None else f"{a * 1e6 / b:.1f}"

    text = re.sub(r"\{\{fig:([\w.]+)\}\}", fig, text)
    text = re.sub(r"\{\{fps:([\w.]+):([\w.]+)\}\}", fps, text)
    text = text.replace("{{table:ports}}", ports_table())
    text = text.replace("{{table:registers}}", regs_table(regs))
    text = text.replace("{{table:errors}}", errors_table(regs))
    text = re.sub(r"\{\{wave:(\w+)\}\}", lambda m: f"![{m.group(1)}](datasheet/waves/{m.group(1)}.svg)", text)
    text = text.replace("{{table:sources}}", sources_table(figs, used))
    left = re.findall(r"\{\{[^}]*\}\}", text)
    if left:
        raise SystemExit(f"datasheet: unknown placeholders {left}")
    header = ("<!-- GENERATED by flow/datasheet.py from docs/datasheet/template.md and the files it names. -->\n"
              "<!-- Do not edit: make docs. A test fails when this file is stale. -->\n")
    lines = text.split("\n")
    return "\n".join(lines[:2]) + "\n" + header + "\n".join(lines[2:])


def html(md_text, out):
    import markdown
    body = markdown.markdown(md_text, extensions=["tables", "fenced_code"])
    # The SVGs inline, so the page stands alone.
    for name, svg in render_svgs().items():
        body = body.replace(f'<img alt="{name}" src="datasheet/waves/{name}.svg" />', svg)
    style = ("body{font-family:sans-serif;max-width:70em;margin:auto;padding:1em}"
             "table{border-collapse:collapse}td,th{border:1px solid #999;padding:2px 6px;font-size:90%}"
             "code{font-size:90%}")
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(f"<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>MCADSW datasheet</title>"
                   f"<style>{style}</style></head><body>\n{body}\n</body></html>\n")


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("cmd", choices=["collect", "render", "check"])
    ap.add_argument("--build", default=str(ROOT / "build"))
    ap.add_argument("--gen-rtl-pkg", default=str(ROOT / "build" / "bin" / "gen_rtl_pkg"))
    ap.add_argument("--html")
    ap.add_argument("--only", nargs="+", help="collect: only the figures whose key starts with one of these")
    a = ap.parse_args(argv)
    if a.cmd == "collect":
        collect(pathlib.Path(a.build), a.only)
        return 0
    text = render(a.gen_rtl_pkg)
    svgs = render_svgs()
    if a.cmd == "check":
        stale = [] if DOC.is_file() and DOC.read_text() == text else [str(DOC.relative_to(ROOT))]
        for n, svg in svgs.items():
            p = WAVES / f"{n}.svg"
            if not p.is_file() or p.read_text() != svg:
                stale.append(str(p.relative_to(ROOT)))
        if stale:
            print("datasheet: stale: " + ", ".join(stale) + " (run make docs)", file=sys.stderr)
            return 1
        print("docs/datasheet.md and its diagrams are up to date")
        return 0
    DOC.write_text(text)
    for n, svg in svgs.items():
        (WAVES / f"{n}.svg").write_text(svg)
    print(f"datasheet: {DOC.relative_to(ROOT)} and {len(svgs)} diagrams written")
    if a.html:
        html(text, pathlib.Path(a.html))
        print(f"datasheet: {a.html}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
