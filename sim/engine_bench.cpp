// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

#include "engine_bench.hpp"

#include <functional>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

// The harness's parts: the frame's layout in memory, the model's clock and a frame's run,
// the scoreboard, the second simulator's files.
#include "bench_clock.hpp"
#include "frame_layout.hpp"
#include "frame_score.hpp"
#include "icarus_dump.hpp"
#include "mcadsw/regs.hpp"

namespace mcadsw::sim {

using bench::dump_after;
using bench::dump_before;
using bench::Engine;
using bench::frame_limit;
using bench::Layout;
using bench::load_frame;
using bench::program;
using bench::rect_reference;
using bench::RectRef;
using bench::run_frame;
using bench::score;
using bench::StartAgain;

uint64_t frame_bytes(int w, int h, const EngineOptions& opt) {
  const Layout lay(w, h, opt.frame.origin, opt);
  return lay.total - lay.origin;
}

EngineResult run_engine(const YuvImage& left, const YuvImage& right, const Config& cfg,
                        const EngineOptions& opt) {
  const Layout lay(left.width(), left.height(), opt.frame.origin, opt);
  const int W = lay.width, H = lay.height;  // with rectification: the meshes' frame
  const std::optional<RectRef> rr = rect_reference(left, right, opt);
  MemoryModel mem(lay.origin, lay.total, opt.memory.latency);
  load_frame(mem, lay, left, right, opt);
  const Plane* base_valid = rr ? &rr->base_valid(opt.frame.right) : nullptr;
  mem.set_regions(lay.regions(base_valid, rr ? &rr->view[1].valid : nullptr));

  EngineResult r;
  r.width = W;
  r.height = H;
  r.disparities = cfg.disparities;
  const RawConfig raw = lay.raw_config(cfg.disparities);
  if (!opt.run.dump_dir.empty()) dump_before(opt.run.dump_dir, mem, raw, cfg.table);
  {
    Engine e(mem, opt);
    program(e, raw, cfg.table);
    run_frame(e, r, frame_limit(W, H, opt), opt.run.progress);
  }
  if (!opt.run.dump_dir.empty()) dump_after(opt.run.dump_dir, mem, lay, r);
  if (rr) score(mem, lay, rr->view[0].image, rr->view[1].image, cfg, opt, r, &*rr);
  else score(mem, lay, left, right, cfg, opt, r);
  return r;
}

std::vector<EngineResult> run_frames(const std::vector<Frame>& frames, const EngineOptions& opt,
                                     FaultSpec fault) {
  std::vector<Layout> lays;
  std::vector<std::optional<RectRef>> rrs;
  uint64_t at = opt.frame.origin;
  for (const Frame& f : frames) {
    lays.emplace_back(f.left.width(), f.left.height(), at, opt);
    rrs.push_back(rect_reference(f.left, f.right, opt));
    at = lays.back().total;
  }
  MemoryModel mem(opt.frame.origin, at, opt.memory.latency);
  for (size_t k = 0; k < frames.size(); ++k) load_frame(mem, lays[k], frames[k].left, frames[k].right, opt);

  std::vector<EngineResult> results(frames.size());
  Engine e(mem, opt);
  for (size_t k = 0; k < frames.size(); ++k) {
    const Frame& f = frames[k];
    const Layout& lay = lays[k];
    const std::optional<RectRef>& rr = rrs[k];
    const Plane* base_valid = rr ? &rr->base_valid(opt.frame.right) : nullptr;
    const int W = lay.width, H = lay.height;
    EngineResult& r = results[k];
    r.width = W;
    r.height = H;
    r.disparities = f.cfg.disparities;
    // Only this frame's planes may be touched while it runs.
    mem.set_regions(lay.regions(base_valid, rr ? &rr->view[1].valid : nullptr));
    program(e, lay.raw_config(f.cfg.disparities), f.cfg.table);
    if (k == 0 && fault.kind == Fault::kResetMidFrame) {
      EngineResult aborted;
      run_frame(e, aborted, fault.at_cycle, false);
      if (!aborted.timed_out) throw std::runtime_error("frame 0 finished before the reset was due");
      e.reset();
      // The aborted frame's writes are not this frame's: checks start again.
      mem.set_regions(lay.regions(base_valid, rr ? &rr->view[1].valid : nullptr));
      program(e, lay.raw_config(f.cfg.disparities), f.cfg.table);
    }
    StartAgain again;
    if (fault.kind == Fault::kStartWhileBusy) again = {fault.at_cycle, fault.other, &f.cfg.table};
    if (fault.kind == Fault::kAbort && k == 0) again = {fault.at_cycle, {}, nullptr, true};
    run_frame(e, r, frame_limit(W, H, opt), opt.run.progress, again);
    if (rr) score(mem, lay, rr->view[0].image, rr->view[1].image, f.cfg, opt, r, &*rr);
    else score(mem, lay, f.left, f.right, f.cfg, opt, r);
  }
  return results;
}

MemoryModel::Violations with_registers(const std::function<void(RegisterPort&)>& script,
                                       const EngineOptions& opt) {
  MemoryModel mem(1 << 20, opt.memory.latency);
  mem.set_regions({});
  {
    Engine e(mem, opt);
    RegisterPort port = e.dut().raw_registers([&e](long n) {
      for (long i = 0; i < n; ++i) e.cycle();
    });
    script(port);
  }
  return mem.violations();
}

EngineResult run_raw(const RawConfig& raw, const EngineOptions& opt, long cycles,
                     const std::vector<std::pair<uint32_t, std::vector<uint8_t>>>& readable) {
  MemoryModel mem(1 << 20, opt.memory.latency);
  MemoryModel::Regions regions;  // a rejected configuration must touch nothing
  for (const auto& [base, bytes] : readable) {
    for (size_t i = 0; i < bytes.size(); ++i) mem.byte(uint64_t(base) + i) = bytes[i];
    MemoryModel::Area a;
    a.name = "readable range";
    a.base = base;
    a.width = int(bytes.size());
    a.height = 1;
    a.stride = uint32_t(bytes.size());
    regions.areas.push_back(a);
  }
  mem.set_regions(regions);
  EngineResult r;
  {
    Engine e(mem, opt);
    program(e, raw, make_weight_table(kDefaultGamma));
    run_frame(e, r, cycles, false);
    // A register read takes a few cycles (AXI4-Lite) or none (engine core): idle
    // cycles of 1, 0 and 2 in between make the gaps of different parity, so a
    // status that alternates from cycle to cycle is seen.
    const uint32_t first = e.dut().registers().read(regs::kStatus);
    for (const int idle : {1, 0, 2}) {
      for (int i = 0; i < idle; ++i) e.cycle();
      r.status_changes += e.dut().registers().read(regs::kStatus) != first;
    }
  }
  r.bus = mem.violations();
  return r;
}

}  // namespace mcadsw::sim