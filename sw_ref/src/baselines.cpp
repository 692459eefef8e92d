// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

#include "mcadsw/baselines.hpp"

#include <algorithm>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace mcadsw {

namespace {

constexpr int kSgbmBlock = 5;  // SGBM matching block (odd); P1/P2 as OpenCV's sample
constexpr int kBmBlock = 9;    // StereoBM block (odd, >= 5)

int search_range(int d) { return (d + 15) / 16 * 16; }

cv::Ptr<cv::StereoMatcher> make_matcher(Baseline b, int d) {
  const int n = search_range(d);
  if (b == Baseline::kBm) {
    auto bm = cv::StereoBM::create(n, kBmBlock);
    bm->setTextureThreshold(0);
    bm->setUniquenessRatio(0);
    bm->setSpeckleWindowSize(0);
    bm->setDisp12MaxDiff(-1);
    return bm;
  }
  const int area = 3 * kSgbmBlock * kSgbmBlock;  // 3 channels
  const int mode = b == Baseline::kSgbmHH ? cv::StereoSGBM::MODE_HH : cv::StereoSGBM::MODE_SGBM_3WAY;
  if (b == Baseline::kSgbmLr)
    return cv::StereoSGBM::create(0, n, kSgbmBlock, 8 * area, 32 * area, /*disp12MaxDiff=*/1,
                                  /*preFilterCap=*/63, /*uniquenessRatio=*/10,
                                  /*speckleWindowSize=*/100, /*speckleRange=*/2, mode);
  return cv::StereoSGBM::create(0, n, kSgbmBlock, 8 * area, 32 * area, /*disp12MaxDiff=*/-1,
                                /*preFilterCap=*/63, /*uniquenessRatio=*/0,
                                /*speckleWindowSize=*/0, /*speckleRange=*/0, mode);
}

}  // namespace

const char* baseline_name(Baseline b) {
  switch (b) {
    case Baseline::kSgbm3Way: return "OpenCV SGBM 3WAY";
    case Baseline::kSgbmHH: return "OpenCV SGBM HH";
    case Baseline::kBm: return "OpenCV BM";
    case Baseline::kSgbmLr: return "OpenCV SGBM 3WAY + LR check";
  }
  return "?";
}

std::string baseline_params(Baseline b, int d) {
  const std::string range = "minDisparity 0, numDisparities " + std::to_string(search_range(d));
  if (b == Baseline::kBm)
    return range + ", blockSize " + std::to_string(kBmBlock) +
           ", grayscale input (BGR2GRAY), textureThreshold 0, uniquenessRatio 0, speckle filter off, "
           "disp12MaxDiff -1";
  const int area = 3 * kSgbmBlock * kSgbmBlock;
  const std::string common = range + ", blockSize " + std::to_string(kSgbmBlock) + ", P1 " +
                             std::to_string(8 * area) + ", P2 " + std::to_string(32 * area) +
                             ", colour input, preFilterCap 63";
  if (b == Baseline::kSgbmLr)
    return common + ", uniquenessRatio 10, speckleWindowSize 100, speckleRange 2, disp12MaxDiff 1";
  return common + ", uniquenessRatio 0, speckle filter off, disp12MaxDiff -1";
}

cv::Mat baseline_disparity16(Baseline b, const cv::Mat& left_bgr, const cv::Mat& right_bgr,
                             int d) {
  if (left_bgr.type() != CV_8UC3 || right_bgr.type() != CV_8UC3)
    throw std::invalid_argument("baseline views must be 8-bit BGR");
  if (left_bgr.size() != right_bgr.size() || left_bgr.empty())
    throw std::invalid_argument("baseline views must be non-empty and of one size");
  if (d < 1 || d > 255) throw std::invalid_argument("baseline D must be in 1..255");
  const int pad = search_range(d);
  cv::Mat l, r;
  cv::copyMakeBorder(left_bgr, l, 0, 0, pad, 0, cv::BORDER_REPLICATE);
  cv::copyMakeBorder(right_bgr, r, 0, 0, pad, 0, cv::BORDER_REPLICATE);
  if (b == Baseline::kBm) {
    cv::cvtColor(l, l, cv::COLOR_BGR2GRAY);
    cv::cvtColor(r, r, cv::COLOR_BGR2GRAY);
  }
  cv::Mat raw;  // CV_16S, disparity * 16, invalid < 0
  make_matcher(b, d)->compute(l, r, raw);
  raw = raw(cv::Rect(pad, 0, left_bgr.cols, left_bgr.rows));

  cv::Mat out(raw.size(), CV_16UC1);
  const int top = 16 * (d - 1);
  for (int y = 0; y < raw.rows; ++y) {
    const int16_t* s = raw.ptr<int16_t>(y);
    uint16_t* o = out.ptr<uint16_t>(y);
    int first_valid = -1;
    for (int x = 0; x < raw.cols; ++x) {
      if (s[x] >= 0) {
        first_valid = x;
        break;
      }
    }
    int last = 0;
    if (first_valid >= 0) last = std::min<int>(s[first_valid], top);
    for (int x = 0; x < raw.cols; ++x) {
      if (s[x] >= 0) last = std::min<int>(s[x], top);
      o[x] = uint16_t(last);
    }
  }
  return out;
}

cv::Mat baseline_disparity(Baseline b, const cv::Mat& left_bgr, const cv::Mat& right_bgr,
                           int d) {
  const cv::Mat s = baseline_disparity16(b, left_bgr, right_bgr, d);
  cv::Mat out(s.size(), CV_8UC1);
  for (int y = 0; y < s.rows; ++y)
    for (int x = 0; x < s.cols; ++x) out.at<uint8_t>(y, x) = uint8_t(std::min((s.at<uint16_t>(y, x) + 8) >> 4, d - 1));
  return out;
}

}  // namespace mcadsw
