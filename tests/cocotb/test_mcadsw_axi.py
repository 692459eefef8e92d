# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""cocotb test of the vendor-tool wrapper mcadsw_axi (rtl/mcadsw_axi.v) under Alex
Forencich's AXI models (cocotbext-axi): AxiRam as the frame memory on m_axi, AxiLiteMaster
as the CPU on s_axi, random back-pressure on every channel of both models.

One frame a run, from the files `mcadsw_sim --dump DIR` wrote (tests/cocotb/run.py makes
them and runs this module once per DIR, environment MCADSW_DUMP=DIR):
  mem.hex                  the frame memory's words before the frame (loaded into AxiRam)
  regs.txt                 the register writes the C++ driver makes for the frame, "offset
                           value" in hex, the last one CTRL.START (replayed through the
                           AXI4-Lite master, in order)
  verilator_out.hex        the output planes' words after the frame, which mcadsw_sim has
                           compared byte for byte with the C++ reference model's (it exits 1
                           otherwise)
  verilator_regions.txt    where those words are (base, bytes)
  verilator_counters.txt   words read and written (the cycles depend on the memory timing)
The test waits for the interrupt, reads STATUS (DONE, not ERROR, code 0), acknowledges it
(the interrupt must fall), reads the counters (words read and written equal the Verilator
run's) and compares every byte of the output planes in AxiRam with the expected words; the
first difference is reported with its plane, address and both values.
"""
import logging
import os
import pathlib
import random

import cocotb
from cocotb.clock import Clock
from cocotb.triggers import ClockCycles, RisingEdge, with_timeout
from cocotbext.axi import AxiBus, AxiLiteBus, AxiLiteMaster, AxiRam

# Register offsets: from the C header the register map generates (one source), read here
# rather than typed again.
HEADER = pathlib.Path(__file__).resolve().parents[2] / "driver" / "include" / "mcadsw" / "mcadsw_regs.h"


def reg_offsets():
    out = {}
    for line in HEADER.read_text().splitlines():
        parts = line.split()
        if len(parts) >= 3 and parts[0] == "#define" and parts[1].startswith("MCADSW_REG_"):
            out[parts[1][len("MCADSW_REG_"):]] = int(parts[2].strip("()uU"), 0)
    return out


def field(name):
    """(lsb, mask) of MCADSW_<name>_LSB / _MASK in the C header."""
    vals = {}
    for line in HEADER.read_text().splitlines():
        parts = line.split()
        if len(parts) >= 3 and parts[0] == "#define" and parts[1] in (f"MCADSW_{name}_LSB", f"MCADSW_{name}_WIDTH"):
            vals[parts[1].rsplit("_", 1)[1]] = int(parts[2].strip("()uU"), 0)
    return vals["LSB"], (1 << vals["WIDTH"]) - 1


def pause(rng, p):
    """A pause generator: each cycle True (hold the channel) with probability p."""
    while True:
        yield rng.random() < p


def attach(dut, dump):
    """The models on the wrapper: an AxiRam on m_axi holding DUMP's memory image (mem.hex) and
    an AxiLiteMaster on s_axi, both logging warnings only (they log every transaction at INFO,
    and a frame has thousands); aclk started (100 MHz). Returns (ram, cpu)."""
    words = [int(w, 16) for w in (dump / "mem.hex").read_text().split()]
    size = 1 << max(12, (4 * len(words) - 1).bit_length())
    ram = AxiRam(AxiBus.from_prefix(dut, "m_axi"), dut.aclk, dut.aresetn, reset_active_level=False, size=size)
    ram.write(0, b"".join(w.to_bytes(4, "little") for w in words))
    cpu = AxiLiteMaster(AxiLiteBus.from_prefix(dut, "s_axi"), dut.aclk, dut.aresetn, reset_active_level=False)
    for m in (ram.write_if, ram.read_if, cpu.write_if, cpu.read_if):
        m.log.setLevel(logging.WARNING)
    cocotb.start_soon(Clock(dut.aclk, 10, unit="ns").start())
    return ram, cpu


async def reset(dut):
    dut.aresetn.value = 0
    await ClockCycles(dut.aclk, 5)
    dut.aresetn.value = 1
    await ClockCycles(dut.aclk, 2)


def register_writes(dump):
    """DUMP's regs.txt: the driver's register writes, (offset, value), CTRL.START last."""
    return [tuple(int(x, 16) for x in line.split()) for line in (dump / "regs.txt").read_text().splitlines()]


@cocotb.test()
async def frame_through_axi_models(dut):
    dump = pathlib.Path(os.environ["MCADSW_DUMP"])
    seed = int(os.environ.get("MCADSW_SEED", "1"))
    busy_p = float(os.environ.get("MCADSW_PAUSE", "0.3"))
    rng = random.Random(seed)
    regs = reg_offsets()

    ram, cpu = attach(dut, dump)
    # Random back-pressure: the memory's AWREADY, WREADY, ARREADY held low and its BVALID,
    # RVALID delayed; the CPU's BREADY and RREADY held low (and its requests delayed).
    for i, ch in enumerate([ram.write_if.aw_channel, ram.write_if.w_channel, ram.write_if.b_channel,
                            ram.read_if.ar_channel, ram.read_if.r_channel,
                            cpu.write_if.aw_channel, cpu.write_if.w_channel, cpu.write_if.b_channel,
                            cpu.read_if.ar_channel, cpu.read_if.r_channel]):
        ch.set_pause_generator(pause(random.Random(seed * 100 + i), busy_p))

    await reset(dut)
    assert dut.interrupt.value == 0, "interrupt high after reset"
    ident = (await cpu.read_dword(regs["ID"]))
    assert ident == 0x4D434144, f"ID reads 0x{ident:08X}, not 0x4D434144"

    # The driver's writes, CTRL.START last.
    for off, val in register_writes(dump):
        await cpu.write_dword(off, val)
    counters = dict(zip(*[iter((dump / "verilator_counters.txt").read_text().split())] * 2))
    limit = 20 * int(counters["cycles"]) + 20000  # back-pressure slows the frame, never 20x
    await with_timeout(RisingEdge(dut.interrupt), limit * 10, "ns")

    status = await cpu.read_dword(regs["STATUS"])
    done_lsb, _ = field("STATUS_DONE")
    err_lsb, _ = field("STATUS_ERROR")
    code_lsb, code_mask = field("STATUS_ERROR_CODE")
    code = (status >> code_lsb) & code_mask
    assert (status >> done_lsb) & 1 and not (status >> err_lsb) & 1 and code == 0, \
        f"STATUS 0x{status:08X} after the interrupt: DONE, no ERROR, code 0 expected (code {code})"
    await cpu.write_dword(regs["STATUS"], (1 << done_lsb))
    await ClockCycles(dut.aclk, 2)
    assert dut.interrupt.value == 0, "interrupt still high after STATUS.DONE was cleared"
    cycles = await cpu.read_dword(regs["CYCLES"])
    got_rd = await cpu.read_dword(regs["WORDS_READ"])
    got_wr = await cpu.read_dword(regs["WORDS_WRITTEN"])
    stalls = await cpu.read_dword(regs["STALLS"])
    assert (got_rd, got_wr) == (int(counters["words_read"]), int(counters["words_written"])), \
        f"words read, written {got_rd}, {got_wr}; the Verilator run {counters['words_read']}, {counters['words_written']}"

    expected = [int(w, 16) for w in (dump / "verilator_out.hex").read_text().split()]
    at = 0
    for plane, line in enumerate((dump / "verilator_regions.txt").read_text().splitlines()):
        base_hex, nbytes = line.split()
        base, nbytes = int(base_hex, 16), int(nbytes)
        want = b"".join(w.to_bytes(4, "little") for w in expected[at:at + nbytes // 4])
        at += nbytes // 4
        got = ram.read(base, nbytes)
        if got != want:
            i = next(k for k in range(nbytes) if got[k] != want[k])
            raise AssertionError(f"plane {plane} (base 0x{base:X}): first difference at byte {i} "
                                 f"(address 0x{base + i:X}): AxiRam 0x{got[i]:02X}, reference 0x{want[i]:02X}")
    assert at == len(expected), "verilator_regions.txt does not cover verilator_out.hex"
    dut._log.info(f"{dump.name}: {len(expected) * 4} output bytes equal the reference's; {cycles} cycles "
                  f"({counters['cycles']} without back-pressure), {stalls} stalled, words read {got_rd}, "
                  f"written {got_wr}")
