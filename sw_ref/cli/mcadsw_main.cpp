// mcadsw: command-line front end of the bit-exact reference model.
//   mcadsw match LEFT RIGHT -d D [--gamma G] [--threads N] -o OUT.png
//   mcadsw eval DISP.png GT.png --scale S --masks DIR
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
#include "mcadsw/ref.hpp"

namespace {

const char* kUsage =
    "usage:\n"
    "  mcadsw match LEFT RIGHT -d D [--gamma G] [--threads N] -o OUT.png\n"
    "      Disparity map of the left view (MCADSW, bit-exact with the RTL).\n"
    "      Writes the raw 8-bit map (pixel value = disparity) to OUT.png and a\n"
    "      colour-mapped view to OUT_color.png. 1 <= D <= 64; default gamma 22.\n"
    "  mcadsw eval DISP.png GT.png --scale S --masks DIR\n"
    "      Middlebury v2 error rates (% of pixels with |d - gt/S| > 1) over\n"
    "      DIR/nonocc.png, DIR/all.png and DIR/disc.png.\n"
    "  mcadsw --help\n";

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Splits argv into positionals and --options; every option takes one value.
struct Args {
  std::vector<std::string> pos;
  std::vector<std::pair<std::string, std::string>> opts;

  Args(int argc, char** argv, int first) {
    for (int i = first; i < argc; ++i) {
      std::string a = argv[i];
      if (a.size() > 1 && a[0] == '-') {
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

int cmd_match(const Args& a) {
  a.only({"-d", "--disparities", "--gamma", "--threads", "-o", "--output"});
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

  const mcadsw::YuvImage left = mcadsw::load_yuv(a.pos[0]);
  const mcadsw::YuvImage right = mcadsw::load_yuv(a.pos[1]);
  const auto parent = std::filesystem::path(*out).parent_path();
  if (!parent.empty() && !std::filesystem::is_directory(parent))
    throw std::runtime_error("output directory '" + parent.string() + "' does not exist");

  const auto t0 = std::chrono::steady_clock::now();
  const mcadsw::Plane disp = mcadsw::disparity_map(left, right, cfg);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  const std::string color = mcadsw::colormap_path_for(*out);
  mcadsw::write_disparity(disp, cfg.disparities, *out, color);
  std::printf("%dx%d D=%d: %.3f s (%.1f MDE/s) -> %s, %s\n", disp.width, disp.height,
              cfg.disparities, s, double(disp.width) * disp.height * cfg.disparities / s / 1e6,
              out->c_str(), color.c_str());
  return 0;
}

int cmd_eval(const Args& a) {
  a.only({"--scale", "--masks"});
  if (a.pos.size() != 2) throw UsageError("eval needs DISP and GT images");
  const std::string* scale = a.get({"--scale"});
  const std::string* masks = a.get({"--masks"});
  if (!scale) throw UsageError("eval needs --scale S");
  if (!masks) throw UsageError("eval needs --masks DIR");
  const double s = to_double(*scale, "scale");
  if (!(s > 0)) throw UsageError("scale must be positive");
  const mcadsw::ErrorRates e = mcadsw::evaluate_files(a.pos[0], a.pos[1], s, *masks);
  std::printf("nonocc %.2f\nall %.2f\ndisc %.2f\n", e.nonocc, e.all, e.disc);
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
  try {
    const Args args(argc, argv, 2);
    if (cmd == "match") return cmd_match(args);
    if (cmd == "eval") return cmd_eval(args);
    throw UsageError("unknown command '" + cmd + "'");
  } catch (const UsageError& e) {
    std::cerr << "mcadsw: " << e.what() << "\n" << kUsage;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "mcadsw: error: " << e.what() << "\n";
    return 1;
  }
}
