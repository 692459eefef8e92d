// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// make_cif_crops SRC DST [--x2 [--vga]]: cuts the CIF (352x288) crop of every Middlebury pair.
// The crop is centred: x0 = (W-352)/2, y0 = (H-288)/2 (integer division), taken
// alike from left.png, right.png, gt.png and the three masks, so the disparity
// convention (left x matches right x-d) and the GT values are unchanged.
//
// --x2 (disparities above 64): Teddy and Cones upscaled by 2 first
// (views: bicubic; ground truth and masks: nearest neighbour). Disparities double
// while the ground truth's values stay, so its scale halves: 2 instead of 4
// (value = 2 x disparity). The crop is not centred but the CIF window, on an
// 8-pixel grid, with the most ground-truth pixels of disparity above 64 (the
// first such window in row-major order). --vga: 640x480 windows instead (VGA,
// for the cycle and frame-rate figures).
#include <filesystem>
#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  const bool x2 = argc >= 4 && std::string(argv[3]) == "--x2";
  const bool vga = x2 && argc == 5 && std::string(argv[4]) == "--vga";
  if (argc != 3 && !(x2 && (argc == 4 || vga))) {
    std::cerr << "usage: make_cif_crops SRC_DIR DST_DIR [--x2 [--vga]] (e.g. data/middlebury data/cif,\n"
                 "       data/middlebury data/cif_x2 --x2, data/middlebury data/vga_x2 --x2 --vga)\n";
    return 2;
  }
  const int kCifW = vga ? 640 : 352, kCifH = vga ? 480 : 288;
  const fs::path src(argv[1]), dst(argv[2]);
  const std::vector<const char*> names =
      x2 ? std::vector<const char*>{"teddy", "cones"}
         : std::vector<const char*>{"tsukuba", "venus", "teddy", "cones"};
  int pairs = 0;
  for (const char* name : names) {
    fs::create_directories(dst / name);
    cv::Point origin(-1, -1);  // --x2: the crop's origin, from the ground truth
    if (x2) {
      cv::Mat gt = cv::imread((src / name / "gt.png").string(), cv::IMREAD_UNCHANGED);
      if (gt.empty()) {
        std::cerr << "make_cif_crops: cannot read " << (src / name / "gt.png") << "\n";
        return 1;
      }
      cv::resize(gt, gt, cv::Size(), 2.0, 2.0, cv::INTER_NEAREST);
      cv::Mat far = (gt > 2 * 64) / 255, sum;  // value 2 d > 2 x 64
      cv::integral(far, sum, CV_32S);
      int best = -1;
      for (int y = 0; y + kCifH <= gt.rows; y += 8)
        for (int x = 0; x + kCifW <= gt.cols; x += 8) {
          const int n = sum.at<int>(y + kCifH, x + kCifW) - sum.at<int>(y, x + kCifW) -
                        sum.at<int>(y + kCifH, x) + sum.at<int>(y, x);
          if (n > best) {
            best = n;
            origin = {x, y};
          }
        }
      std::cout << "make_cif_crops: " << name << " x2 crop at (" << origin.x << "," << origin.y
                << "), " << best << " pixels of disparity above 64\n";
    }
    for (const char* file : {"left.png", "right.png", "gt.png", "nonocc.png", "all.png", "disc.png"}) {
      cv::Mat img = cv::imread((src / name / file).string(), cv::IMREAD_UNCHANGED);
      if (!img.empty() && x2) {
        const bool view = std::string(file) == "left.png" || std::string(file) == "right.png";
        cv::resize(img, img, cv::Size(), 2.0, 2.0, view ? cv::INTER_CUBIC : cv::INTER_NEAREST);
      }
      if (img.empty() || img.cols < kCifW || img.rows < kCifH) {
        std::cerr << "make_cif_crops: cannot read a >= " << kCifW << "x" << kCifH << " image from "
                  << (src / name / file)
                  << "\n";
        return 1;
      }
      const cv::Rect roi(x2 ? origin.x : (img.cols - kCifW) / 2, x2 ? origin.y : (img.rows - kCifH) / 2,
                         kCifW, kCifH);
      if (!cv::imwrite((dst / name / file).string(), img(roi))) {
        std::cerr << "make_cif_crops: cannot write " << (dst / name / file) << "\n";
        return 1;
      }
    }
    ++pairs;
  }
  std::cout << "make_cif_crops: wrote " << pairs << " pairs of " << kCifW << "x" << kCifH << " to " << dst
            << (x2 ? " (2x upscaled)" : "") << "\n";
  return 0;
}
