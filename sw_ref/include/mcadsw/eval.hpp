// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Middlebury v2 evaluation: percentage of bad pixels (|disp/disp_scale - gt/scale| >
// threshold, threshold 1 by default) over the nonocc, all and disc masks (mask value
// 255). docs/algorithm.md sections 8 and 12.7.
#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace mcadsw {

struct ErrorRates {
  double nonocc = 0, all = 0, disc = 0;  // percent
};

inline constexpr double kBadThreshold = 1.0;

// The map's value is disp_scale times the disparity (16 for sub-pixel maps).
struct EvalOptions {
  double disp_scale = 1.0;
  double threshold = kBadThreshold;
};

// All inputs of one size, CV_8UC1; the map may be CV_16UC1 too. Throws
// std::invalid_argument otherwise, or for a non-positive scale or threshold.
ErrorRates evaluate(const cv::Mat& disp, const cv::Mat& gt, double scale, const cv::Mat& nonocc,
                    const cv::Mat& all, const cv::Mat& disc, const EvalOptions& opt = {});
// Reads DISP and GT, and nonocc.png/all.png/disc.png from masks_dir.
// Throws std::runtime_error with a one-line message on any missing file or size mismatch.
ErrorRates evaluate_files(const std::string& disp_path, const std::string& gt_path, double scale,
                          const std::string& masks_dir, const EvalOptions& opt = {});

}  // namespace mcadsw
