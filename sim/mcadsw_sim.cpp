// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// mcadsw_sim: runs the Verilated engine on one stereo pair in a modelled
// 32-bit external memory and compares every disparity with the reference.
//   mcadsw_sim LEFT RIGHT -d D [--gamma G] [--latency N | --random-latency SEED]
//              [--name NAME] [--gt GT --scale S --masks DIR] [--out OUT.png]
//              [--json FILE] [--waves FILE.fst] [--crop X,Y,W,H] [--stride N] [--dump DIR]
//              [--subpixel] [--right] [--out-stride N] [--tiled] [--tile-stride N]
//              [--origin ADDR] [--packed] [--record-ports FILE]
//              [--calib CALIB.yml | --mesh MESH.bin] [--step S]
// Exit status: 0 bit-exact, 1 mismatch / timeout / harness error, 2 usage.
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include <unistd.h>

#include "engine_bench.hpp"
#include "mcadsw/eval.hpp"
#include "mcadsw/image_io.hpp"
#include "mcadsw/parse.hpp"
#include "mcadsw/rectify.hpp"
#include "mcadsw/regs.hpp"
#include <opencv2/imgcodecs.hpp>

namespace {

const char* kUsage =
    "usage: mcadsw_sim LEFT RIGHT -d D [--gamma G] [--latency N | --random-latency SEED]\n"
    "                  [--name NAME] [--gt GT.png --scale S --masks DIR] [--out OUT.png]\n"
    "                  [--json FILE] [--waves FILE.fst] [--crop X,Y,W,H] [--stride N] [--dump DIR]\n"
    "                  [--subpixel] [--right] [--lr [-T T]] [--out-stride N] [--ar-interval N]\n"
    "                  [--tiled] [--tile-stride N] [--origin ADDR] [--packed] [--record-ports FILE]\n"
    "                  [--calib CALIB.yml | --mesh MESH.bin] [--step S]\n"
    "  --latency N     AXI4 memory: N wait states before each burst's first R beat and each B\n"
    "  --random-latency SEED  AXI4 memory: 0..8 more wait states a burst, READY 70 % of the time\n"
    "  --ar-interval N AXI4 memory: an AR accepted at most once in N clocks (default 1)\n"
    "  --crop X,Y,W,H  run on that region of both images (and of the ground truth)\n"
    "  --stride N      bytes per row of the input planes in memory: a multiple of 4, at least\n"
    "                  the width (default: the width rounded up to 4); N, ADDR: decimal or 0x hex\n"
    "  --origin ADDR   the frame's memory from ADDR (a multiple of 4096; default 0): the planes\n"
    "                  after a 4 KiB guard, anywhere in the 32-bit space\n"
    "  --packed        the planes back to back at 4-byte alignment (default: 4 KiB boundaries)\n"
    "  --tiled         input planes column-tiled (docs/memory_map.md): a column of 4 pixels,\n"
    "                  all rows, is consecutive words, so strip words are read in bursts\n"
    "  --tile-stride N tiled: bytes from one 4-pixel column to the next, a multiple of 4, at\n"
    "                  least 4 x the height (default 4 x the height); implies --tiled\n"
    "  --subpixel      sub-pixel mode: 16-bit output, 16 x disparity (docs/algorithm.md 12.6);\n"
    "                  --out writes a 16-bit PNG\n"
    "  --right         the right view as base: the right-reference map dR (docs/algorithm.md\n"
    "                  12.1; reads the right view's U and V); --gt then needs the right view's\n"
    "                  ground truth\n"
    "  --lr            LR mode (docs/algorithm.md 12.2-12.5): left map, right map, left-right\n"
    "                  check, fill and 3x3 median; --out writes the filtered map; the mask\n"
    "                  plane is compared too (not with --right)\n"
    "  -T T            LR tolerance of the check, 0..63 (default 1)\n"
    "  --out-stride N  bytes per row of the output plane: a multiple of 4, at least the width\n"
    "                  (2 x the width with --subpixel); default: that rounded up to 4\n"
    "  --dump DIR      memory image, configuration and result for tests/icarus/run.sh\n"
    "  --record-ports FILE  the engine core's ports every cycle (mcadsw_sim_core only; make\n"
    "                  power replays them on the netlist: sim/activity/netlist_activity.cpp)\n"
    "  --calib CALIB.yml  the engine rectifies first (docs/algorithm.md 13, register map 1.2):\n"
    "                  LEFT and RIGHT are raw camera views of the calibration's image size\n"
    "                  (OpenCV YAML or XML: K1 D1 R1 P1 K2 D2 R2 P2, or K1 D1 K2 D2 R T), the\n"
    "                  rectified frame is of that size; the rectified planes and validity\n"
    "                  bitmaps are compared too, and an invalid base pixel's output is the\n"
    "                  invalid code (255; 0xFFFF with --subpixel); --gt counts only valid pixels\n"
    "  --mesh MESH.bin the same from a mesh memory image (mcadsw mesh: left, then right),\n"
    "                  for a rectified frame of the raw views' size\n"
    "  --step S        the mesh step with --calib or --mesh: 8, 16 or 32 (default 16)\n"
    "                  With rectification, --crop X,Y,W,H takes that region of the rectified\n"
    "                  frame (X and Y multiples of S; the raw views stay whole). With --lr,\n"
    "                  dR is 255 and dL flagged at invalid pixels before the post stage\n"
    "                  (compared too), and the output's invalid left pixels get the code\n";

// The clock of the waves and of constraints/mcadsw.sdc: the paper's 95 MHz (Table III).
constexpr double kClockMHz = 1e6 / double(mcadsw::sim::kClockPeriodPs);

// The part of a mesh over the region (x, y, w, h) of its frame, x and y multiples of
// its step: the same nodes, so every pixel's source position is the whole frame's.
mcadsw::Mesh crop_mesh(const mcadsw::Mesh& m, const cv::Rect& r) {
  mcadsw::Mesh c = mcadsw::make_mesh(r.width, r.height, m.step_log2);
  const int i0 = r.x >> m.step_log2, j0 = r.y >> m.step_log2;
  for (int j = 0; j < c.ny; ++j)
    for (int i = 0; i < c.nx; ++i) {
      const size_t from = size_t(j0 + j) * size_t(m.nx) + size_t(i0 + i), to = size_t(j) * size_t(c.nx) + size_t(i);
      c.u[to] = m.u[from];
      c.v[to] = m.v[from];
    }
  mcadsw::check_mesh(c);
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  // A failing RTL assertion prints on stdout and aborts: keep stdout line-buffered
  // so its message is not lost in a pipe's buffer.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  std::string left, right, name, gt, masks, out, json, waves, calib, mesh;
  int step = 0;  // --step: 0 not given
  cv::Rect crop;
  constexpr int kNoD = -1000000;
  int d = kNoD;
  double gamma = mcadsw::kDefaultGamma, scale = 0;
  mcadsw::sim::EngineOptions opt;
  opt.run.progress = true;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      auto val = [&]() -> std::string {
        if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
        return argv[++i];
      };
      // A row stride in bytes: a multiple of 4, not 0 (the planes must still fit
      // in the 32-bit space: the harness's layout checks that).
      auto stride = [](const std::string& text, const std::string& what) {
        const uint32_t v = mcadsw::parse_u32(text, what);
        if (v < 4 || v % 4 != 0)
          throw std::invalid_argument(what + " " + std::to_string(v) + " must be a multiple of 4, at least 4");
        return v;
      };
      if (a == "-d") d = int(mcadsw::parse_long(val(), "D"));
      else if (a == "--gamma") gamma = mcadsw::parse_double(val(), "gamma");
      else if (a == "--latency") opt.memory.latency.fixed = int(mcadsw::parse_long(val(), "latency"));
      else if (a == "--ar-interval") opt.memory.axi_ar_interval = int(mcadsw::parse_long(val(), "AR interval"));
      else if (a == "--random-latency") {
        opt.memory.latency.random = true;
        opt.memory.latency.seed = uint32_t(mcadsw::parse_long(val(), "seed"));
      } else if (a == "--name") name = val();
      else if (a == "--gt") gt = val();
      else if (a == "--scale") scale = mcadsw::parse_double(val(), "scale");
      else if (a == "--masks") masks = val();
      else if (a == "--out") out = val();
      else if (a == "--json") json = val();
      else if (a == "--waves") waves = val();
      else if (a == "--dump") opt.run.dump_dir = val();
      else if (a == "--record-ports") opt.run.record_ports = val();
      else if (a == "--stride") opt.frame.stride = stride(val(), "stride");
      else if (a == "--tiled") opt.frame.tiled = true;
      else if (a == "--origin") opt.frame.origin = mcadsw::parse_u32(val(), "origin");
      else if (a == "--packed") opt.frame.packed = true;
      else if (a == "--tile-stride") {
        opt.frame.tile_stride = stride(val(), "tile stride");
        opt.frame.tiled = true;
      }
      else if (a == "--subpixel") opt.frame.subpixel = true;
      else if (a == "--right") opt.frame.right = true;
      else if (a == "--lr") opt.frame.lr = true;
      else if (a == "-T") opt.frame.lr_tolerance = int(mcadsw::parse_long(val(), "LR tolerance"));
      else if (a == "--out-stride") opt.frame.out_stride = stride(val(), "output stride");
      else if (a == "--calib") calib = val();
      else if (a == "--mesh") mesh = val();
      else if (a == "--step") {
        step = int(mcadsw::parse_long(val(), "step"));
        if (step != 8 && step != 16 && step != 32) throw std::invalid_argument("--step must be 8, 16 or 32");
      }
      else if (a == "--crop") {
        if (std::sscanf(val().c_str(), "%d,%d,%d,%d", &crop.x, &crop.y, &crop.width, &crop.height) != 4)
          throw std::invalid_argument("--crop takes X,Y,W,H");
      }
      else if (a == "-h" || a == "--help") {
        std::cout << kUsage;
        return 0;
      } else if (!a.empty() && a[0] == '-') throw std::invalid_argument("unknown option " + a);
      else if (left.empty()) left = a;
      else if (right.empty()) right = a;
      else throw std::invalid_argument("unexpected argument " + a);
    }
    if (left.empty() || right.empty()) throw std::invalid_argument("need LEFT and RIGHT images");
    if (d == kNoD) throw std::invalid_argument("need -d D");
    if (d < 1 || d > mcadsw::kDmax)
      throw std::invalid_argument("D = " + std::to_string(d) + " out of range 1.." +
                                  std::to_string(mcadsw::kDmax));
    if (opt.memory.latency.fixed < 0) throw std::invalid_argument("latency must not be negative");
    if (opt.memory.axi_ar_interval < 1) throw std::invalid_argument("--ar-interval must be at least 1");
    if (opt.frame.lr && opt.frame.right) throw std::invalid_argument("--lr and --right do not combine");
    mcadsw::check_lr_tolerance(opt.frame.lr_tolerance);
    if (!gt.empty() && (masks.empty() || !(scale > 0)))
      throw std::invalid_argument("--gt needs --scale S > 0 and --masks DIR");
    if (!calib.empty() && !mesh.empty()) throw std::invalid_argument("--calib and --mesh do not combine");
    if ((!calib.empty() || !mesh.empty()) && !mcadsw::kRect)
      throw std::invalid_argument("--calib / --mesh: this build has no rectifier (MCADSW_RECT=OFF: the engine "
                                  "rejects RECT_CTRL.ENABLE with code 24); rectified frames need a build with it");
    if (step && calib.empty() && mesh.empty()) throw std::invalid_argument("--step needs --calib or --mesh");
    if (!step) step = 16;
    if ((!calib.empty() || !mesh.empty()) && crop.area() > 0 && (crop.x % step != 0 || crop.y % step != 0))
      throw std::invalid_argument("--crop with rectification: X and Y must be multiples of the mesh step " +
                                  std::to_string(step) + " (a region of the rectified frame on whole mesh cells)");
  } catch (const std::exception& e) {
    std::cerr << "mcadsw_sim: " << e.what() << "\n" << kUsage;
    return 2;
  }
  if (!waves.empty() && !mcadsw::sim::model_writes_waves()) {
    // This model simulates faster without tracing; mcadsw_sim_waves, beside it, is the
    // same program on the traced model: run that with the same arguments.
    std::error_code ec;
    const auto traced = std::filesystem::read_symlink("/proc/self/exe", ec).parent_path() / "mcadsw_sim_waves";
    if (!ec && std::filesystem::exists(traced)) {
      std::fflush(stdout);
      execv(traced.c_str(), argv);
      std::cerr << "mcadsw_sim: --waves: cannot run " << traced.string() << ": " << std::strerror(errno) << "\n";
      return 1;
    }
    std::cerr << "mcadsw_sim: --waves: this model was built without FST tracing, and " << traced.string()
              << " (the traced one) is missing: cmake --build BUILD --target mcadsw_sim_waves\n";
    return 2;
  }
  opt.run.waves = waves;
  if (name.empty()) name = left;

  const bool rect = !calib.empty() || !mesh.empty();
  const int step_log2 = step == 8 ? 3 : step == 16 ? 4 : 5;
  try {
    auto load = [&](const std::string& path) {
      cv::Mat img = mcadsw::read_color_image(path);
      if (crop.area() > 0 && !rect) {  // rectification: a region of the rectified frame (below)
        if ((crop & cv::Rect(0, 0, img.cols, img.rows)) != crop)
          throw std::runtime_error("--crop region is not inside " + path);
        img = img(crop).clone();
      }
      return mcadsw::to_yuv(img);
    };
    const mcadsw::YuvImage l = load(left), r = load(right);
    if (r.width() != l.width() || r.height() != l.height())
      throw std::runtime_error("left and right images must have the same size (" +
                               std::to_string(l.width()) + "x" + std::to_string(l.height()) +
                               " vs " + std::to_string(r.width()) + "x" +
                               std::to_string(r.height()) + ")");
    // The frame: the images, or with rectification the rectified frame (the raw
    // views' size, or the --crop region of it).
    int fw = l.width(), fh = l.height();
    if (rect) {
      std::pair<mcadsw::Mesh, mcadsw::Mesh> meshes;
      if (!calib.empty()) {
        const mcadsw::StereoRectification cal = mcadsw::read_calibration(calib);
        if (cal.size.width != l.width() || cal.size.height != l.height())
          throw std::runtime_error("the raw views are " + std::to_string(l.width()) + "x" +
                                   std::to_string(l.height()) + ", the calibration's images (" + calib + ") " +
                                   std::to_string(cal.size.width) + "x" + std::to_string(cal.size.height));
        meshes = mcadsw::meshes_from_rectification(cal, l.width(), l.height(), step_log2);
      } else {
        meshes = mcadsw::read_meshes(mesh, l.width(), l.height(), step_log2);
      }
      if (crop.area() > 0) {
        if ((crop & cv::Rect(0, 0, l.width(), l.height())) != crop)
          throw std::runtime_error("--crop region is not inside the rectified frame (" + std::to_string(l.width()) +
                                   "x" + std::to_string(l.height()) + ")");
        meshes = {crop_mesh(meshes.first, crop), crop_mesh(meshes.second, crop)};
      }
      fw = meshes.first.out_width;
      fh = meshes.first.out_height;
      opt.frame.rect = mcadsw::sim::Rectification{std::move(meshes.first), std::move(meshes.second)};
    }
    mcadsw::Config cfg;
    cfg.disparities = d;
    cfg.table = mcadsw::make_weight_table(gamma);
    mcadsw::check_config(cfg, fw, fh);
    if (opt.frame.lr && fw > mcadsw::kPostMaxWidth)
      throw std::invalid_argument("the LR mode takes widths up to " +
                                  std::to_string(mcadsw::kPostMaxWidth) + ", not " +
                                  std::to_string(fw));
    if (opt.frame.tile_stride && opt.frame.tile_stride < 4 * uint32_t(fh))
      throw std::invalid_argument("tile stride " + std::to_string(opt.frame.tile_stride) +
                                  " is below 4 x the height " + std::to_string(fh));
    if (opt.frame.stride && opt.frame.stride < uint32_t(fw))
      throw std::invalid_argument("stride " + std::to_string(opt.frame.stride) + " is below the width " +
                                  std::to_string(fw));
    const int out_row = fw * (opt.frame.subpixel ? 2 : 1);
    if (opt.frame.out_stride && opt.frame.out_stride < uint32_t(out_row))
      throw std::invalid_argument("output stride " + std::to_string(opt.frame.out_stride) +
                                  " is below the output row of " + std::to_string(out_row) +
                                  " bytes");
    if (!out.empty()) {
      const auto parent = std::filesystem::path(out).parent_path();
      if (!parent.empty() && !std::filesystem::is_directory(parent))
        throw std::runtime_error("output directory '" + parent.string() + "' does not exist");
    }

    const mcadsw::sim::EngineResult res = mcadsw::sim::run_engine(l, r, cfg, opt);
    double err_all = -1;
    if (!gt.empty()) {
      const auto rd = [&](const std::string& p) {
        cv::Mat m = cv::imread(p, cv::IMREAD_UNCHANGED);
        return crop.area() > 0 && !m.empty() ? cv::Mat(m(crop)) : m;
      };
      // Rectification: the pixels valid after it (the base view's), as
      // docs/algorithm.md 13.7 counts them.
      const cv::Mat invalid = rect ? cv::Mat(mcadsw::to_mat(res.rect_valid) == 0) : cv::Mat();
      const auto rd_mask = [&](const std::string& p) {
        cv::Mat m = rd(p);
        if (!invalid.empty() && !m.empty() && m.size() == invalid.size()) {
          m = m.clone();
          m.setTo(0, invalid);
        }
        return m;
      };
      mcadsw::EvalOptions eo;
      if (opt.frame.subpixel) eo.disp_scale = mcadsw::kSubpixelScale;
      const cv::Mat map = opt.frame.subpixel ? mcadsw::to_mat(res.disparity16) : mcadsw::to_mat(res.disparity);
      err_all = mcadsw::evaluate(map, rd(gt), scale, rd_mask(masks + "/nonocc.png"), rd_mask(masks + "/all.png"),
                                 rd_mask(masks + "/disc.png"), eo)
                    .all;
    }
    if (!out.empty()) {
      if (opt.frame.subpixel)
        mcadsw::write_disparity16(res.disparity16, d, out, mcadsw::colormap_path_for(out));
      else
        mcadsw::write_disparity(res.disparity, d, out, mcadsw::colormap_path_for(out));
    }
    const double pixels = double(res.width) * res.height;
    const bool ok = res.clean();
    std::printf("%-16s %4dx%-4d D=%-2d%s%s%s%s %9ld cycles %6.1f fps@95MHz  read %8ld  written %6ld  "
                "reads/px %5.2f  stalls %7ld  rbursts %7ld  wbursts %6ld  %s",
                name.c_str(), res.width, res.height, d, opt.frame.subpixel ? " sub" : "",
                opt.frame.right ? " right" : opt.frame.lr ? " lr" : "", opt.frame.tiled ? " tiled" : "",
                rect ? (" rect S=" + std::to_string(step)).c_str() : "", res.cycles, kClockMHz * 1e6 / res.cycles,
                res.words_read, res.words_written, res.words_read / pixels, res.stall_cycles,
                res.read_bursts, res.write_bursts, ok ? "BIT-EXACT" : "FAILED");
    if (err_all >= 0) std::printf("  all %.2f%%", err_all);
    std::printf("  (%.1f s, %.0f kcycles/s)\n", res.sim_seconds, res.cycles / res.sim_seconds / 1e3);
    if (res.timed_out) std::printf("  TIMEOUT: the engine did not finish\n");
    if (res.error)
      std::printf("  engine rejected the configuration or ended the frame, error code %d: %s\n", res.error_code,
                  mcadsw::regs::error_text(res.error_code));
    std::fputs(res.report.c_str(), stdout);
    if (!json.empty()) {
      std::ofstream j(json);
      j << "{\"case\": \"" << name << "\", \"width\": " << res.width << ", \"height\": " << res.height
        << ", \"disparities\": " << d << ", \"subpixel\": " << (opt.frame.subpixel ? "true" : "false")
        << ", \"right\": " << (opt.frame.right ? "true" : "false")
        << ", \"lr\": " << (opt.frame.lr ? "true" : "false")
        << ", \"tiled\": " << (opt.frame.tiled ? "true" : "false")
        << ", \"rect\": " << (rect ? "true" : "false")
        << ", \"rect_step\": " << (rect ? std::to_string(step) : "null")
        << ", \"rect_mismatches\": " << res.rect_mismatches
        << ", \"error_code\": " << res.error_code
        << ", \"cycles\": " << res.cycles
        << ", \"words_read\": " << res.words_read << ", \"words_written\": " << res.words_written
        << ", \"stall_cycles\": " << res.stall_cycles << ", \"read_bursts\": " << res.read_bursts
        << ", \"write_bursts\": " << res.write_bursts << ", \"mismatches\": " << res.mismatches
        << ", \"bus_violations\": " << res.bus.total() << ", \"stride\": " << (opt.frame.stride ? opt.frame.stride : (res.width + 3) / 4 * 4)
        << ", \"error_all\": " << (err_all >= 0 ? std::to_string(err_all) : "null")
        << ", \"sim_seconds\": " << res.sim_seconds << "}\n";
    }
    return ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "mcadsw_sim: error: " << e.what() << "\n";
    return 1;
  }
}
