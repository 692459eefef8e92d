#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""Writes the IP-XACT (IEEE 1685-2014) component of the vendor-tool wrapper rtl/mcadsw_axi.v:
component.xml at the repository's root, where Vivado's IP catalog looks for it (Settings ->
IP -> Repository: the repository's folder).

    flow/ipxact.py [--gen-rtl-pkg EXE]            rewrite component.xml (make rtl-pkg runs it)
    flow/ipxact.py [--gen-rtl-pkg EXE] --check    exit 1 with a diff when it is stale (ctest)

Its sources, so that nothing in it is typed twice:
  - the ports: rtl/mcadsw_axi.v's ANSI port list (one `input|output wire [l:r] name` a line);
  - the register map: `gen_rtl_pkg regs-json` (sw_ref/include/mcadsw/regs.hpp, the map's single
    source; EXE defaults to build/bin/gen_rtl_pkg);
  - the configuration it describes: rtl/mcadsw_pkg.sv's DMAX, PAR, FPGA and RECT (component
    parameters, informative: the package sets them, not the wrapper);
  - the files: rtl/mcadsw.f, then the wrapper;
  - the version: CMakeLists.txt's project().

Bus interfaces use the bus definitions Vivado ships (xilinx.com:interface:aximm:1.0 with
PROTOCOL AXI4LITE and AXI4, xilinx.com:signal:clock / reset / interrupt:1.0), and map every
port of a bus: s_axi_<sig> and m_axi_<sig> onto the logical port <SIG>, aclk onto CLK,
aresetn onto RST, interrupt onto INTERRUPT. A port that fits no bus interface stops the
generator (ctest ipxact_component checks the same from the wrapper as Yosys reads it).
"""
import argparse
import json
import re
import subprocess
import sys
from xml.sax.saxutils import escape, quoteattr

from flowlib import ROOT, project_version, rtl_list, write_or_check

OUT = ROOT / "component.xml"
WRAPPER = ROOT / "rtl" / "mcadsw_axi.v"
NS = "http://www.accellera.org/XMLSchema/IPXACT/1685-2014"

ACCESS = {"RO": ("read-only", None), "RW": ("read-write", None), "WO": ("write-only", None),
          "W1C": ("read-write", "oneToClear")}

# The bus interfaces: name, Vivado bus type, abstraction, mode, port prefix or ports, parameters.
BUSES = [
    {"name": "s_axi", "bus": ("xilinx.com", "interface", "aximm", "1.0"),
     "abs": ("xilinx.com", "interface", "aximm_rtl", "1.0"), "mode": "slave",
     "prefix": "s_axi_", "params": {"PROTOCOL": "AXI4LITE", "DATA_WIDTH": "32"}},
    {"name": "m_axi", "bus": ("xilinx.com", "interface", "aximm", "1.0"),
     "abs": ("xilinx.com", "interface", "aximm_rtl", "1.0"), "mode": "master",
     "prefix": "m_axi_", "params": {"PROTOCOL": "AXI4", "DATA_WIDTH": "32", "MAX_BURST_LENGTH": "16"}},
    {"name": "aclk", "bus": ("xilinx.com", "signal", "clock", "1.0"),
     "abs": ("xilinx.com", "signal", "clock_rtl", "1.0"), "mode": "slave",
     "ports": {"aclk": "CLK"}, "params": {"ASSOCIATED_BUSIF": "s_axi:m_axi", "ASSOCIATED_RESET": "aresetn"}},
    {"name": "aresetn", "bus": ("xilinx.com", "signal", "reset", "1.0"),
     "abs": ("xilinx.com", "signal", "reset_rtl", "1.0"), "mode": "slave",
     "ports": {"aresetn": "RST"}, "params": {"POLARITY": "ACTIVE_LOW"}},
    {"name": "interrupt", "bus": ("xilinx.com", "signal", "interrupt", "1.0"),
     "abs": ("xilinx.com", "signal", "interrupt_rtl", "1.0"), "mode": "master",
     "ports": {"interrupt": "INTERRUPT"}, "params": {"SENSITIVITY": "LEVEL_HIGH"}},
]

PKG_PARAMS = {"DMAX": "largest disparity range D of this build (HWCONFIG.DMAX)",
              "PAR": "disparities a step (HWCONFIG.PAR)",
              "FPGA": "target: 0 the ASIC memory shapes, 1 the FPGA's (block RAM)",
              "RECT": "1: the rectifier is built in (HWCONFIG.NORECT reads its inverse)"}


def regs_json(gen):
    """The register map, `gen_rtl_pkg regs-json`; exit 2 with a message when GEN fails."""
    try:
        return json.loads(subprocess.run([gen, "regs-json"], check=True, capture_output=True, text=True).stdout)
    except (OSError, subprocess.CalledProcessError) as e:
        raise SystemExit(f"{gen} regs-json failed ({e}); build it: cmake --build build --target gen_rtl_pkg") \
            from None


def ports():
    """(name, direction, width) of the wrapper's ports, in order."""
    out = []
    for line in WRAPPER.read_text().splitlines():
        m = re.match(r"\s*(input|output)\s+wire\s+(?:\[(\d+):0\]\s+)?(\w+)\s*,?\s*(//.*)?$", line)
        if m:
            out.append((m.group(3), "in" if m.group(1) == "input" else "out",
                        int(m.group(2)) + 1 if m.group(2) else 1))
    if not out:
        raise SystemExit(f"ipxact: no ports found in {WRAPPER}")
    return out


def bus_of(port):
    for b in BUSES:
        if "prefix" in b and port.startswith(b["prefix"]):
            return b, port[len(b["prefix"]):].upper()
        if port in b.get("ports", {}):
            return b, b["ports"][port]
    return None, None


def pkg_values():
    text = (ROOT / "rtl" / "mcadsw_pkg.sv").read_text()
    vals = {}
    for k in PKG_PARAMS:
        m = re.search(rf"localparam int {k}\s*=\s*(\d+);", text)
        if not m:
            raise SystemExit(f"ipxact: rtl/mcadsw_pkg.sv has no {k}")
        vals[k] = int(m.group(1))
    return vals


def files():
    return ["rtl/" + f for f in rtl_list()] + ["rtl/mcadsw_axi.v"]


def vlnv_attrs(v):
    return f'vendor="{v[0]}" library="{v[1]}" name="{v[2]}" version="{v[3]}"'


def component(regs):
    ps = ports()
    lines = []
    w = lines.append
    w('<?xml version="1.0" encoding="UTF-8"?>')
    # (Written in two pieces so that the licence check does not read these lines as this file's.)
    w("<!-- SPDX-" "FileCopyrightText: 2026 The mcadsw authors -->")
    w("<!-- SPDX-" "License-Identifier: Apache-2.0 -->")
    w("<!-- GENERATED by flow/ipxact.py from rtl/mcadsw_axi.v, sw_ref/include/mcadsw/regs.hpp,")
    w("     rtl/mcadsw_pkg.sv and rtl/mcadsw.f. Do not edit: run `make rtl-pkg`. A test fails")
    w("     when this file is stale. -->")
    w(f'<ipxact:component xmlns:ipxact="{NS}" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" '
      f'xsi:schemaLocation="{NS} {NS}/index.xsd">')
    w("  <ipxact:vendor>mcadsw</ipxact:vendor>")
    w("  <ipxact:library>ip</ipxact:library>")
    w("  <ipxact:name>mcadsw_axi</ipxact:name>")
    w(f"  <ipxact:version>{project_version()}</ipxact:version>")
    # Bus interfaces, every port of each mapped.
    w("  <ipxact:busInterfaces>")
    for b in BUSES:
        maps = [(p, logical) for p, _, _ in ps for bb, logical in [bus_of(p)] if bb is b]
        if not maps:
            raise SystemExit(f"ipxact: bus interface {b['name']} has no port in the wrapper")
        w("    <ipxact:busInterface>")
        w(f"      <ipxact:name>{b['name']}</ipxact:name>")
        w(f"      <ipxact:busType {vlnv_attrs(b['bus'])}/>")
        w("      <ipxact:abstractionTypes>")
        w("        <ipxact:abstractionType>")
        w(f"          <ipxact:abstractionRef {vlnv_attrs(b['abs'])}/>")
        w("          <ipxact:portMaps>")
        for p, logical in maps:
            w("            <ipxact:portMap>")
            w(f"              <ipxact:logicalPort><ipxact:name>{logical}</ipxact:name></ipxact:logicalPort>")
            w(f"              <ipxact:physicalPort><ipxact:name>{p}</ipxact:name></ipxact:physicalPort>")
            w("            </ipxact:portMap>")
        w("          </ipxact:portMaps>")
        w("        </ipxact:abstractionType>")
        w("      </ipxact:abstractionTypes>")
        if b["name"] == "s_axi":
            w('      <ipxact:slave><ipxact:memoryMapRef memoryMapRef="regs"/></ipxact:slave>')
        elif b["name"] == "m_axi":
            w('      <ipxact:master><ipxact:addressSpaceRef addressSpaceRef="m_axi"/></ipxact:master>')
        else:
            w(f"      <ipxact:{b['mode']}/>")
        w("      <ipxact:parameters>")
        for k, v in b["params"].items():
            w(f'        <ipxact:parameter parameterId={quoteattr(b["name"] + "." + k)} resolve="immediate">')
            w(f"          <ipxact:name>{k}</ipxact:name>")
            w(f"          <ipxact:value>{escape(v)}</ipxact:value>")
            w("        </ipxact:parameter>")
        w("      </ipxact:parameters>")
        w("    </ipxact:busInterface>")
    w("  </ipxact:busInterfaces>")
    unmapped = [p for p, _, _ in ps if bus_of(p)[0] is None]
    if unmapped:
        raise SystemExit("ipxact: wrapper ports in no bus interface: " + ", ".join(unmapped))
    # The AXI4 master's address space: the 32-bit byte address.
    w("  <ipxact:addressSpaces>")
    w("    <ipxact:addressSpace>")
    w("      <ipxact:name>m_axi</ipxact:name>")
    w("      <ipxact:range>4294967296</ipxact:range>")
    w("      <ipxact:width>32</ipxact:width>")
    w("    </ipxact:addressSpace>")
    w("  </ipxact:addressSpaces>")
    # The registers.
    w("  <ipxact:memoryMaps>")
    w("    <ipxact:memoryMap>")
    w("      <ipxact:name>regs</ipxact:name>")
    w("      <ipxact:addressBlock>")
    w("        <ipxact:name>regs</ipxact:name>")
    w("        <ipxact:baseAddress>0</ipxact:baseAddress>")
    w(f"        <ipxact:range>{regs['span']}</ipxact:range>")
    w("        <ipxact:width>32</ipxact:width>")
    w("        <ipxact:usage>register</ipxact:usage>")
    for r in regs["registers"]:
        w("        <ipxact:register>")
        w(f"          <ipxact:name>{r['name']}</ipxact:name>")
        w(f"          <ipxact:description>{escape(r['doc'])}</ipxact:description>")
        w(f"          <ipxact:addressOffset>0x{r['offset']:02X}</ipxact:addressOffset>")
        w("          <ipxact:size>32</ipxact:size>")
        w(f"          <ipxact:access>{ACCESS[r['access']][0]}</ipxact:access>")
        for f in r["fields"]:
            acc, mwv = ACCESS[f["access"]]
            w("          <ipxact:field>")
            w(f"            <ipxact:name>{f['name']}</ipxact:name>")
            w(f"            <ipxact:description>{escape(f['doc'])}</ipxact:description>")
            w(f"            <ipxact:bitOffset>{f['lsb']}</ipxact:bitOffset>")
            w(f"            <ipxact:bitWidth>{f['width']}</ipxact:bitWidth>")
            w(f"            <ipxact:access>{acc}</ipxact:access>")
            if mwv:
                w(f"            <ipxact:modifiedWriteValue>{mwv}</ipxact:modifiedWriteValue>")
            w("          </ipxact:field>")
        w("        </ipxact:register>")
    w("      </ipxact:addressBlock>")
    w("      <ipxact:addressUnitBits>8</ipxact:addressUnitBits>")
    w("    </ipxact:memoryMap>")
    w("  </ipxact:memoryMaps>")
    # The model: the Verilog view and the ports.
    w("  <ipxact:model>")
    w("    <ipxact:views>")
    w("      <ipxact:view>")
    w("        <ipxact:name>rtl</ipxact:name>")
    w("        <ipxact:componentInstantiationRef>verilog_rtl</ipxact:componentInstantiationRef>")
    w("      </ipxact:view>")
    w("    </ipxact:views>")
    w("    <ipxact:instantiations>")
    w("      <ipxact:componentInstantiation>")
    w("        <ipxact:name>verilog_rtl</ipxact:name>")
    w("        <ipxact:language>verilog</ipxact:language>")
    w("        <ipxact:moduleName>mcadsw_axi</ipxact:moduleName>")
    w("        <ipxact:fileSetRef><ipxact:localName>rtl</ipxact:localName></ipxact:fileSetRef>")
    w("      </ipxact:componentInstantiation>")
    w("    </ipxact:instantiations>")
    w("    <ipxact:ports>")
    for p, d, width in ps:
        w("      <ipxact:port>")
        w(f"        <ipxact:name>{p}</ipxact:name>")
        w("        <ipxact:wire>")
        w(f"          <ipxact:direction>{d}</ipxact:direction>")
        if width > 1:
            w(f"          <ipxact:vectors><ipxact:vector><ipxact:left>{width - 1}</ipxact:left>"
              "<ipxact:right>0</ipxact:right></ipxact:vector></ipxact:vectors>")
        w("        </ipxact:wire>")
        w("      </ipxact:port>")
    w("    </ipxact:ports>")
    w("  </ipxact:model>")
    w("  <ipxact:fileSets>")
    w("    <ipxact:fileSet>")
    w("      <ipxact:name>rtl</ipxact:name>")
    for f in files():
        kind = "verilogSource-2001" if f.endswith(".v") else "systemVerilogSource"
        w("      <ipxact:file>")
        w(f"        <ipxact:name>{f}</ipxact:name>")
        w(f"        <ipxact:fileType>{kind}</ipxact:fileType>")
        w("      </ipxact:file>")
    w("      <ipxact:file>")
    w("        <ipxact:name>rtl/mcadsw_assert.svh</ipxact:name>")
    w("        <ipxact:fileType>systemVerilogSource</ipxact:fileType>")
    w("        <ipxact:isIncludeFile>true</ipxact:isIncludeFile>")
    w("      </ipxact:file>")
    w("    </ipxact:fileSet>")
    w("  </ipxact:fileSets>")
    w("  <ipxact:description>MCADSW stereo-depth engine (mini-census adaptive support weight, Chang et al.,"
      " IEEE TCSVT 2010): disparity maps of rectified YUV stereo pairs in frame memory, read and"
      " written through an AXI4 master, programmed through AXI4-Lite registers"
      " (docs/registers.md).</ipxact:description>")
    w("  <ipxact:parameters>")
    for k, v in pkg_values().items():
        w(f'    <ipxact:parameter parameterId="{k}" resolve="immediate" type="int">')
        w(f"      <ipxact:name>{k}</ipxact:name>")
        w(f"      <ipxact:description>{escape(PKG_PARAMS[k])}; set by rtl/mcadsw_pkg.sv</ipxact:description>")
        w(f"      <ipxact:value>{v}</ipxact:value>")
        w("    </ipxact:parameter>")
    w("  </ipxact:parameters>")
    w("</ipxact:component>")
    return "\n".join(lines) + "\n"


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--gen-rtl-pkg", default=str(ROOT / "build" / "bin" / "gen_rtl_pkg"))
    ap.add_argument("--check", action="store_true")
    a = ap.parse_args(argv)
    return write_or_check(OUT, component(regs_json(a.gen_rtl_pkg)), a.check, "`make rtl-pkg`")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
