# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""The datasheet's timing diagrams, recorded from a simulation of mcadsw_axi (not drawn):
cocotb samples the wrapper's ports (and the SoC's busy flag) every cycle, mid-cycle, while
the C++ driver's register writes for a small column-tiled frame are replayed through
cocotbext-axi's AxiLiteMaster on an AxiRam without back-pressure, then while a start with
DISP = 0 is rejected. It writes WaveJSON (WaveDrom's input) into MCADSW_WAVES:
  start_irq.json    CTRL.START written, busy, ... the frame's end: busy falls, the interrupt
  read_burst.json   the first AXI4 read burst of more than one beat
  error_start.json  the rejected start: DONE and ERROR at once, the interrupt, code 3
flow/datasheet.py renders them to SVG with wavedrom. Run by tests/cocotb/run.py --waves
(make docs-waves).
"""
import json
import os
import pathlib

import cocotb
from cocotb.triggers import ClockCycles, FallingEdge, RisingEdge, with_timeout

from test_mcadsw_axi import attach, field, reg_offsets, register_writes, reset

ONE_BIT = ["s_axi_awvalid", "s_axi_awready", "s_axi_wvalid", "s_axi_wready", "s_axi_bvalid",
           "m_axi_arvalid", "m_axi_arready", "m_axi_rvalid", "m_axi_rready", "m_axi_rlast", "interrupt"]
BUSES = ["s_axi_awaddr", "s_axi_wdata", "m_axi_araddr", "m_axi_arlen", "m_axi_rdata"]


def value(sig):
    """A signal's value as an int, None when any bit is X or Z (drawn as x)."""
    v = sig.value
    return int(v) if v.is_resolvable else None


class Recorder:
    """Every signal's value at each falling edge of aclk, from start() to stop()."""

    def __init__(self, dut):
        self.dut = dut
        self.rows = []
        self.on = False

    async def run(self):
        while True:
            await FallingEdge(self.dut.aclk)
            if self.on:
                row = {n: value(getattr(self.dut, n)) for n in ONE_BIT + BUSES}
                row["busy"] = value(self.dut.u_top.busy)
                self.rows.append(row)


def wave(title, rows, windows, signals):
    """WaveJSON of the rows of each window (a, b), the windows joined by WaveDrom's gap '|'.
    signals: (label, row key, kind) with kind bit, hex or dec."""
    def lane(sig, kind):
        parts, data = [], []
        for s, e in windows:
            w, prev = "", None
            for i in range(s, e):
                v = rows[i][sig]
                if v == prev:
                    w += "."
                elif v is None:
                    w += "x"
                elif kind == "bit":
                    w += str(v)
                else:
                    w += "="
                    data.append(f"{v:x}" if kind == "hex" else str(v))
                prev = v
            parts.append(w)
        return "|".join(parts), data

    out = {"signal": [{"name": "aclk", "wave": "|".join("p" + "." * (e - s - 1) for s, e in windows)}],
           "head": {"text": title}}
    for label, sig, kind in signals:
        w, data = lane(sig, kind)
        out["signal"].append({"name": label, "wave": w, **({"data": data} if data else {})})
    return out


@cocotb.test()
async def record_waves(dut):
    dump = pathlib.Path(os.environ["MCADSW_DUMP"])
    dest = pathlib.Path(os.environ["MCADSW_WAVES"])
    dest.mkdir(parents=True, exist_ok=True)
    regs = reg_offsets()
    _, cpu = attach(dut, dump)
    rec = Recorder(dut)
    cocotb.start_soon(rec.run())
    await reset(dut)

    writes = register_writes(dump)
    for off, val in writes[:-1]:
        await cpu.write_dword(off, val)
    rec.on = True
    await ClockCycles(dut.aclk, 2)
    start_at = len(rec.rows)
    await cpu.write_dword(*writes[-1])  # CTRL.START
    await with_timeout(RisingEdge(dut.interrupt), 1, "ms")
    await ClockCycles(dut.aclk, 4)
    rec.on = False
    rows = rec.rows
    irq = next(i for i, r in enumerate(rows) if r["interrupt"])
    start = next(i for i in range(start_at, len(rows)) if rows[i]["s_axi_awvalid"])
    lite = [("AWVALID", "s_axi_awvalid", "bit"), ("AWREADY", "s_axi_awready", "bit"),
            ("AWADDR", "s_axi_awaddr", "hex"), ("WVALID", "s_axi_wvalid", "bit"),
            ("WDATA", "s_axi_wdata", "hex"), ("BVALID", "s_axi_bvalid", "bit"),
            ("busy (STATUS.BUSY)", "busy", "bit"), ("ARVALID", "m_axi_arvalid", "bit"),
            ("interrupt", "interrupt", "bit")]
    (dest / "start_irq.json").write_text(json.dumps(
        wave("CTRL.START written (AXI4-Lite), the frame running, its end: busy falls, interrupt rises",
             rows, [(max(0, start - 2), start + 12), (irq - 8, irq + 3)], lite), indent=1) + "\n")
    burst = next(i for i, r in enumerate(rows) if r["m_axi_arvalid"] and r["m_axi_arready"] and r["m_axi_arlen"] > 0)
    last = next(i for i in range(burst, len(rows)) if rows[i]["m_axi_rvalid"] and rows[i]["m_axi_rready"] and rows[i]["m_axi_rlast"])
    axi = [("ARVALID", "m_axi_arvalid", "bit"), ("ARREADY", "m_axi_arready", "bit"),
           ("ARADDR", "m_axi_araddr", "hex"), ("ARLEN", "m_axi_arlen", "dec"),
           ("RVALID", "m_axi_rvalid", "bit"), ("RREADY", "m_axi_rready", "bit"),
           ("RDATA", "m_axi_rdata", "hex"), ("RLAST", "m_axi_rlast", "bit")]
    (dest / "read_burst.json").write_text(json.dumps(
        wave(f"An AXI4 read burst of {rows[burst]['m_axi_arlen'] + 1} beats (column-tiled input planes)",
             rows, [(burst - 2, last + 3)], axi), indent=1) + "\n")

    # A rejected start: DISP = 0. The interrupt is cleared first.
    done_lsb, _ = field("STATUS_DONE")
    await cpu.write_dword(regs["STATUS"], 1 << done_lsb)
    await cpu.write_dword(regs["DISP"], 0)
    rec.rows = []
    rec.on = True
    await ClockCycles(dut.aclk, 2)
    await cpu.write_dword(*writes[-1])
    await with_timeout(RisingEdge(dut.interrupt), 10, "us")
    await ClockCycles(dut.aclk, 3)
    rec.on = False
    rows = rec.rows
    status = await cpu.read_dword(regs["STATUS"])
    code_lsb, code_mask = field("STATUS_ERROR_CODE")
    err_lsb, _ = field("STATUS_ERROR")
    assert (status >> err_lsb) & 1 and (status >> code_lsb) & code_mask == 3, f"STATUS 0x{status:08X}"
    (dest / "error_start.json").write_text(json.dumps(
        wave("A start rejected (DISP = 0): DONE and ERROR (code 3) with no frame, the interrupt",
             rows, [(0, len(rows))], lite[:6] + [("busy (STATUS.BUSY)", "busy", "bit"),
                                             ("interrupt", "interrupt", "bit")]), indent=1) + "\n")
