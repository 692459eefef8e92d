// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// mcadsw: command-line front end of the bit-exact reference model.
//   mcadsw match LEFT RIGHT -d D [--lr [-T T] [--valid MASK.png]] [--subpixel]
//                [--gamma G] [--threads N] [--calib CALIB.yml [--step S]] -o OUT.png
//   mcadsw eval DISP.png GT.png --scale S --masks DIR [--disp-scale S] [--threshold T]
//   mcadsw mesh CALIB.yml [--step S] -o MESH.bin
//   mcadsw rectify CALIB.yml LEFT RIGHT [--step S] -o OUTDIR
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "mcadsw/eval.hpp"
#include "mcadsw/image_io.hpp"
#include "mcadsw/parse.hpp"
#include "mcadsw/rectify.hpp"
#include "mcadsw/ref.hpp"
#include "mcadsw/regs.hpp"
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace {

const std::string kUsage =
    std::string("usage:\n"
    "  mcadsw match LEFT RIGHT -d D [--lr [-T T] [--valid MASK.png]] [--subpixel]\n"
    "               [--gamma G] [--threads N] [--calib CALIB.yml [--step S]] -o OUT.png\n"
    "      Disparity map of the left view (MCADSW, bit-exact with the RTL).\n"
    "      --calib: LEFT and RIGHT are raw camera views, rectified first through the\n"
    "      mesh (as mcadsw rectify); a left pixel whose source lies outside its raw\n"
    "      view gets 255 (0xFFFF with --subpixel), docs/algorithm.md 13.4.\n"
    "      Writes the raw 8-bit map (pixel value = disparity) to OUT.png and a\n"
    "      colour-mapped view to OUT_color.png. 1 <= D <= ") + std::to_string(mcadsw::kDmax) + " (DMAX); default gamma 22.\n"
    "      --lr: left-right check (tolerance T, 0..63, default 1), fill, 3x3 median;\n"
    "      --valid writes the check's mask (255 valid, 0 filled). --subpixel: a\n"
    "      16-bit map of 16 x disparity (parabolic). docs/algorithm.md section 12.\n"
    "  mcadsw eval DISP.png GT.png --scale S --masks DIR [--disp-scale S] [--threshold T]\n"
    "      Middlebury v2 error rates (% of pixels with |d/disp-scale - gt/S| > T,\n"
    "      T = 1 by default) over DIR/nonocc.png, DIR/all.png and DIR/disc.png.\n"
    "      --disp-scale 16 for the 16-bit maps of --subpixel.\n"
    "  mcadsw mesh CALIB.yml [--step S] -o MESH.bin\n"
    "      The rectification mesh of an OpenCV calibration (YAML or XML: image_width,\n"
    "      image_height and K1 D1 K2 D2 R T, or K1 D1 R1 P1 K2 D2 R2 P2), both views,\n"
    "      as the engine reads it (docs/algorithm.md section 13). S: 8, 16 (default) or 32.\n"
    "  mcadsw rectify CALIB.yml LEFT RIGHT [--step S] -o OUTDIR\n"
    "      The raw pair rectified through the mesh (bit-exact with the RTL): OUTDIR/left.png,\n"
    "      right.png (YUV converted back to BGR for viewing) and left_valid.png,\n"
    "      right_valid.png (255 where the source lies inside the raw view). Prints, per view,\n"
    "      the mesh's largest deviation from OpenCV's float map and the PSNR against\n"
    "      cv::remap (INTER_LINEAR) on that map.\n"
    "  mcadsw --help\n"
    "  mcadsw --version\n"
    "      The project's version and the register map version of the engine it models.\n";

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Flags: options without a value.
bool is_flag(const std::string& a) { return a == "--lr" || a == "--subpixel"; }

// Splits argv into positionals and --options; every option but a flag takes one value.
struct Args {
  std::vector<std::string> pos;
  std::vector<std::pair<std::string, std::string>> opts;

  Args(int argc, char** argv, int first) {
    for (int i = first; i < argc; ++i) {
      std::string a = argv[i];
      if (is_flag(a)) {
        opts.emplace_back(a, "");
      } else if (a.size() > 1 && a[0] == '-') {
        if (i + 1 >= argc) throw UsageError("option " + a + " needs a value");
        opts.emplace_back(a, argv[++i]);
      } else {
        pos.push_back(a);
      }
    }
  }
  const std::string* get(std::initializer_list<const char*> names) const {
    const std::string* found = nullptr;
    for (auto& [k, v] : opts) {
      bool match = false;
      for (const char* n : names) match |= (k == n);
      if (match) found = &v;
    }
    return found;
  }
  void only(std::initializer_list<const char*> allowed) const {
    for (auto& [k, v] : opts) {
      bool ok = false;
      for (const char* n : allowed) ok |= (k == n);
      if (!ok) throw UsageError("unknown option " + k);
    }
  }
};

// Bad numbers are usage errors (exit status 2).
long to_int(const std::string& s, const char* what) {
  try {
    return mcadsw::parse_long(s, what);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
}

double to_double(const std::string& s, const char* what) {
  try {
    return mcadsw::parse_double(s, what);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
}

int step_log2_of(const Args& a);

// A raw view must have the calibration's image size.
void check_raw_size(const mcadsw::StereoRectification& cal, const mcadsw::YuvImage& raw, const std::string& path) {
  if (raw.width() != cal.size.width || raw.height() != cal.size.height)
    throw std::runtime_error(path + " is " + std::to_string(raw.width()) + "x" + std::to_string(raw.height()) +
                             ", the calibration's images " + std::to_string(cal.size.width) + "x" +
                             std::to_string(cal.size.height));
}

int cmd_match(const Args& a) {
  a.only({"-d", "--disparities", "--gamma", "--threads", "-o", "--output", "--lr", "--subpixel",
          "-T", "--tolerance", "--valid", "--calib", "--step"});
  if (a.pos.size() != 2) throw UsageError("match needs LEFT and RIGHT images");
  const std::string* d = a.get({"-d", "--disparities"});
  const std::string* out = a.get({"-o", "--output"});
  if (!d) throw UsageError("match needs -d D");
  if (!out) throw UsageError("match needs -o OUT.png");

  mcadsw::Config cfg;
  cfg.disparities = int(to_int(*d, "D"));
  if (const std::string* g = a.get({"--gamma"}))
    cfg.table = mcadsw::make_weight_table(to_double(*g, "gamma"));
  if (const std::string* t = a.get({"--threads"})) cfg.threads = int(to_int(*t, "threads"));
  mcadsw::DepthOptions post;
  post.lr = a.get({"--lr"}) != nullptr;
  post.subpixel = a.get({"--subpixel"}) != nullptr;
  const std::string* tol = a.get({"-T", "--tolerance"});
  const std::string* valid = a.get({"--valid"});
  if ((tol || valid) && !post.lr) throw UsageError("-T and --valid need --lr");
  if (tol) post.tolerance = int(to_int(*tol, "T"));
  mcadsw::check_config(cfg, 1, 1);
  mcadsw::check_lr_tolerance(post.tolerance);

  const std::string* calib = a.get({"--calib"});
  if (a.get({"--step"}) && !calib) throw UsageError("--step needs --calib");
  const int step_log2 = step_log2_of(a);

  mcadsw::YuvImage left = mcadsw::load_yuv(a.pos[0]);
  mcadsw::YuvImage right = mcadsw::load_yuv(a.pos[1]);
  long long invalid[2] = {0, 0};
  if (calib) {  // rectify first (docs/algorithm.md 13); invalid pixels per 13.4
    const mcadsw::StereoRectification cal = mcadsw::read_calibration(*calib);
    check_raw_size(cal, left, a.pos[0]);
    check_raw_size(cal, right, a.pos[1]);
    const auto meshes = mcadsw::meshes_from_rectification(cal, cal.size.width, cal.size.height, step_log2);
    mcadsw::Rectified l = mcadsw::rectify(left, meshes.first), r = mcadsw::rectify(right, meshes.second);
    for (const auto v : l.valid.px) invalid[0] += v == 0;
    for (const auto v : r.valid.px) invalid[1] += v == 0;
    left = std::move(l.image);
    right = std::move(r.image);
    post.left_valid = std::move(l.valid);
    post.right_valid = std::move(r.valid);
  }
  for (const std::string* o : {out, valid}) {
    if (!o) continue;
    const auto parent = std::filesystem::path(*o).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent))
      throw std::runtime_error("output directory '" + parent.string() + "' does not exist");
  }

  const auto t0 = std::chrono::steady_clock::now();
  mcadsw::DepthResult r;
  if (post.lr || post.subpixel || calib) {
    r = mcadsw::depth_map(left, right, cfg, post);
  } else {
    r.raw = mcadsw::disparity_map(left, right, cfg);  // the paper's raw mode
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  const std::string color = mcadsw::colormap_path_for(*out);
  if (post.subpixel) {
    mcadsw::write_disparity16(r.disp16, cfg.disparities, *out, color);
  } else {
    mcadsw::write_disparity(post.lr || calib ? r.disp8() : r.raw, cfg.disparities, *out, color);
  }
  if (valid) {
    try {
      mcadsw::write_mask(r.valid, *valid);
    } catch (...) {
      std::remove(out->c_str());
      std::remove(color.c_str());
      throw;
    }
  }
  if (calib)
    std::printf("rectified (%s, step %d): %lld left and %lld right pixels invalid (left ones: depth %d)\n",
                calib->c_str(), 1 << step_log2, invalid[0], invalid[1],
                post.subpixel ? mcadsw::kRectInvalidDisp16 : mcadsw::kRectInvalidDisp8);
  std::printf("%dx%d D=%d%s%s: %.3f s (%.1f MDE/s) -> %s, %s%s%s\n", r.raw.width, r.raw.height,
              cfg.disparities, post.lr ? " lr" : "", post.subpixel ? " subpixel" : "", s,
              double(r.raw.width) * r.raw.height * cfg.disparities / s / 1e6, out->c_str(),
              color.c_str(), valid ? ", " : "", valid ? valid->c_str() : "");
  return 0;
}

int cmd_eval(const Args& a) {
  a.only({"--scale", "--masks", "--disp-scale", "--threshold"});
  if (a.pos.size() != 2) throw UsageError("eval needs DISP and GT images");
  const std::string* scale = a.get({"--scale"});
  const std::string* masks = a.get({"--masks"});
  if (!scale) throw UsageError("eval needs --scale S");
  if (!masks) throw UsageError("eval needs --masks DIR");
  const double s = to_double(*scale, "scale");
  if (!(s > 0)) throw UsageError("scale must be positive");
  mcadsw::EvalOptions opt;
  if (const std::string* ds = a.get({"--disp-scale"})) opt.disp_scale = to_double(*ds, "disp-scale");
  if (const std::string* th = a.get({"--threshold"})) opt.threshold = to_double(*th, "threshold");
  if (!(opt.disp_scale > 0)) throw UsageError("disp-scale must be positive");
  if (!(opt.threshold > 0)) throw UsageError("threshold must be positive");
  const mcadsw::ErrorRates e = mcadsw::evaluate_files(a.pos[0], a.pos[1], s, *masks, opt);
  std::printf("nonocc %.2f\nall %.2f\ndisc %.2f\n", e.nonocc, e.all, e.disc);
  return 0;
}

int step_log2_of(const Args& a) {
  const std::string* st = a.get({"--step"});
  const long step = st ? to_int(*st, "step") : 16;
  if (step != 8 && step != 16 && step != 32) throw UsageError("--step must be 8, 16 or 32");
  return step == 8 ? 3 : step == 16 ? 4 : 5;
}

int cmd_mesh(const Args& a) {
  a.only({"--step", "-o", "--output"});
  if (a.pos.size() != 1) throw UsageError("mesh needs CALIB.yml");
  const std::string* out = a.get({"-o", "--output"});
  if (!out) throw UsageError("mesh needs -o MESH.bin");
  const mcadsw::StereoRectification r = mcadsw::read_calibration(a.pos[0]);
  const auto [l, rt] = mcadsw::meshes_from_rectification(r, r.size.width, r.size.height, step_log2_of(a));
  mcadsw::write_meshes(*out, l, rt);
  std::printf("%s: %dx%d frame, step %d, %dx%d nodes a view\n", out->c_str(), r.size.width, r.size.height, l.step(),
              l.nx, l.ny);
  return 0;
}

int cmd_rectify(const Args& a) {
  a.only({"--step", "-o", "--output"});
  if (a.pos.size() != 3) throw UsageError("rectify needs CALIB.yml LEFT RIGHT");
  const std::string* out = a.get({"-o", "--output"});
  if (!out) throw UsageError("rectify needs -o OUTDIR");
  const mcadsw::StereoRectification r = mcadsw::read_calibration(a.pos[0]);
  const auto meshes = mcadsw::meshes_from_rectification(r, r.size.width, r.size.height, step_log2_of(a));
  const mcadsw::YuvImage raws[2] = {mcadsw::load_yuv(a.pos[1]), mcadsw::load_yuv(a.pos[2])};
  check_raw_size(r, raws[0], a.pos[1]);
  check_raw_size(r, raws[1], a.pos[2]);
  std::filesystem::create_directories(*out);
  for (const int view : {0, 1}) {
    const mcadsw::YuvImage& raw = raws[view];
    const mcadsw::Mesh& mesh = view == 0 ? meshes.first : meshes.second;
    const mcadsw::Rectified rect = mcadsw::rectify(raw, mesh);
    const mcadsw::RectifyAgreement agree =
        view == 0 ? mcadsw::compare_with_opencv(raw, mesh, r.k1, r.d1, r.r1, cv::Matx34d(r.p1))
                  : mcadsw::compare_with_opencv(raw, mesh, r.k2, r.d2, r.r2, cv::Matx34d(r.p2));
    long long valid = 0;
    for (const auto v : rect.valid.px) valid += v;
    std::printf("%s: %lld of %d pixels valid; mesh within %.3f pixel of OpenCV's float map; "
                "%.1f dB PSNR against cv::remap INTER_LINEAR on it (%lld pixels)\n",
                view == 0 ? "left" : "right", valid, r.size.width * r.size.height, agree.mesh_deviation, agree.psnr,
                agree.valid);
    cv::Mat yuv, bgr;
    cv::merge(std::vector<cv::Mat>{mcadsw::to_mat(rect.image.y), mcadsw::to_mat(rect.image.u),
                                   mcadsw::to_mat(rect.image.v)},
              yuv);
    cv::cvtColor(yuv, bgr, cv::COLOR_YUV2BGR);
    const std::string name = view == 0 ? "left" : "right";
    if (!cv::imwrite(*out + "/" + name + ".png", bgr)) throw std::runtime_error("cannot write " + *out + "/" + name + ".png");
    mcadsw::Plane mask = rect.valid;
    for (auto& v : mask.px) v = v ? 255 : 0;
    mcadsw::write_mask(mask, *out + "/" + name + "_valid.png");
  }
  std::printf("%s: left.png right.png left_valid.png right_valid.png (%dx%d)\n", out->c_str(), r.size.width,
              r.size.height);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << kUsage;
    return 2;
  }
  const std::string cmd = argv[1];
  if (cmd == "--help" || cmd == "-h" || cmd == "help") {
    std::cout << kUsage;
    return 0;
  }
  if (cmd == "--version") {
    std::cout << "mcadsw " << MCADSW_VERSION << " (register map " << mcadsw::regs::kVersionMajor
              << "." << mcadsw::regs::kVersionMinor << ")\n";
    return 0;
  }
  try {
    const Args args(argc, argv, 2);
    if (cmd == "match") return cmd_match(args);
    if (cmd == "eval") return cmd_eval(args);
    if (cmd == "mesh") return cmd_mesh(args);
    if (cmd == "rectify") return cmd_rectify(args);
    throw UsageError("unknown command '" + cmd + "'");
  } catch (const UsageError& e) {
    std::cerr << "mcadsw: " << e.what() << "\n" << kUsage;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "mcadsw: error: " << e.what() << "\n";
    return 1;
  }
}
