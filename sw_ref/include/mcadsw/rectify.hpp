// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Rectification of raw camera frames (docs/algorithm.md section 13): a
// mesh of source positions every S output pixels, interpolated per pixel, and a
// bilinear sample with 5-bit weights. Integer arithmetic, bit-exact with the RTL.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "mcadsw/ref.hpp"

namespace mcadsw {

// Source positions in the raw view, in 1/32 pixel, at the output positions
// (i S, j S), S = 2^step_log2; node (i, j) at index j nx + i (section 13.1).
struct Mesh {
  int step_log2 = 4;
  int out_width = 0, out_height = 0;  // the rectified frame, W x H
  int nx = 0, ny = 0;                 // floor((W - 1) / S) + 2, likewise for H
  std::vector<int32_t> u, v;

  int step() const { return 1 << step_log2; }
};

// A mesh of W x H at step 2^step_log2 with every node at (0, 0); throws
// std::invalid_argument for a size or step out of range.
Mesh make_mesh(int out_width, int out_height, int step_log2);

// Throws std::invalid_argument (naming the node) unless the mesh is well formed:
// step 8, 16 or 32, node counts that match its size, every node in
// [-kMeshCoordLimit, kMeshCoordLimit).
void check_mesh(const Mesh& mesh);

// Source position of output pixel (x, y), in 1/32 pixel (section 13.2).
std::pair<int32_t, int32_t> mesh_position(const Mesh& mesh, int x, int y);

// The engine's limit (section 13.8): the source rectangle of output tile (a, b) of
// kRectTileW x kRectTileH pixels, from the bounding box of the tile's nodes (at a step
// larger than the tile's height, of its top and bottom edges interpolated), in a raw
// view of raw_w x raw_h. x0 is word-aligned; cols and rows count from (x0, y0).
struct TileSource {
  int node_i0 = 0, node_i1 = 0, node_j0 = 0, node_j1 = 0;  // the tile's nodes, inclusive
  int32_t umin = 0, umax = 0, vmin = 0, vmax = 0;          // the box, 1/32 pixel (13.8)
  bool empty = false;                                      // wholly outside the raw view
  int x0 = 0, y0 = 0, cols = 0, rows = 0;                  // the rectangle (when not empty)
  bool fits() const;                                       // empty, or cols <= 64 and rows <= 32
};
TileSource tile_source(const Mesh& mesh, int tile_a, int tile_b, int raw_w, int raw_h);
// Throws std::invalid_argument naming the first tile (row by row) whose source
// rectangle does not fit the engine's tile buffer.
void check_rect_footprints(const Mesh& mesh, int raw_w, int raw_h);

// The check of the rectification's configuration (docs/blocks/rectifier.md 2, register
// map 1.2 codes 16..21 = 15 + the result; rtl/rect/mcadsw_rect_check.sv): 0, or the first
// failing check: 1 step, 2 raw size, 3 mesh size, 4 align, 5 overlap, 6 beyond. Regions
// 0..5 raw planes, 6..7 meshes (read), 8..13 rectified planes, 16..19 output planes
// (written), 14..15 validity bitmaps; sizes exact in 64 bits.
struct RectCheck {
  int step_log2 = 4;
  int width = 0, height = 0;             // the rectified frame (the engine's, 1 .. 2048)
  int raw_width = 0, raw_height = 0;     // 0 .. 4095 (RAW_SIZE's 12-bit fields)
  uint32_t raw_stride = 0;
  bool tiled = false;                    // TILE_STRIDE not 0: raw planes column-tiled too
  int planes = 0;                        // bit p: plane p (LY LU LV RY RU RV) rectified
  uint32_t raw_base[6] = {}, rect_base[6] = {};
  uint64_t rect_size = 0;                // bytes of a rectified plane (the engine's input plane)
  uint32_t mesh_base[2] = {}, valid_base[2] = {};
  int mesh_nx = 0, mesh_ny = 0;          // MESH_NODES, 0 .. 4095
  uint32_t out_base[4] = {};
  uint64_t out_size[4] = {};
  int outs = 0;                          // bit k: output plane k written by the mode
};
int rect_check(const RectCheck& c);

// The rectified view (section 13.3): every plane of `raw` sampled at the mesh's
// positions; valid (1) where the position lies inside the raw view, else 0 and
// the pixel black (Y 0, U and V 128).
struct Rectified {
  YuvImage image;
  Plane valid;
};
Rectified rectify(const YuvImage& raw, const Mesh& mesh);

// The validity bitmap the hardware writes and its mark step reads (docs/blocks/rectifier.md
// section 1): one bit a pixel in strip order, word (x / 4) ceil(H / 8) + y / 8, bit
// 4 (y % 8) + x % 4, 1 valid; the bits of pixels outside the frame are 0.
std::vector<uint32_t> validity_bitmap(const Plane& valid);

// The mesh of OpenCV float maps (CV_32FC1, at least (nx - 1) S + 1 by (ny - 1) S + 1
// pixels, section 13.5): node (i, j) = cvRound(32 map(i S, j S)).
Mesh mesh_from_maps(const cv::Mat& map_x, const cv::Mat& map_y, int out_width, int out_height,
                    int step_log2);

}  // namespace mcadsw

namespace mcadsw {

// A stereo rectification as OpenCV describes it (docs/algorithm.md 13.5): per view
// the camera matrix K, the distortion D (OpenCV's order: k1 k2 p1 p2 [k3 ...]), the
// rectifying rotation R and the new projection P; `size` is the image size.
struct StereoRectification {
  cv::Matx33d k1, k2, r1, r2;
  cv::Mat d1, d2;
  cv::Matx34d p1, p2;
  cv::Size size;
};

// Reads a cv::FileStorage file (YAML or XML) with either K1 D1 K2 D2 R T and the image
// size (image_width, image_height), rectified by cv::stereoRectify (alpha 0, zero
// disparity), or the rectification K1 D1 R1 P1 K2 D2 R2 P2 with the size. Throws
// std::invalid_argument naming the file and the key: missing, wrong size, not finite.
StereoRectification read_calibration(const std::string& path);

// The two views' meshes of a rectification for a W x H rectified frame.
std::pair<Mesh, Mesh> meshes_from_rectification(const StereoRectification& rect, int out_width, int out_height,
                                                int step_log2);

// OpenCV's rectification of a raw view on float maps (CV_32FC1): cv::remap of its Y, U
// and V planes with `interpolation` (replicated border); valid where the map lies in the
// closed rectangle of the raw pixels' centres (as 13.3), and black there otherwise.
Rectified remap_with_opencv(const YuvImage& raw, const cv::Mat& map_x, const cv::Mat& map_y, int interpolation);

// How close the mesh rectification of one raw view comes to OpenCV's float one
// (reported by `mcadsw rectify`): cv::initUndistortRectifyMap (CV_32FC1) of
// (k, d, r, p) at the mesh's frame size against the mesh interpolated at every pixel,
// and cv::remap (INTER_LINEAR) of the raw Y, U and V planes on that float map against
// mcadsw::rectify, over the pixels both call valid.
struct RectifyAgreement {
  double mesh_deviation = 0;  // largest |mesh position - float map|, pixels (u or v)
  double psnr = 0;            // dB, 8-bit, Y U V planes together
  long long valid = 0;        // pixels valid for both
};
RectifyAgreement compare_with_opencv(const YuvImage& raw, const Mesh& mesh, const cv::Matx33d& k, const cv::Mat& d,
                                     const cv::Matx33d& r, const cv::Matx34d& p);

// The mesh memory image (13.1): the left view's nodes, then the right's, row by row,
// each u then v as 32-bit little-endian words. read_meshes checks the file's size.
void write_meshes(const std::string& path, const Mesh& left, const Mesh& right);
std::pair<Mesh, Mesh> read_meshes(const std::string& path, int out_width, int out_height, int step_log2);

}  // namespace mcadsw
