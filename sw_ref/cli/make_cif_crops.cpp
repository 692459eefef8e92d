// make_cif_crops SRC DST: cuts the CIF (352x288) crop of every Middlebury pair.
// The crop is centred: x0 = (W-352)/2, y0 = (H-288)/2 (integer division), taken
// alike from left.png, right.png, gt.png and the three masks, so the disparity
// convention (left x matches right x-d) and the GT values are unchanged.
#include <filesystem>
#include <iostream>
#include <opencv2/imgcodecs.hpp>

namespace fs = std::filesystem;

constexpr int kCifW = 352, kCifH = 288;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: make_cif_crops SRC_DIR DST_DIR (e.g. data/middlebury data/cif)\n";
    return 2;
  }
  const fs::path src(argv[1]), dst(argv[2]);
  int pairs = 0;
  for (const char* name : {"tsukuba", "venus", "teddy", "cones"}) {
    fs::create_directories(dst / name);
    for (const char* file : {"left.png", "right.png", "gt.png", "nonocc.png", "all.png", "disc.png"}) {
      const cv::Mat img = cv::imread((src / name / file).string(), cv::IMREAD_UNCHANGED);
      if (img.empty() || img.cols < kCifW || img.rows < kCifH) {
        std::cerr << "make_cif_crops: cannot read a >= 352x288 image from " << (src / name / file)
                  << "\n";
        return 1;
      }
      const cv::Rect roi((img.cols - kCifW) / 2, (img.rows - kCifH) / 2, kCifW, kCifH);
      if (!cv::imwrite((dst / name / file).string(), img(roi))) {
        std::cerr << "make_cif_crops: cannot write " << (dst / name / file) << "\n";
        return 1;
      }
    }
    ++pairs;
  }
  std::cout << "make_cif_crops: wrote " << pairs << " CIF pairs to " << dst << "\n";
  return 0;
}
