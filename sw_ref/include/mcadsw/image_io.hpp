// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Image input/output around the reference: OpenCV reads the files and performs
// the BGR -> YUV 4:4:4 conversion that, in a camera, the ISP would do before the
// data reaches the engine's external memory (docs/algorithm.md, "Input").
#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "mcadsw/ref.hpp"

namespace mcadsw {

// Reads an 8-bit colour image (3 channels, or 4 with alpha dropped). Throws
// std::runtime_error with a one-line message for a missing or unreadable file,
// a non-8-bit image or a grayscale image (the weight generator needs U and V).
cv::Mat read_color_image(const std::string& path);

// cv::cvtColor(bgr, COLOR_BGR2YUV), split into planes.
YuvImage to_yuv(const cv::Mat& bgr);
YuvImage load_yuv(const std::string& path);
// The w x h region at (x0, y0) of all three planes; coordinates outside the
// image take the nearest edge pixel.
YuvImage crop(const YuvImage& img, int x0, int y0, int w, int h);

cv::Mat to_mat(const Plane& p);  // CV_8UC1 copy
Plane from_mat(const cv::Mat& gray8);

// Raw 8-bit map (pixel value = disparity) and a colour-mapped view scaled by
// 255 / (D - 1), written to `path` and to `colormap_path`. Both or neither are
// left behind: on failure, whatever was written is removed and it throws.
void write_disparity(const Plane& disp, int disparities, const std::string& path,
                     const std::string& colormap_path);
// 16-bit map (value = 16 x disparity, docs/algorithm.md 12.6) and its colour view.
void write_disparity16(const Plane16& disp, int disparities, const std::string& path,
                       const std::string& colormap_path);
cv::Mat to_mat(const Plane16& p);  // CV_16UC1 copy
// 8-bit mask (validity: 255 / 0). Removes a partial file and throws on failure.
void write_mask(const Plane& mask, const std::string& path);
std::string colormap_path_for(const std::string& path);  // out.png -> out_color.png

}  // namespace mcadsw
