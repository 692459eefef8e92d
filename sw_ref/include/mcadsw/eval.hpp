// Middlebury v2 evaluation: percentage of bad pixels (|d - gt/scale| > 1) over
// the nonocc, all and disc masks (mask value 255).
#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace mcadsw {

struct ErrorRates {
  double nonocc = 0, all = 0, disc = 0;  // percent
};

inline constexpr double kBadThreshold = 1.0;

// All inputs CV_8UC1 of one size. Throws std::invalid_argument otherwise.
ErrorRates evaluate(const cv::Mat& disp, const cv::Mat& gt, double scale, const cv::Mat& nonocc,
                    const cv::Mat& all, const cv::Mat& disc);
// Reads DISP and GT, and nonocc.png/all.png/disc.png from masks_dir.
// Throws std::runtime_error with a one-line message on any missing file or size mismatch.
ErrorRates evaluate_files(const std::string& disp_path, const std::string& gt_path, double scale,
                          const std::string& masks_dir);

}  // namespace mcadsw
