#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

"""The synthesis report (report.md) from the flow's summary.json.

flow/synth.py writes summary.json (every figure of the run) and then this
report from it; run alone it renders a summary again:

  flow/synth_report.py build/synth/summary.json > report.md
"""
import json
import sys

# The paper's Fig. 16 names the three blocks that dominate the gate count.
DOMINANT = ["census_left", "census_right", "cost_aggregator_wta"]
# The rectifier's group (flow/blocks.py RECT_GROUP): inside the engine, reported apart,
# not in the engine's totals (summary.json nand2_eq, flip_flops, memory_kB_engine).
RECT = "rectifier"


def kb(bits):
    return float(f"{bits / 8 / 1024:.1f}")


def render(s):
    run, crit, ram, cross = s["run"], s["critical_path"], s["ram_timing"], s["crossing"]
    rect_bits = s.get("rect_memory_bits", 0)
    rect_mods = set(s.get("rect", {}))
    r = [f"# Synthesis report (`make synth`, DMAX = {s['dmax']}, PAR = {s['par']}, hierarchical)", "",
         f"Yosys 0.23 to OSU 0.18 um standard cells (`{s['liberty']}`), block by block: each block",
         "(each module parameterisation the top instantiates, sub-modules flattened into it) and the top's own",
         f"logic (blocks as black boxes) in its own Yosys process, {s['jobs']} at a time; ABC with buffering",
         "(`constraints/abc_osu018.script`, `-constr constraints/abc_osu018.constr`) per block; the block",
         "netlists assembled into `mcadsw_engine_osu018.v`; OpenSTA on it against `constraints/mcadsw.sdc`.",
         "On-chip memories are black-box macros (`MCADSW_RAM`, ports from `sim/gls/mcadsw_ram_model.v`),",
         "counted apart as the paper does. Scripts: `flow/` (driver `flow/synth.py`).", "",
         f"Run: {run['wall_seconds']} s wall (blocks {run['blocks_wall_seconds']} s incl. elaboration, STA "
         f"{run['sta_seconds']} s); {run['synthesised']} blocks synthesised",
         f"({run['yosys_seconds']} s of Yosys in all), {run['reused']} unchanged and reused. Peak memory: "
         f"{run['peak_process_MB']} MB for the largest",
         f"single process ({run['peak_process']}; " +
         (f"largest block run {run['largest_block_MB']} MB" if run["synthesised"] else "no block run") +
         f", STA netlist preparation {run['sta_netlist_MB']} MB,",
         f"OpenSTA {run['sta_MB']} MB), {run['peak_sum_MB']} MB for all processes of the run together "
         f"(sampled each second).",
         "", "| figure | this engine | paper (Table III, UMC 90 nm) |", "|---|---|---|",
         f"| gates (NAND2 equivalents, memories excluded" + (", without the rectifier" if rect_mods else "") +
         f") | {s['nand2_eq']} | 563k |",
         f"| with the SoC wrapper (mcadsw_top: AXI4-Lite registers {s['soc_regs_nand2_eq']}, AXI4 master "
         f"{s['soc_axi_master_nand2_eq']}; each timed alone, worst slack {s['soc_worst_slack_ns']} ns) | "
         f"{s['soc_total_nand2_eq']} | |",
         f"| on-chip memory | {s['memory_bits']} bits = {s['memory_kB']} kB in {s['memory_macros']} macros | 21.3 kB |",
         f"| of which the engine of the paper (without the LR post stage" +
         (" and the rectifier" if rect_mods else "") + ") | "
         f"{s['memory_bits'] - s['post_stage_memory_bits'] - rect_bits} bits = {s['memory_kB_engine']} kB | "
         f"21.3 kB |",
         f"| LR post stage (beyond the paper): gates, memory | {s['post_stage_nand2_eq']} NAND2 eq, "
         f"{s['post_stage_memory_bits']} bits = {s['post_stage_memory_kB']} kB | |",
         *([f"| rectifier (beyond the paper; in the engine, reported apart, below): gates, memory, "
            f"worst slack | {s['rect_nand2_eq']} NAND2 eq, {rect_bits} bits = {s['rect_memory_kB']} kB, "
            f"{s['rect_worst_slack_ns']} ns | |"] if rect_mods else []),
         f"| macros with an asynchronous read port | {s['async_read_macros']} (every other read port: address "
         f"registered, data the next cycle) | |",
         f"| data registers of 64 bits or more (flip-flops, in the gate count) | {s['data_register_bits']} bits in "
         f"{sum(1 for x in s['data_registers'] if x[0] not in rect_mods)} registers (listed below" +
         (", with the rectifier's" if rect_mods else "") + ") | |",
         f"| flip-flops (in the gate count) | {s['flip_flops']} | |",
         "| clock gating (flow/clock_gate.py, latch + AND a group) | " + (
             f"{s['clock_gating']['gated_flip_flops']} flip-flops behind {s['clock_gating']['gates']} gates "
             f"(groups of {s['clock_gating']['min_group']} or more sharing an enable); "
             f"{s['clock_gating']['enable_flip_flops_kept']} keep their enable multiplexer"
             if s['clock_gating']['min_group'] else "none (CLOCK_GATE_MIN=0)") + " | none described |",
         f"| clock target | {s['clock_mhz']} MHz | 95 MHz |",
         f"| worst slack (WNS) | {s['worst_slack_ns']} ns ({s['wns_ns']} ns) | |",
         f"| achievable clock (1 / (period - slack)) | {s['fmax_mhz']} MHz | 95 MHz |"]
    cif = s.get("cif_cycles")
    if cif and s["dmax"] == 64 and s["par"] == 1:
        r.append(f"| CIF frame at D = 64 (`make sim`) | {cif} cycles = {s['fmax_mhz'] * 1e6 / cif:.1f} fps at "
                 f"{s['fmax_mhz']} MHz, {95e6 / cif:.1f} fps at 95 MHz | 42 fps at 95 MHz |")
    r += ["", f"Critical path: from `{crit['start']}` to `{crit['end']}`, arrival {crit['arrival_ns']} ns",
          "(full path in `sta.log`). Paths into and out of the memory macros are timed with the",
          "assumed macro timing of `constraints/mcadsw_ram_timing.cfg` (OSU 0.18 um has no memory compiler):",
          f"clocked read {ram['clk_to_q']} ns after the clock, asynchronous read {ram['async_access']} ns, "
          f"setup {ram['setup']} ns.", "",
          f"Nets between blocks (`sta_crossing.txt`: pins in more than one block instance): {cross['nets']}; worst",
          f"transition at their driver {cross['worst_transition_ns']} ns, {cross['above_0_5_ns']} above 0.5 ns. "
          f"The slowest:", "",
          "| net | driver | cell | pins | transition (ns) |", "|---|---|---|---|---|"]
    r += [f"| `{c['net']}` | `{c['driver']}` | {c['cell']} | {c['pins']} | {c['transition_ns']:.3f} |"
          for c in cross["slowest"]]
    r.append("")
    if s["violations"]:
        r += ["Endpoints that miss the clock, per block instance (`sta_endpoints.log`):", "",
              "| instance | violating endpoints | worst slack (ns) |", "|---|---|---|"]
        r += [f"| {v['instance']} | {v['endpoints']} | {v['worst_slack_ns']} |" for v in s["violations"]]
    else:
        r.append("Every endpoint meets the clock.")
    total = s["nand2_eq"]
    rect_total = s.get("rect_nand2_eq") or 1

    def share(nand2, group):
        # A share of the engine's gates; the rectifier's blocks: of the rectifier's.
        if group == RECT and rect_mods:
            return f"{100 * nand2 / rect_total:.1f} % of the rectifier"
        return f"{100 * nand2 / total:.1f} %"
    r += ["", "## Blocks", "", "Each line one Yosys run (`blocks/<block>/`); figures per instance; shares of the "
          "engine's gates" + (" (the rectifier's blocks: of the rectifier's, not in the engine's)" if rect_mods
                              else "") + ".", "",
          "| block | module | instances | NAND2 eq | share | flip-flops | memory bits | Yosys s | peak MB | this run |",
          "|---|---|---|---|---|---|---|---|---|---|"]
    for label, b in sorted(s["blocks"].items(), key=lambda kv: -kv[1]["nand2_eq"]):
        r.append(f"| {label} | {b['module']} | {b['instances']} | {b['nand2_eq']} | "
                 f"{share(b['instances'] * b['nand2_eq'], b.get('group'))} | {b['flip_flops']} | "
                 f"{b['memory_bits']} | "
                 f"{b['yosys_seconds']} | {b['peak_MB']} | {'reused' if b['reused'] else 'synthesised'} |")
    if rect_mods:
        r += ["", "## Rectifier, in the engine, reported apart", "",
              "The rectifier of `rtl/rect/` is inside the engine: `mcadsw_rectifier` (instance `u_rectifier`), its",
              "pass (`mcadsw_rect`), mark step (`mcadsw_rect_mark`) and configuration check (`mcadsw_rect_check`),",
              "is a block of the engine, mapped, assembled and timed with it (group",
              "`rectifier`). Its figures are reported apart and excluded from the engine's budgets (the gates,",
              "flip-flops and engine memory above; the macro count and the asynchronous-read count above include",
              "it). Its worst slack is the worst endpoint inside its instances in the engine's STA",
              "(`sta_endpoints.log`: paths that end in the rectifier; a path from it into the rest of the engine",
              "ends there); the engine's worst slack above is the whole netlist's, the rectifier's included.",
              "The rectifier's limits: 60 000 NAND2 eq and 4 kB of on-chip memory, the engine's own budgets",
              "unchanged.", "",
              "| module | NAND2 eq | flip-flops (clock-gated) | memory | worst slack (ns) |", "|---|---|---|---|---|"]
        for m, x in s["rect"].items():
            inst = f" ({', '.join(x['instance_names'])})" if x.get("instance_names") else ""
            r.append(f"| {m}{inst} | {x['nand2_eq']} | {x['flip_flops']} ({x['gated_flip_flops']}) | "
                     f"{x['memory_bits']} bits in {x['memory_macros']} macros | {x['worst_slack_ns']} |")
        r.append(f"| **rectifier** | **{s['rect_nand2_eq']}** (limit 60 000) | | **{s['rect_memory_kB']} kB** "
                 f"(limit 4 kB) | {s['rect_worst_slack_ns']} |")
    r += ["", "## Gates per paper block (Fig. 16)", "",
          "The paper's Fig. 16 gives the gate shares as a chart only; its text says: \"The total gate-count",
          "was dominated by the cost aggregator and WTA, census left buffer, and census right buffer. This was",
          "due to the high-computation resource requirement and complex demultiplexing circuits.\"", "",
          "| paper block | NAND2 eq | share | flip-flops | memory bits | paper (Fig. 16, text) |",
          "|---|---|---|---|---|---|"]
    for g in s["groups"]:
        sh = "apart, not in the engine's" if g["group"] == RECT and rect_mods else share(g["nand2_eq"], g["group"])
        r.append(f"| {g['name']} | {g['nand2_eq']} | {sh} | {g['flip_flops']} | "
                 f"{g['memory_bits']} | {g['paper']} |")
    if sorted([g["group"] for g in s["groups"] if g["group"] != RECT][:3]) == DOMINANT:
        r += ["", "As in the paper, the cost aggregator + WTA and the two census blocks are the three largest."]
    r += ["", "Memory per module (bits):", "", "| module | bits | kB |", "|---|---|---|"]
    per_mod = {}
    for m in s["memories"]:
        per_mod[m[0]] = per_mod.get(m[0], 0) + int(m[4])
    r += [f"| {k} | {v} | {v / 8192:.1f} |" for k, v in sorted(per_mod.items(), key=lambda kv: -kv[1])]
    r.append("")
    if s["memory_kB_engine"] > 21.3:
        r += ["The memory exceeds the paper's 21.3 kB; where it stands and what would close the gap:",
              "docs/budget.md (storage) and docs/results.md (synthesis).", ""]
    r += ["## Memories (black-box macros)", "",
          "| module | memory | width | words | bits | read ports | write ports | read |",
          "|---|---|---|---|---|---|---|---|"]
    r += ["| " + " | ".join(m[:8]) + " |" for m in s["memories"]]
    r += ["", "## Data registers (flip-flops of 64 bits or more)", "",
          "Registers that hold image, census, weight or cost words in flip-flops rather than in a macro:",
          "pipeline registers, staging registers and the buffers kept in flip-flops (docs/budget.md,",
          "storage). Their bits are in the gate count, not in the memory figure.", "",
          "| module | register | bits |", "|---|---|---|"]
    r += [f"| {x[0]} | {x[1]} | {x[2]} |" for x in sorted(s["data_registers"], key=lambda x: -int(x[2]))]
    return "\n".join(r) + "\n"


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: flow/synth_report.py SUMMARY.json > report.md")
    with open(sys.argv[1]) as f:
        sys.stdout.write(render(json.load(f)))
