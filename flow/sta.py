# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

"""Timing of the assembled engine netlist (flow/synth.py, step 4): the netlist
prepared for OpenSTA (flow/sta_netlist.tcl, then every MCADSW_RAM instance a
parameter-free macro cell with a generated liberty), OpenSTA (flow/sta_engine.tcl),
and the figures read back from its logs."""
import re
import sys
from pathlib import Path

from blocks import read_table
from flowlib import CON, FLOW, RAM_MODEL, FlowError, indent, log, tail

STA_OUT = ("mcadsw_engine_sta.v", "mcadsw_ram.lib", "sta.log", "sta_endpoints.log", "sta_crossing.txt")


# ---- STA netlist: parameter-free macro cells and their liberty ---------------------------
def sta_netlist(flat_v, out, cfg_path, top="mcadsw_engine"):
    """Every MCADSW_RAM instance of the flattened netlist renamed to a parameter-free
    cell per shape (MCADSW_RAM_S<words>_W<bits>_A<addr bits>_<SYNC|ASYNC>, _WE when
    all bit write enables are one net: a word write enable); writes
    <top>_sta.v and mcadsw_ram.lib (a cell per shape, timing from
    constraints/mcadsw_ram_timing.cfg). Returns the number of shapes."""
    def val(s):
        s = s[s.rfind("(") + 1:]
        s = s.split(")")[0]
        if "'b" in s:   # x and z bits (initial values) count as 0
            return int(re.sub(r"[^01]", "0", s.split("'b")[1]) or "0", 2)
        if "'d" in s:
            s = s.split("'d")[1]
        m = re.match(r"\s*[0-9]+", s)
        return int(m.group()) if m else 0

    renamed, shapes, inmac, p = [], {}, False, {}
    for line in Path(flat_v).read_text().splitlines():
        if re.match(r"^ *MCADSW_RAM #\($", line):
            inmac, p = True, {}
        elif inmac and re.match(r"^ *\.", line):
            p[line.strip()[1:].split("(")[0]] = val(line)
        elif inmac and re.match(r"^ *\) ", line):
            if p.get("RD_PORTS") != 1 or p.get("WR_PORTS") != 1:
                raise FlowError("STA netlist: multi-port macro")
            cell = (f"MCADSW_RAM_S{p['SIZE']}_W{p['WIDTH']}_A{p['ABITS']}_"
                    f"{'SYNC' if p['RD_CLK_ENABLE'] else 'ASYNC'}")
            shapes.setdefault(cell, (p["SIZE"], p["WIDTH"], p["ABITS"], p["RD_CLK_ENABLE"]))
            renamed.append(re.sub(r"^ *\)", "  " + cell, line, count=1))
            inmac = False
        elif inmac:
            raise FlowError(f"STA netlist: unexpected line in a macro instance: {line}")
        else:
            renamed.append(line)
    # A macro whose bit write enables are all one net is a macro with a word write
    # enable (WR_WE): that is how it would be built, and it keeps a single enable
    # from appearing to drive thousands of macro pins.
    final, buf, inst = [], [], False
    for line in renamed:
        if re.match(r"^ *MCADSW_RAM_[A-Z0-9_]+ .*\($", line):
            inst, buf = True, [line]
            continue
        if inst and re.match(r"^ *\.WR_EN\(\{ .* \}\),?$", line):
            body = re.sub(r"^ *\.WR_EN\(\{ ", "", line)
            comma = body.endswith(",")
            items = re.sub(r" \}\),?$", "", body).split(", ")
            if all(i == items[0] for i in items):
                buf[0] = re.sub(r"^( *MCADSW_RAM_[A-Z0-9_]+)", r"\1_WE", buf[0], count=1)
                buf.append(f"    .WR_WE({items[0]})" + ("," if comma else ""))
                continue
        if inst:
            buf.append(line)
            if re.match(r"^ *\);$", line):
                inst = False
                final += buf
                buf = []
            continue
        final.append(line)
    text = "\n".join(final) + "\n"
    if "#(" in text:
        raise FlowError(f"STA netlist: parameterised instances left in {out}/{top}_sta.v")
    (out / f"{top}_sta.v").write_text(text)

    cfg = {}
    for line in Path(cfg_path).read_text().splitlines():
        w = line.split()
        if len(w) >= 2 and not w[0].startswith("#"):
            cfg[w[0]] = w[1]
    cap, slew = cfg["pin_cap"], cfg["out_transition"]
    lib = []

    def arc(rel, typ, d):
        lib.append(f'      timing () {{ related_pin : "{rel}"; timing_type : {typ};')
        if "setup" in typ or "hold" in typ:
            lib.append(f'        rise_constraint (scalar) {{ values ("{d}"); }} '
                       f'fall_constraint (scalar) {{ values ("{d}"); }} }}')
        else:
            lib.append(f'        cell_rise (scalar) {{ values ("{d}"); }} cell_fall (scalar) {{ values ("{d}"); }}')
            lib.append(f'        rise_transition (scalar) {{ values ("{slew}"); }} '
                       f'fall_transition (scalar) {{ values ("{slew}"); }} }}')

    def input_bus(name, w, clk):
        lib.append(f"    bus ({name}) {{ bus_type : bus{w}; direction : input; capacitance : {cap};")
        arc(clk, "setup_rising", cfg["setup"])
        arc(clk, "hold_rising", cfg["hold"])
        lib.append("    }")

    def input_pin(name, clk):
        lib.append(f"    pin ({name}) {{ direction : input; capacitance : {cap};")
        arc(clk, "setup_rising", cfg["setup"])
        arc(clk, "hold_rising", cfg["hold"])
        lib.append("    }")

    lib += ["/* Generated by flow/sta.py from constraints/mcadsw_ram_timing.cfg: timing models",
            "   of the MCADSW_RAM memory macros (one cell per shape). Not a characterised library. */",
            "library (mcadsw_ram) {",
            "  delay_model : table_lookup;",
            '  time_unit : "1ns"; voltage_unit : "1V"; current_unit : "1uA";',
            '  pulling_resistance_unit : "1kohm"; leakage_power_unit : "1nW"; capacitive_load_unit (1,pf);',
            "  slew_upper_threshold_pct_rise : 80; slew_lower_threshold_pct_rise : 20;",
            "  slew_upper_threshold_pct_fall : 80; slew_lower_threshold_pct_fall : 20;",
            "  input_threshold_pct_rise : 50; input_threshold_pct_fall : 50;",
            "  output_threshold_pct_rise : 50; output_threshold_pct_fall : 50;",
            "  nom_process : 1; nom_voltage : 1.8; nom_temperature : 25;"]
    for n in sorted({w for s in shapes.values() for w in (s[1], s[2])}):
        lib.append(f"  type (bus{n}) {{ base_type : array; data_type : bit; bit_width : {n}; "
                   f"bit_from : {n - 1}; bit_to : 0; downto : true; }}")
    for cell, (size, width, abits, sync) in shapes.items():
        for we in (False, True):
            lib.append(f"  cell ({cell}{'_WE' if we else ''}) {{")
            lib.append("    area : 0; dont_touch : true; dont_use : true;")
            lib.append(f"    pin (RD_CLK) {{ direction : input; capacitance : {cap}; clock : true; }}")
            lib.append(f"    pin (WR_CLK) {{ direction : input; capacitance : {cap}; clock : true; }}")
            lib.append(f"    pin (RD_ARST) {{ direction : input; capacitance : {cap}; }}")
            if sync:
                input_pin("RD_EN", "RD_CLK")
                input_bus("RD_ADDR", abits, "RD_CLK")
            else:
                lib.append(f"    pin (RD_EN) {{ direction : input; capacitance : {cap}; }}")
                lib.append(f"    bus (RD_ADDR) {{ bus_type : bus{abits}; direction : input; capacitance : {cap}; }}")
            if we:
                input_pin("WR_WE", "WR_CLK")
            else:
                input_bus("WR_EN", width, "WR_CLK")
            input_bus("WR_ADDR", abits, "WR_CLK")
            input_bus("WR_DATA", width, "WR_CLK")
            lib.append(f"    bus (RD_DATA) {{ bus_type : bus{width}; direction : output;")
            if sync:
                arc("RD_CLK", "rising_edge", cfg["clk_to_q"])
            else:
                acc = cfg["async_access"]
                lib.append('      timing () { related_bus_pins : "RD_ADDR"; timing_type : combinational; '
                           'timing_sense : non_unate;')
                lib.append(f'        cell_rise (scalar) {{ values ("{acc}"); }} cell_fall (scalar) {{ values ("{acc}"); }}')
                lib.append(f'        rise_transition (scalar) {{ values ("{slew}"); }} '
                           f'fall_transition (scalar) {{ values ("{slew}"); }} }}')
                arc("WR_CLK", "rising_edge", acc)
            lib.append("    }\n  }")
    lib.append("}")
    (out / "mcadsw_ram.lib").write_text("\n".join(lib) + "\n")
    return len(shapes)



def run_sta(run, out, yosys, lib, sdc, netlist):
    """The STA netlist and macro liberty, then OpenSTA: (peak MB of each)."""
    log(f"OpenSTA on the assembled netlist (log: {out}/sta.log)")
    for f in STA_OUT:
        (out / f).unlink(missing_ok=True)
    rc, stanet_mb, _ = run.run([yosys, "-q", "-l", str(out / "sta_netlist.log"), "-c", str(FLOW / "sta_netlist.tcl")],
                               err_path=out / "sta_netlist.err",
                               env={"RAM_MODEL": str(RAM_MODEL), "LIBERTY": lib, "NETLIST": str(netlist),
                                    "OUT_V": str(out / "mcadsw_engine_flat.v")})
    if rc != 0:
        sys.stderr.write(indent(tail(out / "sta_netlist.log", 20)))
        raise FlowError(f"preparing the STA netlist failed (log: {out}/sta_netlist.log)")
    resized = [ln for ln in tail(out / "sta_netlist.log", 10**7) if "Resizing cell port" in ln]
    if resized:
        sys.stderr.write("".join(ln + "\n" for ln in resized[:5]))
        raise FlowError(f"STA netlist: port widths of an instance and its module differ in {netlist}")
    nshapes = sta_netlist(out / "mcadsw_engine_flat.v", out, CON / "mcadsw_ram_timing.cfg")
    (out / "mcadsw_engine_flat.v").unlink()
    log(f"  {nshapes} macro shapes -> {out}/mcadsw_ram.lib, netlist {out}/mcadsw_engine_sta.v")
    rc, sta_mb, _ = run.run(["sta", "-no_splash", "-exit", str(FLOW / "sta_engine.tcl")],
                            out_path=out / "sta.log", err_path=out / "sta.err",
                            env={"LIBERTY": lib, "OUT_DIR": str(out), "SDC": str(sdc)})
    sta_log = (out / "sta.log").read_text(errors="replace")
    if rc != 0 or not re.search(r"^worst slack", sta_log, re.M):
        sys.stderr.write(indent(sta_log.splitlines()[-20:] + tail(out / "sta.err", 5)))
        raise FlowError(f"sta failed or gave no worst slack (log: {out}/sta.log)")
    return stanet_mb, sta_mb



def read_sta(out, instances=()):
    """The figures of OpenSTA's logs in out: wns and worst slack (ns), the critical
    path, the nets of the crossing check (slowest first), the violating
    endpoints per block instance, and for each top-level instance named in
    instances (u_rectifier, ...) its endpoints and their worst slack (endpoint_slack)."""
    sta_log = (out / "sta.log").read_text(errors="replace")

    def first(pattern, text, field):
        for line in text.splitlines():
            if re.match(pattern, line):
                return line.split()[field]
        return None
    # wns: worst negative slack (0 when every path meets the clock); slack: the
    # worst path's slack, negative or positive, which sets the achievable clock.
    wns, slack = first(r"^wns", sta_log, 1), first(r"^worst slack", sta_log, 2)
    if wns is None or slack is None:
        sys.stderr.write(indent(sta_log.splitlines()[-20:] + tail(out / "sta.err", 5)))
        raise FlowError(f"sta failed or gave no wns / worst slack (log: {out}/sta.log)")
    wns, slack = float(wns), float(slack)
    # The critical path: of the paths report_checks printed (one a path group: the
    # clock, and with clock gates the gating checks), the one with the least slack.
    paths = []
    for block in re.split(r"^(?=Startpoint:)", sta_log, flags=re.M)[1:]:
        s = re.search(r"^\s*(-?[0-9.]+)\s+slack \(", block, re.M)
        paths.append((float(s.group(1)) if s else float("inf"), block.splitlines()))
    lines = min(paths, key=lambda p: p[0])[1] if paths else []
    crit_start = next((ln[len("Startpoint: "):] for ln in lines if ln.startswith("Startpoint:")), "")
    crit_end = next((ln[len("Endpoint: "):] for ln in lines if ln.startswith("Endpoint:")), "")
    crit_arrival = next((ln.split()[0] for ln in lines if "data arrival time" in ln), "")
    crossing = [(w[0], w[1], w[2], int(w[3]), float(w[4])) for w in read_table(out / "sta_crossing.txt")]
    crossing.sort(key=lambda c: -c[4])
    cross_worst = float(f"{crossing[0][4]:.3f}") if crossing else 0
    cross_slow = sum(1 for c in crossing if c[4] > 0.5)
    viol, inst = endpoint_slack(out / "sta_endpoints.log", instances)
    return {"wns": wns, "slack": slack, "crit": (crit_start, crit_end, crit_arrival), "crossing": crossing,
            "cross_worst": cross_worst, "cross_slow": cross_slow, "viol": viol, "endpoint_slack": inst}


def endpoint_slack(path, instances=()):
    """Every endpoint of flow/sta_engine.tcl's sta_endpoints.log (report_checks
    -format end: `<endpoint> (<cell>) <required> <actual> <slack> (MET|VIOLATED)`,
    every path group, the clock gates' checks included). The STA netlist is
    flattened: a cell of a block instance is named <instance>.<cell of the block>
    (u_post._15412_/D, u_post.clock_gate_0_and/B), the top's own cells _<n>_ and
    ports by their names. Returns (violating endpoints per block instance: {the
    name's first component, "top" for the top's cells: (count, worst slack)}, and
    for each name of instances: {instance: (endpoints, worst slack or None when
    the log has none of it)})."""
    viol, inst = {}, {i: (0, None) for i in instances}
    for line in Path(path).read_text(errors="replace").splitlines():
        w = line.split()
        if len(w) < 6 or w[-1] not in ("(MET)", "(VIOLATED)"):
            continue
        try:
            s = float(w[-2])
        except ValueError:
            continue
        for i in instances:
            if w[0].startswith(i + "."):
                n, worst = inst[i]
                inst[i] = (n + 1, s if worst is None or s < worst else worst)
        if w[-1] == "(VIOLATED)":
            # Per block instance: the instance path's first component.
            bl = re.sub(r"\[.*", "", w[0].split(".")[0])
            bl = "top" if bl.startswith("_") else bl
            n, worst = viol.get(bl, (0, None))
            viol[bl] = (n + 1, s if worst is None or s < worst else worst)
    return viol, inst
