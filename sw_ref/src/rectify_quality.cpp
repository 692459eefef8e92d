// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

#include "mcadsw/rectify_quality.hpp"

#include <filesystem>
#include <stdexcept>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "mcadsw/eval.hpp"
#include "mcadsw/image_io.hpp"
#include "mcadsw/rectify.hpp"

namespace mcadsw {
namespace {

namespace fs = std::filesystem;

using View = Rectified;  // image and validity (1 valid)

Plane match_lr(const View& left, const View& right, int disparities, int tolerance, bool use_valid) {
  Config cfg;
  cfg.disparities = disparities;
  DepthOptions opt;
  opt.lr = true;
  opt.tolerance = tolerance;
  if (use_valid) {
    opt.left_valid = left.valid;
    opt.right_valid = right.valid;
  }
  return depth_map(left.image, right.image, cfg, opt).disp8();
}

cv::Mat read_mask(const fs::path& p) {
  cv::Mat m = cv::imread(p.string(), cv::IMREAD_GRAYSCALE);
  if (m.empty()) throw std::runtime_error("cannot read " + p.string());
  return m;
}

}  // namespace

RectificationQuality rectification_quality(const std::string& raw_dir, const std::string& bundled_dir,
                                           int disparities, double gt_scale, int step_log2, int tolerance) {
  const fs::path raw(raw_dir), bundled(bundled_dir);
  const StereoRectification cal = read_calibration((raw / "calib.yml").string());
  const YuvImage raws[2] = {load_yuv((raw / "left.png").string()), load_yuv((raw / "right.png").string())};
  for (const YuvImage& r : raws)
    if (r.width() != cal.size.width || r.height() != cal.size.height)
      throw std::runtime_error(raw_dir + ": the views are not the calibration's size");
  const View undistorted[2] = {{load_yuv((bundled / "left.png").string()), {}},
                               {load_yuv((bundled / "right.png").string()), {}}};

  // The mesh, as the engine does it.
  const auto meshes = meshes_from_rectification(cal, cal.size.width, cal.size.height, step_log2);
  View mesh[2];
  for (int v = 0; v < 2; ++v) {
    Rectified r = rectify(raws[v], v == 0 ? meshes.first : meshes.second);
    mesh[v] = std::move(r);
  }
  // OpenCV's float maps, three filters.
  cv::Mat mx[2], my[2];
  cv::initUndistortRectifyMap(cv::Mat(cal.k1), cal.d1, cv::Mat(cal.r1), cv::Mat(cal.p1), cal.size, CV_32FC1, mx[0],
                              my[0]);
  cv::initUndistortRectifyMap(cv::Mat(cal.k2), cal.d2, cv::Mat(cal.r2), cv::Mat(cal.p2), cal.size, CV_32FC1, mx[1],
                              my[1]);
  const int filters[3] = {cv::INTER_LINEAR, cv::INTER_CUBIC, cv::INTER_LANCZOS4};
  View cv_views[3][2];
  for (int f = 0; f < 3; ++f)
    for (int v = 0; v < 2; ++v) cv_views[f][v] = remap_with_opencv(raws[v], mx[v], my[v], filters[f]);

  const cv::Mat maps[5] = {to_mat(match_lr(undistorted[0], undistorted[1], disparities, tolerance, false)),
                           to_mat(match_lr(mesh[0], mesh[1], disparities, tolerance, true)),
                           to_mat(match_lr(cv_views[0][0], cv_views[0][1], disparities, tolerance, true)),
                           to_mat(match_lr(cv_views[1][0], cv_views[1][1], disparities, tolerance, true)),
                           to_mat(match_lr(cv_views[2][0], cv_views[2][1], disparities, tolerance, true))};

  // The same pixels for every map: "all", and valid in the mesh's and OpenCV's left view.
  cv::Mat all = read_mask(bundled / "all.png") == 255;
  all &= to_mat(mesh[0].valid) != 0;
  all &= to_mat(cv_views[0][0].valid) != 0;
  const cv::Mat gt = read_mask(bundled / "gt.png");
  if (gt.size() != cal.size || all.size() != cal.size)
    throw std::runtime_error(bundled_dir + ": ground truth and masks must be the calibration's size");
  const cv::Mat none = cv::Mat::zeros(gt.size(), CV_8UC1);
  double e[5];
  for (int k = 0; k < 5; ++k) e[k] = evaluate(maps[k], gt, gt_scale, none, all, none).all;
  RectificationQuality q;
  q.undistorted = e[0];
  q.mesh = e[1];
  q.opencv_linear = e[2];
  q.opencv_cubic = e[3];
  q.opencv_lanczos = e[4];
  q.pixels = cv::countNonZero(all);
  return q;
}

}  // namespace mcadsw
