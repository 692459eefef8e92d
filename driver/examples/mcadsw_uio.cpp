// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// A Linux user of the MCADSW driver: the register block mapped from a UIO device
// (/dev/uioN, map 0) or from /dev/mem at a physical address. Prints the block's
// identity and status; with --frame, runs one raw frame whose six input planes
// (left Y, U, V, right Y, U, V; width rounded up to 4 bytes a row) lie one after
// another from IN, the disparity plane at OUT, and prints status and counters.
//
//   mcadsw_uio /dev/uio0 [--frame W H D IN OUT]
//   mcadsw_uio /dev/mem 0x43c00000 [--frame W H D IN OUT]
//
// The frame's planes must be in memory the engine's AXI4 master reaches (for
// example a reserved-memory region or a CMA buffer the application filled).
#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "mcadsw/driver.hpp"

namespace {

class MappedRegisters : public mcadsw::driver::RegisterBus {
 public:
  explicit MappedRegisters(volatile uint32_t* base) : base_(base) {}
  uint32_t read(uint32_t offset) override { return base_[offset / 4]; }
  void write(uint32_t offset, uint32_t value) override { base_[offset / 4] = value; }

 private:
  volatile uint32_t* base_;
};

uint32_t number(const char* s) { return uint32_t(std::strtoul(s, nullptr, 0)); }

int usage() {
  std::fprintf(stderr,
               "usage: mcadsw_uio /dev/uioN [--frame W H D IN OUT]\n"
               "       mcadsw_uio /dev/mem PHYS_ADDR [--frame W H D IN OUT]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage();
  const std::string dev = argv[1];
  int arg = 2;
  off_t phys = 0;
  if (dev == "/dev/mem") {
    if (argc < 3) return usage();
    phys = off_t(std::strtoull(argv[2], nullptr, 0));
    arg = 3;
  }
  const int fd = open(dev.c_str(), O_RDWR | O_SYNC);
  if (fd < 0) {
    std::fprintf(stderr, "mcadsw_uio: cannot open %s: %s\n", dev.c_str(), std::strerror(errno));
    return 1;
  }
  void* map = mmap(nullptr, MCADSW_REG_SPAN, PROT_READ | PROT_WRITE, MAP_SHARED, fd, phys);
  if (map == MAP_FAILED) {
    std::fprintf(stderr, "mcadsw_uio: cannot map %s: %s\n", dev.c_str(), std::strerror(errno));
    close(fd);
    return 1;
  }
  MappedRegisters bus(static_cast<volatile uint32_t*>(map));
  mcadsw::driver::Engine engine(bus);
  const mcadsw::driver::Identity id = engine.identify();
  std::printf("id 0x%08x, register map %d.%d, DMAX %d, PAR %d%s\n", unsigned(id.id), id.version_major,
              id.version_minor, id.dmax, id.par, id.compatible() ? "" : " (not a block this driver knows)");
  int rc = id.compatible() ? 0 : 1;
  if (rc == 0 && arg + 6 <= argc && std::string(argv[arg]) == "--frame") {
    mcadsw::driver::FrameConfig c;
    c.width = int(number(argv[arg + 1]));
    c.height = int(number(argv[arg + 2]));
    c.disparities = int(number(argv[arg + 3]));
    c.stride = (uint32_t(c.width) + 3) & ~3u;
    const uint32_t plane = c.stride * uint32_t(c.height), in = number(argv[arg + 4]);
    c.base_ly = in;
    c.base_lu = in + plane;
    c.base_lv = in + 2 * plane;
    c.base_ry = in + 3 * plane;
    c.base_ru = in + 4 * plane;
    c.base_rv = in + 5 * plane;
    c.base_out = number(argv[arg + 5]);
    c.out_stride = c.stride;
    c.thresholds = {2, 6, 10, 16, 24, 40, 64};  // an example table: docs/algorithm.md has the tuned one
    engine.configure(c);
    engine.start();
    const mcadsw::driver::Status st = engine.wait(100000000L, [] { usleep(100); });
    const mcadsw::driver::Counters n = engine.counters();
    if (!st.done) {
      std::printf("frame not done (busy %d)\n", st.busy);
      rc = 1;
    } else if (st.error) {
      std::printf("frame rejected or ended: error %d: %s\n", st.error_code,
                  mcadsw::driver::error_text(st.error_code));
      rc = 1;
    } else {
      std::printf("frame done: %u cycles, %u words read, %u written, %u stall cycles\n",
                  unsigned(n.cycles), unsigned(n.words_read), unsigned(n.words_written),
                  unsigned(n.stalls));
    }
  } else if (arg < argc) {
    munmap(map, MCADSW_REG_SPAN);
    close(fd);
    return usage();
  } else {
    const mcadsw::driver::Status st = engine.status();
    std::printf("busy %d, done %d, error %d (code %d: %s)\n", st.busy, st.done, st.error, st.error_code,
                mcadsw::driver::error_text(st.error_code));
  }
  munmap(map, MCADSW_REG_SPAN);
  close(fd);
  return rc;
}
