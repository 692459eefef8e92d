// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

#include "mcadsw/eval.hpp"

#include <cmath>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

namespace mcadsw {

ErrorRates evaluate(const cv::Mat& disp, const cv::Mat& gt, double scale, const cv::Mat& nonocc,
                    const cv::Mat& all, const cv::Mat& disc, const EvalOptions& opt) {
  if (!(scale > 0)) throw std::invalid_argument("scale must be positive");
  if (!(opt.disp_scale > 0)) throw std::invalid_argument("disparity scale must be positive");
  if (!(opt.threshold > 0)) throw std::invalid_argument("threshold must be positive");
  if (disp.type() != CV_8UC1 && disp.type() != CV_16UC1)
    throw std::invalid_argument("the disparity map must be 8-bit or 16-bit gray");
  for (const cv::Mat* m : {&disp, &gt, &nonocc, &all, &disc}) {
    if (m != &disp && m->type() != CV_8UC1)
      throw std::invalid_argument("ground truth and masks must be 8-bit gray");
    if (m->size() != disp.size())
      throw std::invalid_argument("size mismatch: disparity " + std::to_string(disp.cols) + "x" +
                                  std::to_string(disp.rows) + " vs " + std::to_string(m->cols) +
                                  "x" + std::to_string(m->rows));
  }
  long bad[3] = {0, 0, 0}, count[3] = {0, 0, 0};
  const cv::Mat* masks[3] = {&nonocc, &all, &disc};
  for (int y = 0; y < disp.rows; ++y) {
    for (int x = 0; x < disp.cols; ++x) {
      const double d = (disp.type() == CV_16UC1 ? disp.at<uint16_t>(y, x) : disp.at<uint8_t>(y, x)) /
                       opt.disp_scale;
      const bool is_bad = std::fabs(d - gt.at<uint8_t>(y, x) / scale) > opt.threshold;
      for (int m = 0; m < 3; ++m) {
        if (masks[m]->at<uint8_t>(y, x) != 255) continue;
        ++count[m];
        bad[m] += is_bad;
      }
    }
  }
  auto pct = [&](int m) { return count[m] ? 100.0 * bad[m] / count[m] : 0.0; };
  return ErrorRates{pct(0), pct(1), pct(2)};
}

static cv::Mat read_gray(const std::string& path, bool allow16 = false) {
  if (!std::filesystem::is_regular_file(path))
    throw std::runtime_error("cannot open '" + path + "': no such file");
  cv::Mat m = cv::imread(path, cv::IMREAD_UNCHANGED);
  if (m.empty()) throw std::runtime_error("cannot read '" + path + "': not an image");
  if (m.type() != CV_8UC1 && !(allow16 && m.type() == CV_16UC1))
    throw std::runtime_error("'" + path + "' must be an 8-bit" + (allow16 ? " or 16-bit" : "") +
                             " single-channel image");
  return m;
}

ErrorRates evaluate_files(const std::string& disp_path, const std::string& gt_path, double scale,
                          const std::string& masks_dir, const EvalOptions& opt) {
  const std::filesystem::path dir(masks_dir);
  // Read in a fixed order so the first missing file is the one reported.
  const cv::Mat disp = read_gray(disp_path, true);
  const cv::Mat gt = read_gray(gt_path);
  const cv::Mat nonocc = read_gray((dir / "nonocc.png").string());
  const cv::Mat all = read_gray((dir / "all.png").string());
  const cv::Mat disc = read_gray((dir / "disc.png").string());
  try {
    return evaluate(disp, gt, scale, nonocc, all, disc, opt);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(e.what());
  }
}

}  // namespace mcadsw
