#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""The IP-XACT component read back (ctest ipxact_component):

    tests/ipxact/check_component.py [COMPONENT_XML [WRAPPER_V [REGISTERS_MD]]]

- parsed with ipyxact's IEEE 1685-2014 binding (ipyxact.ipxact2014), not with the
  generator's own code;
- every port of the wrapper, as Yosys 0.23 reads rtl/mcadsw_axi.v (write_json), is a port
  of the component with the same direction and width, and is mapped in exactly one bus
  interface (no plain ports); no component port or port map names a port the wrapper
  lacks;
- the register map equals docs/registers.md: the same registers (offset, name, access), the
  same fields (bits, access; W1C as read-write with oneToClear), and a register that
  docs/registers.md lists without fields holds one field VALUE of the width it states;
- every file of the file set exists.
Prints each disagreement and exits 1 if there is one.
"""
import json
import pathlib
import re
import subprocess
import sys

from ipyxact import ipxact2014

ROOT = pathlib.Path(__file__).resolve().parents[2]
ACCESS = {"RO": ("read-only", None), "RW": ("read-write", None), "WO": ("write-only", None),
          "W1C": ("read-write", "oneToClear")}


def wrapper_ports(path):
    out = subprocess.run(["yosys", "-q", "-p", f"read_verilog {path}; write_json -"], check=True,
                         capture_output=True, text=True).stdout
    mod = json.loads(out[out.index("{"):])["modules"]["mcadsw_axi"]
    return {n: ("in" if p["direction"] == "input" else "out", len(p["bits"]))
            for n, p in mod["ports"].items()}


def doc_map(path):
    """docs/registers.md: {name: (offset, access)}, {(reg, field): (lsb, width, access)},
    and the widths of registers listed without fields."""
    text = path.read_text()
    regs, fields = {}, {}
    for m in re.finditer(r"^\| 0x([0-9A-F]+) \| (\w+) \| (RO|RW|W1C|WO) \|", text, re.M):
        regs[m.group(2)] = (int(m.group(1), 16), m.group(3))
    for m in re.finditer(r"^\| (\w+) \| (\w+) \| (\d+)(?::(\d+))? \| (RO|RW|W1C|WO) \|", text, re.M):
        hi, lo = int(m.group(3)), int(m.group(4)) if m.group(4) else int(m.group(3))
        fields[(m.group(1), m.group(2))] = (lo, hi - lo + 1, m.group(5))
    m = re.search(r"(\d+) for the base addresses,\s+strides and counters, (\d+) for THR0..THR6", text)
    if not m or not regs or not fields:
        raise SystemExit(f"check_component: cannot read the tables of {path}")
    return regs, fields, (int(m.group(1)), int(m.group(2)))


def g(obj, name):
    """A child of a parsed element by its IP-XACT name (the binding capitalises some:
    BusInterfaces, AbstractionTypes, Vectors, Vector)."""
    for k in vars(obj):
        if k.lower() == name.lower():
            return getattr(obj, k)
    raise AttributeError(f"{type(obj).__name__} has no {name}")


def val(obj):
    """An element's text (expressions and names are objects with valueOf_)."""
    return str(obj.valueOf_ if hasattr(obj, "valueOf_") else obj)


def main(argv):
    xml = pathlib.Path(argv[0]) if argv else ROOT / "component.xml"
    wrapper = pathlib.Path(argv[1]) if len(argv) > 1 else ROOT / "rtl" / "mcadsw_axi.v"
    regs_md = pathlib.Path(argv[2]) if len(argv) > 2 else ROOT / "docs" / "registers.md"
    bad = []
    comp = ipxact2014.parse(str(xml), silence=True, print_warnings=False)

    # Ports.
    have = wrapper_ports(wrapper)
    comp_ports = {}
    for p in g(g(comp, "model"), "ports").port:
        vecs = g(p.wire, "vectors")
        vec = g(vecs, "vector")[0] if vecs else None
        width = int(val(vec.left)) - int(val(vec.right)) + 1 if vec else 1
        comp_ports[val(p.name)] = (p.wire.direction, width)
    for n, dw in have.items():
        if n not in comp_ports:
            bad.append(f"wrapper port {n} is not a port of the component")
        elif comp_ports[n] != dw:
            bad.append(f"port {n}: wrapper {dw}, component {comp_ports[n]}")
    for n in comp_ports:
        if n not in have:
            bad.append(f"component port {n} is not a port of the wrapper")
    mapped = {}
    buses = g(g(comp, "busInterfaces"), "busInterface")
    for bi in buses:
        for at in g(g(bi, "abstractionTypes"), "abstractionType"):
            for pm in g(g(at, "portMaps"), "portMap"):
                phys = val(g(g(pm, "physicalPort"), "name"))
                if phys not in have:
                    bad.append(f"bus interface {val(bi.name)} maps {phys}, not a wrapper port")
                mapped.setdefault(phys, []).append(val(bi.name))
    for n in have:
        if len(mapped.get(n, [])) != 1:
            bad.append(f"wrapper port {n} is in {len(mapped.get(n, []))} bus interfaces ({mapped.get(n, [])})")
    modes = {val(bi.name): [m for m in ("master", "slave") if g(bi, m) is not None] for bi in buses}
    if modes.get("s_axi") != ["slave"] or modes.get("m_axi") != ["master"]:
        bad.append(f"s_axi must be a slave and m_axi a master: {modes}")

    # Registers.
    regs, fields, (wide, thr) = doc_map(regs_md)
    block = comp.memoryMaps.memoryMap[0].addressBlock[0]
    seen = set()
    for r in block.register:
        name = val(r.name)
        seen.add(name)
        off = int(val(r.addressOffset), 0)
        if name not in regs:
            bad.append(f"register {name} is not in {regs_md.name}")
            continue
        if off != regs[name][0] or val(r.access) != ACCESS[regs[name][1]][0]:
            bad.append(f"register {name}: component offset 0x{off:02X} access {val(r.access)}, "
                       f"{regs_md.name} 0x{regs[name][0]:02X} {regs[name][1]}")
        doc_fields = {f: v for (rr, f), v in fields.items() if rr == name}
        if not doc_fields:
            doc_fields = {"VALUE": (0, thr if name.startswith("THR") else wide, regs[name][1])}
        got = {}
        for f in r.field:
            got[val(f.name)] = (int(val(f.bitOffset), 0), int(val(f.bitWidth), 0), val(f.access),
                                val(f.modifiedWriteValue) if f.modifiedWriteValue else None)
        want = {k: (lo, w, *ACCESS[a]) for k, (lo, w, a) in doc_fields.items()}
        if got != want:
            bad.append(f"register {name}: fields {got} in the component, {want} in {regs_md.name}")
    for name in regs:
        if name not in seen:
            bad.append(f"register {name} of {regs_md.name} is not in the component")

    # Files.
    for fs in comp.fileSets.fileSet:
        for f in fs.file:
            if not (ROOT / val(f.name)).is_file():
                bad.append(f"file set {val(fs.name)}: {val(f.name)} does not exist")

    for b in bad:
        print("check_component: " + b)
    if bad:
        return 1
    print(f"check_component: {xml.name} parses (IP-XACT 1685-2014); its {len(comp_ports)} ports are "
          f"the wrapper's, each in one of {len(buses)} bus interfaces; "
          f"its {len(seen)} registers and their fields equal {regs_md.name}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
