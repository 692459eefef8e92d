// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// mcadsw_report: the quality part of `make report` (flow/report.py).
//   mcadsw_report DATA_DIR OUT_DIR
// For each Middlebury pair (Tsukuba D=16, Venus D=20, Teddy D=60, Cones D=60 at
// native size) it runs the bit-exact model (hence the RTL) and the OpenCV
// baselines (sw_ref/include/mcadsw/baselines.hpp), evaluates nonocc / all / disc
// at threshold 1, writes OUT_DIR/<pair>.png (disparity and error maps of every
// method next to the ground truth) and prints a Markdown table on stdout, then a
// second one: sub-pixel maps, nonocc at threshold 0.5 (docs/algorithm.md 12.7), and a
// third: the raw camera pairs of data/raw rectified (docs/algorithm.md 13.7).
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "mcadsw/baselines.hpp"
#include "mcadsw/eval.hpp"
#include "mcadsw/image_io.hpp"
#include "mcadsw/rectify_quality.hpp"
#include "mcadsw/ref.hpp"

namespace {

struct Pair {
  const char* name;
  int disparities;
  double scale;
};
constexpr Pair kPairs[] = {{"tsukuba", 16, 16}, {"venus", 20, 8}, {"teddy", 60, 4}, {"cones", 60, 4}};

cv::Mat colorize(const cv::Mat& disp8, double to_255) {
  cv::Mat scaled, color;
  disp8.convertTo(scaled, CV_8U, to_255);
  cv::applyColorMap(scaled, color, cv::COLORMAP_JET);
  return color;
}

// Left view in gray; bad pixels red where non-occluded, yellow where occluded
// (evaluated in "all" only); pixels no mask evaluates are darkened.
cv::Mat error_map(const cv::Mat& left_bgr, const cv::Mat& disp, const cv::Mat& gt, double scale,
                  const cv::Mat& nonocc, const cv::Mat& all) {
  cv::Mat gray, out;
  cv::cvtColor(left_bgr, gray, cv::COLOR_BGR2GRAY);
  cv::cvtColor(gray, out, cv::COLOR_GRAY2BGR);
  for (int y = 0; y < disp.rows; ++y) {
    for (int x = 0; x < disp.cols; ++x) {
      cv::Vec3b& p = out.at<cv::Vec3b>(y, x);
      if (all.at<uint8_t>(y, x) != 255) {
        p /= 3;
        continue;
      }
      const bool bad =
          std::abs(disp.at<uint8_t>(y, x) - gt.at<uint8_t>(y, x) / scale) > mcadsw::kBadThreshold;
      if (bad) p = nonocc.at<uint8_t>(y, x) == 255 ? cv::Vec3b(0, 0, 255) : cv::Vec3b(0, 255, 255);
    }
  }
  return out;
}

cv::Mat labelled(const cv::Mat& img, const std::string& text) {
  cv::Mat out;
  cv::copyMakeBorder(img, out, 22, 2, 2, 2, cv::BORDER_CONSTANT, cv::Scalar(255, 255, 255));
  cv::putText(out, text, {4, 16}, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: mcadsw_report DATA_DIR OUT_DIR\n";
    return 2;
  }
  const std::string data = argv[1], out = argv[2];
  try {
    std::vector<std::string> methods{"MCADSW (this engine, bit-exact RTL model)",
                                     "MCADSW --lr (T = 1, fill, 3x3 median; reference)"};
    const std::vector<std::string> short_names{"MCADSW", "MCADSW --lr"};
    for (mcadsw::Baseline b : mcadsw::kBaselines) methods.push_back(mcadsw::baseline_name(b));
    std::vector<std::vector<mcadsw::ErrorRates>> err(methods.size());
    // Sub-pixel table: nonocc at threshold 0.5.
    const std::vector<std::string> sub_methods{
        "MCADSW, integer disparities", "MCADSW --subpixel (reference)",
        "MCADSW --lr --subpixel (reference)", "OpenCV SGBM 3WAY (16 x disparity)",
        "OpenCV SGBM 3WAY + LR check (16 x disparity)"};
    std::vector<std::vector<double>> sub_err(sub_methods.size());

    for (const Pair& p : kPairs) {
      const std::string dir = data + "/middlebury/" + p.name + "/";
      const cv::Mat l = mcadsw::read_color_image(dir + "left.png");
      const cv::Mat r = mcadsw::read_color_image(dir + "right.png");
      const auto gray = [&](const std::string& f) {
        cv::Mat m = cv::imread(dir + f, cv::IMREAD_GRAYSCALE);
        if (m.empty()) throw std::runtime_error("cannot read " + dir + f);
        return m;
      };
      const cv::Mat gt = gray("gt.png"), nonocc = gray("nonocc.png"), all = gray("all.png"),
                    disc = gray("disc.png");

      std::vector<cv::Mat> disp;
      mcadsw::Config cfg;
      cfg.disparities = p.disparities;
      const mcadsw::YuvImage ly = mcadsw::to_yuv(l), ry = mcadsw::to_yuv(r);
      disp.push_back(mcadsw::to_mat(mcadsw::disparity_map(ly, ry, cfg)));
      mcadsw::DepthOptions lr;
      lr.lr = true;
      disp.push_back(mcadsw::to_mat(mcadsw::depth_map(ly, ry, cfg, lr).disp8()));
      for (mcadsw::Baseline b : mcadsw::kBaselines)
        disp.push_back(mcadsw::baseline_disparity(b, l, r, p.disparities));

      mcadsw::DepthOptions sub;
      sub.subpixel = true;
      mcadsw::DepthOptions lr_sub = lr;
      lr_sub.subpixel = true;
      const std::vector<std::pair<cv::Mat, double>> sub_maps{
          {disp[0], 1.0},
          {mcadsw::to_mat(mcadsw::depth_map(ly, ry, cfg, sub).disp16), 16.0},
          {mcadsw::to_mat(mcadsw::depth_map(ly, ry, cfg, lr_sub).disp16), 16.0},
          {mcadsw::baseline_disparity16(mcadsw::Baseline::kSgbm3Way, l, r, p.disparities), 16.0},
          {mcadsw::baseline_disparity16(mcadsw::Baseline::kSgbmLr, l, r, p.disparities), 16.0}};
      for (size_t m = 0; m < sub_maps.size(); ++m) {
        mcadsw::EvalOptions half;
        half.disp_scale = sub_maps[m].second;
        half.threshold = 0.5;
        sub_err[m].push_back(mcadsw::evaluate(sub_maps[m].first, gt, p.scale, nonocc, all, disc, half).nonocc);
      }

      const double to_255 = 255.0 / (p.disparities - 1);
      cv::Mat gt_d;
      gt.convertTo(gt_d, CV_8U, 1.0 / p.scale);
      std::vector<cv::Mat> rows;
      cv::Mat head;
      cv::hconcat(labelled(l, std::string(p.name) + " left view"),
                  labelled(colorize(gt_d, to_255), "ground truth"), head);
      rows.push_back(head);
      for (size_t m = 0; m < disp.size(); ++m) {
        const mcadsw::ErrorRates e = mcadsw::evaluate(disp[m], gt, p.scale, nonocc, all, disc);
        err[m].push_back(e);
        const std::string short_name =
            m < short_names.size() ? short_names[m] : mcadsw::baseline_name(mcadsw::kBaselines[m - short_names.size()]);
        char line[160];
        std::snprintf(line, sizeof line, "%s: nonocc %.2f %%, all %.2f %%", short_name.c_str(), e.nonocc,
                      e.all);
        cv::Mat row;
        cv::hconcat(labelled(colorize(disp[m], to_255), short_name + " disparity"),
                    labelled(error_map(l, disp[m], gt, p.scale, nonocc, all), line), row);
        rows.push_back(row);
      }
      cv::Mat sheet;
      cv::vconcat(rows, sheet);
      const std::string path = out + "/" + p.name + ".png";
      if (!cv::imwrite(path, sheet)) throw std::runtime_error("cannot write " + path);
    }

    std::printf("| method | Tsukuba nonocc | all | disc | Venus nonocc | all | disc | Teddy nonocc | all | disc "
                "| Cones nonocc | all | disc | average all |\n|---|");
    for (int i = 0; i < 13; ++i) std::printf("---|");
    std::printf("\n");
    for (size_t m = 0; m < methods.size(); ++m) {
      std::printf("| %s", methods[m].c_str());
      double sum = 0;
      for (const mcadsw::ErrorRates& e : err[m]) {
        std::printf(" | %.2f | %.2f | %.2f", e.nonocc, e.all, e.disc);
        sum += e.all;
      }
      std::printf(" | %.2f |\n", sum / double(err[m].size()));
    }
    std::printf("\nSub-pixel: nonocc error %% at threshold 0.5 (|d - gt| > 0.5).\n\n"
                "| method | Tsukuba | Venus | Teddy | Cones | average Venus, Teddy, Cones |\n"
                "|---|---|---|---|---|---|\n");
    for (size_t m = 0; m < sub_methods.size(); ++m) {
      std::printf("| %s", sub_methods[m].c_str());
      for (double e : sub_err[m]) std::printf(" | %.2f", e);
      std::printf(" | %.2f |\n", (sub_err[m][1] + sub_err[m][2] + sub_err[m][3]) / 3.0);
    }

    // Rectification (docs/algorithm.md 13.7): the raw camera pairs of data/raw,
    // LR mode, "all" error over the pixels valid after rectification.
    std::printf("\nRectification: raw camera pairs (data/raw), LR mode, \"all\" error %% over the pixels valid "
                "after rectification; average over the pairs of each camera.\n\n"
                "| camera | pairs | undistorted (bundled) | mesh S = 16 (engine) | OpenCV float, bilinear | "
                "OpenCV float, bicubic | OpenCV float, Lanczos-4 | mesh - OpenCV bilinear |\n"
                "|---|---|---|---|---|---|---|---|\n");
    for (const char* cam : {"A", "B", "C"}) {
      mcadsw::RectificationQuality sum;
      int n = 0;
      for (const Pair& p : kPairs) {
        const std::string raw_dir = data + "/raw/" + cam + "/middlebury/" + p.name;
        if (!std::filesystem::is_directory(raw_dir)) continue;
        const mcadsw::RectificationQuality q =
            mcadsw::rectification_quality(raw_dir, data + "/middlebury/" + p.name, p.disparities, p.scale);
        sum.undistorted += q.undistorted;
        sum.mesh += q.mesh;
        sum.opencv_linear += q.opencv_linear;
        sum.opencv_cubic += q.opencv_cubic;
        sum.opencv_lanczos += q.opencv_lanczos;
        ++n;
      }
      if (n == 0) throw std::runtime_error("no raw pairs of camera " + std::string(cam) + " in " + data + "/raw");
      std::printf("| %s | %d | %.2f | %.2f | %.2f | %.2f | %.2f | %+.2f |\n", cam, n, sum.undistorted / n,
                  sum.mesh / n, sum.opencv_linear / n, sum.opencv_cubic / n, sum.opencv_lanczos / n,
                  (sum.mesh - sum.opencv_linear) / n);
    }
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "mcadsw_report: error: " << e.what() << "\n";
    return 1;
  }
}
