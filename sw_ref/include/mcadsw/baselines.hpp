// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// OpenCV stereo matchers the report (`make report`) and the benchmark compare
// the engine with: StereoSGBM in MODE_SGBM_3WAY and MODE_HH, StereoBM, and
// StereoSGBM 3WAY with its own left-right check, uniqueness and speckle filter
// (the fair row for the engine's LR mode, docs/algorithm.md section 12).
// Not part of the engine; this is what a user would otherwise run.
#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace mcadsw {

enum class Baseline { kSgbm3Way, kSgbmHH, kBm, kSgbmLr };
inline constexpr Baseline kBaselines[] = {Baseline::kSgbm3Way, Baseline::kSgbmHH, Baseline::kBm,
                                          Baseline::kSgbmLr};

const char* baseline_name(Baseline b);
// The matcher's parameters, one line, for the report.
std::string baseline_params(Baseline b, int disparities);

// Dense integer disparity map of the left view, CV_8UC1 with values 0..D-1,
// from 8-bit BGR views of one size. So that the baselines are not penalised for
// what the engine handles by its border rule and always outputs a value:
//  - both views are padded on the left by the disparity range (edge pixels
//    replicated) and the result cropped back, so every pixel has all D candidates;
//  - uniqueness, left-right and speckle checks are off (except kSgbmLr: disp12MaxDiff
//    1, uniquenessRatio 10, speckle window 100, range 2), and any pixel left invalid
//    takes the nearest valid disparity to its left (else to its right);
//  - the sub-pixel result is rounded to the nearest integer and clamped to D-1.
// OpenCV searches a multiple of 16 disparities: D is rounded up for the search.
// Throws std::invalid_argument for bad sizes, types or D outside 1..255.
cv::Mat baseline_disparity(Baseline b, const cv::Mat& left_bgr, const cv::Mat& right_bgr,
                           int disparities);
// The same map before rounding: CV_16UC1, 16 x disparity (OpenCV's sub-pixel output),
// invalid pixels filled as above, clamped to 16 (D - 1).
cv::Mat baseline_disparity16(Baseline b, const cv::Mat& left_bgr, const cv::Mat& right_bgr,
                             int disparities);

}  // namespace mcadsw
