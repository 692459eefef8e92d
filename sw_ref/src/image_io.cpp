// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

#include "mcadsw/image_io.hpp"

#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace mcadsw {

cv::Mat read_color_image(const std::string& path) {
  if (!std::filesystem::is_regular_file(path))
    throw std::runtime_error("cannot open '" + path + "': no such file");
  cv::Mat img = cv::imread(path, cv::IMREAD_UNCHANGED);
  if (img.empty())
    throw std::runtime_error("cannot read '" + path + "': not an image OpenCV can decode");
  if (img.depth() != CV_8U)
    throw std::runtime_error("'" + path + "' is not an 8-bit image");
  if (img.channels() == 1 || img.channels() == 2)
    throw std::runtime_error("'" + path +
                             "' is grayscale; the weight generator needs a colour (3-channel) image");
  if (img.channels() == 4) cv::cvtColor(img, img, cv::COLOR_BGRA2BGR);
  return img;
}

Plane from_mat(const cv::Mat& gray8) {
  CV_Assert(gray8.type() == CV_8UC1);
  Plane p(gray8.cols, gray8.rows);
  for (int y = 0; y < gray8.rows; ++y)
    std::copy_n(gray8.ptr<uint8_t>(y), gray8.cols, &p.px[size_t(y) * p.width]);
  return p;
}

cv::Mat to_mat(const Plane& p) {
  cv::Mat m(p.height, p.width, CV_8UC1);
  for (int y = 0; y < p.height; ++y)
    std::copy_n(&p.px[size_t(y) * p.width], p.width, m.ptr<uint8_t>(y));
  return m;
}

YuvImage to_yuv(const cv::Mat& bgr) {
  CV_Assert(bgr.type() == CV_8UC3);
  cv::Mat yuv;
  cv::cvtColor(bgr, yuv, cv::COLOR_BGR2YUV);
  cv::Mat planes[3];
  cv::split(yuv, planes);
  return YuvImage{from_mat(planes[0]), from_mat(planes[1]), from_mat(planes[2])};
}

YuvImage crop(const YuvImage& img, int x0, int y0, int w, int h) {
  YuvImage c{Plane(w, h), Plane(w, h), Plane(w, h)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      c.y.at(x, y) = img.y.clamped(x0 + x, y0 + y);
      c.u.at(x, y) = img.u.clamped(x0 + x, y0 + y);
      c.v.at(x, y) = img.v.clamped(x0 + x, y0 + y);
    }
  return c;
}

YuvImage load_yuv(const std::string& path) { return to_yuv(read_color_image(path)); }

std::string colormap_path_for(const std::string& path) {
  std::filesystem::path p(path);
  return (p.parent_path() / (p.stem().string() + "_color" + p.extension().string())).string();
}

namespace {

// Writes `raw` (8 or 16 bits) and its colour view (raw * scale, JET; black where raw
// holds the invalid code of a rectified frame, docs/algorithm.md 13.4), both or neither.
void write_map(const cv::Mat& raw, double scale, int invalid_code, const std::string& path,
               const std::string& colormap_path) {
  cv::Mat scaled, color;
  raw.convertTo(scaled, CV_8U, scale);
  cv::applyColorMap(scaled, color, cv::COLORMAP_JET);
  color.setTo(cv::Scalar::all(0), raw == invalid_code);
  bool ok = false;
  try {
    ok = cv::imwrite(path, raw) && cv::imwrite(colormap_path, color);
  } catch (const cv::Exception&) {
    ok = false;
  }
  if (!ok) {
    std::remove(path.c_str());
    std::remove(colormap_path.c_str());
    throw std::runtime_error("cannot write '" + path + "' / '" + colormap_path + "'");
  }
}

}  // namespace

void write_disparity(const Plane& disp, int disparities, const std::string& path,
                     const std::string& colormap_path) {
  write_map(to_mat(disp), disparities > 1 ? 255.0 / (disparities - 1) : 0.0, kRectInvalidDisp8, path,
            colormap_path);
}

cv::Mat to_mat(const Plane16& p) {
  cv::Mat m(p.height, p.width, CV_16UC1);
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) m.at<uint16_t>(y, x) = p.at(x, y);
  return m;
}

void write_disparity16(const Plane16& disp, int disparities, const std::string& path,
                       const std::string& colormap_path) {
  write_map(to_mat(disp), disparities > 1 ? 255.0 / (kSubpixelScale * (disparities - 1)) : 0.0,
            kRectInvalidDisp16, path, colormap_path);
}

void write_mask(const Plane& mask, const std::string& path) {
  bool ok = false;
  try {
    ok = cv::imwrite(path, to_mat(mask));
  } catch (const cv::Exception&) {
    ok = false;
  }
  if (!ok) {
    std::remove(path.c_str());
    throw std::runtime_error("cannot write '" + path + "'");
  }
}

}  // namespace mcadsw
