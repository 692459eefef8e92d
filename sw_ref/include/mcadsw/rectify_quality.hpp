// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The quality bar (docs/algorithm.md 13.7): a raw camera pair of data/raw
// rectified three ways and matched by the same matcher (LR mode), its "all" error
// over the pixels valid after rectification, next to the bundled (undistorted) pair's
// error over the same pixels.
#pragma once

#include <string>

#include "mcadsw/ref.hpp"

namespace mcadsw {

struct RectificationQuality {
  double undistorted = 0;     // the bundled pair, matched as it is
  double mesh = 0;            // mcadsw::rectify through the mesh (bit-exact with the RTL)
  double opencv_linear = 0;   // cv::remap INTER_LINEAR on the float maps
  double opencv_cubic = 0;    // INTER_CUBIC
  double opencv_lanczos = 0;  // INTER_LANCZOS4
  long long pixels = 0;       // "all" pixels valid in every rectification of the left view
};

// raw_dir: left.png, right.png, calib.yml (data/raw/<camera>/<set>/<name>); bundled_dir:
// the bundled pair with gt.png and the masks (data/<set>/<name>). LR mode, tolerance T,
// `disparities` D, ground-truth scale `gt_scale`, mesh step 2^step_log2. "All" error in
// percent at threshold 1, each over the same pixels.
RectificationQuality rectification_quality(const std::string& raw_dir, const std::string& bundled_dir,
                                           int disparities, double gt_scale, int step_log2 = 4,
                                           int tolerance = kLrToleranceDefault);

}  // namespace mcadsw
