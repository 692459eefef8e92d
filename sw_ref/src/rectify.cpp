// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

#include "mcadsw/rectify.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <climits>
#include <limits>
#include <stdexcept>
#include <string>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "mcadsw/image_io.hpp"
#include "mcadsw/params.hpp"

namespace mcadsw {

namespace {
int nodes_for(int size, int step_log2) { return ((size - 1) >> step_log2) + 2; }
}  // namespace

Mesh make_mesh(int out_width, int out_height, int step_log2) {
  if (step_log2 < kMeshStepLog2Min || step_log2 > kMeshStepLog2Max)
    throw std::invalid_argument("mesh step 2^" + std::to_string(step_log2) + ": must be 8, 16 or 32");
  if (out_width < 1 || out_width > kMaxWidth || out_height < 1 || out_height > kMaxHeight)
    throw std::invalid_argument("mesh for a " + std::to_string(out_width) + "x" + std::to_string(out_height) +
                                " frame: each side 1.." + std::to_string(kMaxWidth));
  Mesh m;
  m.step_log2 = step_log2;
  m.out_width = out_width;
  m.out_height = out_height;
  m.nx = nodes_for(out_width, step_log2);
  m.ny = nodes_for(out_height, step_log2);
  m.u.assign(size_t(m.nx) * size_t(m.ny), 0);
  m.v.assign(m.u.size(), 0);
  return m;
}

void check_mesh(const Mesh& m) {
  const Mesh shape = make_mesh(m.out_width, m.out_height, m.step_log2);  // throws on size / step
  if (m.nx != shape.nx || m.ny != shape.ny || m.u.size() != shape.u.size() || m.v.size() != shape.u.size())
    throw std::invalid_argument("mesh of " + std::to_string(m.nx) + "x" + std::to_string(m.ny) +
                                " nodes for a " + std::to_string(m.out_width) + "x" +
                                std::to_string(m.out_height) + " frame at step " + std::to_string(m.step()) +
                                ": it needs " + std::to_string(shape.nx) + "x" + std::to_string(shape.ny));
  for (size_t k = 0; k < m.u.size(); ++k)
    for (const int32_t c : {m.u[k], m.v[k]})
      if (c < -kMeshCoordLimit || c >= kMeshCoordLimit)
        throw std::invalid_argument("mesh node (" + std::to_string(k % size_t(m.nx)) + ", " +
                                    std::to_string(k / size_t(m.nx)) + ") at " + std::to_string(c) +
                                    "/32 pixel: outside -4096 .. 4096 pixels");
}

std::pair<int32_t, int32_t> mesh_position(const Mesh& m, int x, int y) {
  const int s = m.step_log2, S = 1 << s;
  const int cx = x >> s, cy = y >> s, ox = x & (S - 1), oy = y & (S - 1);
  const size_t n00 = size_t(cy) * size_t(m.nx) + size_t(cx), n10 = n00 + 1, n01 = n00 + size_t(m.nx),
               n11 = n01 + 1;
  const int64_t w00 = int64_t(S - ox) * (S - oy), w10 = int64_t(ox) * (S - oy), w01 = int64_t(S - ox) * oy,
                w11 = int64_t(ox) * oy;
  const auto interp = [&](const std::vector<int32_t>& n) {
    const int64_t sum = w00 * n[n00] + w10 * n[n10] + w01 * n[n01] + w11 * n[n11];
    return int32_t((sum + (int64_t(1) << (2 * s - 1))) >> (2 * s));  // round half up
  };
  return {interp(m.u), interp(m.v)};
}

std::vector<uint32_t> validity_bitmap(const Plane& valid) {
  const int vh = (valid.height + 7) / 8, nk = (valid.width + 3) / 4;
  std::vector<uint32_t> words(size_t(nk * vh), 0u);
  for (int y = 0; y < valid.height; ++y)
    for (int x = 0; x < valid.width; ++x)
      if (valid.at(x, y)) words[size_t((x / 4) * vh + y / 8)] |= 1u << (4 * (y % 8) + x % 4);
  return words;
}

Rectified rectify(const YuvImage& raw, const Mesh& m) {
  check_mesh(m);
  const int wr = raw.width(), hr = raw.height();
  if (wr < 1 || hr < 1) throw std::invalid_argument("rectify: empty raw view");
  Rectified r{YuvImage{Plane(m.out_width, m.out_height, kRectInvalidY), Plane(m.out_width, m.out_height, kRectInvalidUV),
                       Plane(m.out_width, m.out_height, kRectInvalidUV)},
              Plane(m.out_width, m.out_height, 0)};
  const int32_t one = 1 << kMeshFracBits, mask = one - 1;
  for (int y = 0; y < m.out_height; ++y)
    for (int x = 0; x < m.out_width; ++x) {
      const auto [pu, pv] = mesh_position(m, x, y);
      if (pu < 0 || pu > one * (wr - 1) || pv < 0 || pv > one * (hr - 1)) continue;  // invalid
      const int ui = pu >> kMeshFracBits, vi = pv >> kMeshFracBits, fu = pu & mask, fv = pv & mask;
      const int u1 = std::min(ui + 1, wr - 1), v1 = std::min(vi + 1, hr - 1);
      const auto sample = [&](const Plane& p) {
        const int sum = (one - fu) * (one - fv) * p.at(ui, vi) + fu * (one - fv) * p.at(u1, vi) +
                        (one - fu) * fv * p.at(ui, v1) + fu * fv * p.at(u1, v1);
        return uint8_t((sum + (1 << (2 * kMeshFracBits - 1))) >> (2 * kMeshFracBits));
      };
      r.image.y.at(x, y) = sample(raw.y);
      r.image.u.at(x, y) = sample(raw.u);
      r.image.v.at(x, y) = sample(raw.v);
      r.valid.at(x, y) = 1;
    }
  return r;
}

bool TileSource::fits() const { return empty || (cols <= kRectBufW && rows <= kRectBufH); }

TileSource tile_source(const Mesh& m, int a, int b, int raw_w, int raw_h) {
  const int x_first = a * kRectTileW, y_first = b * kRectTileH;
  if (a < 0 || b < 0 || x_first >= m.out_width || y_first >= m.out_height)
    throw std::invalid_argument("tile_source: tile (" + std::to_string(a) + ", " + std::to_string(b) +
                                ") outside the frame");
  const int xl = std::min(x_first + kRectTileW - 1, m.out_width - 1);
  const int yl = std::min(y_first + kRectTileH - 1, m.out_height - 1);
  TileSource t;
  t.node_i0 = x_first >> m.step_log2;
  t.node_i1 = (xl >> m.step_log2) + 1;
  t.node_j0 = y_first >> m.step_log2;
  t.node_j1 = (yl >> m.step_log2) + 1;
  // The box in 1/64 pixel (section 13.8): twice each node, except at a step larger
  // than the tile's height, where the tile holds half a cell row and the box is over its
  // top and bottom edges: a node of the cell row's near edge, and the midpoint of the
  // node column's two nodes (their sum in 1/64 pixel) at the tile's other edge.
  const bool half = (1 << m.step_log2) > kRectTileH;
  const bool lower = half && (y_first & ((1 << m.step_log2) - 1)) != 0;  // the cell row's lower half
  int64_t umin = INT64_MAX, umax = INT64_MIN, vmin = INT64_MAX, vmax = INT64_MIN;
  auto take = [&](int64_t u64, int64_t v64) {
    umin = std::min(umin, u64);
    umax = std::max(umax, u64);
    vmin = std::min(vmin, v64);
    vmax = std::max(vmax, v64);
  };
  for (int j = t.node_j0; j <= t.node_j1; ++j)
    for (int i = t.node_i0; i <= t.node_i1; ++i) {
      const size_t k = size_t(j) * size_t(m.nx) + size_t(i);
      if (!half || (j == t.node_j0) == !lower) take(2 * int64_t(m.u[k]), 2 * int64_t(m.v[k]));
      if (half && j == t.node_j1) {
        const size_t k0 = size_t(t.node_j0) * size_t(m.nx) + size_t(i);
        take(int64_t(m.u[k0]) + m.u[k], int64_t(m.v[k0]) + m.v[k]);
      }
    }
  // Floor of the smallest, ceiling of the largest, in 1/32 pixel: every rounded position
  // (13.2, round half up) of a pixel of the tile lies between them.
  t.umin = int32_t(umin >> 1);
  t.umax = int32_t((umax + 1) >> 1);
  t.vmin = int32_t(vmin >> 1);
  t.vmax = int32_t((vmax + 1) >> 1);
  const int xf = std::max(0, t.umin >> kMeshFracBits), xt = std::min(raw_w - 1, (t.umax >> kMeshFracBits) + 1);
  const int yf = std::max(0, t.vmin >> kMeshFracBits), yt = std::min(raw_h - 1, (t.vmax >> kMeshFracBits) + 1);
  t.empty = xf > xt || yf > yt;
  if (!t.empty) {
    t.x0 = xf & ~3;
    t.y0 = yf;
    t.cols = xt - t.x0 + 1;
    t.rows = yt - t.y0 + 1;
  }
  return t;
}

int rect_check(const RectCheck& c) {
  // The regions of docs/blocks/rectifier.md 2: base, bytes, enabled, kind (0 read,
  // 1 write, 2 bitmap).
  const int views = ((c.planes & 7) != 0 ? 1 : 0) | ((c.planes & 070) != 0 ? 2 : 0);
  const uint64_t raw_size =
      uint64_t(c.raw_stride) * uint64_t(c.tiled ? (c.raw_width + 3) / 4 : c.raw_height);
  const uint64_t mesh_size = 8 * uint64_t(c.mesh_nx) * uint64_t(c.mesh_ny);
  const uint64_t bm_size = 4 * uint64_t((c.width + 3) / 4) * uint64_t((c.height + 7) / 8);
  struct Region {
    uint64_t base, size;
    bool en;
    int kind;
  };
  std::vector<Region> r;
  for (int p = 0; p < 6; ++p) r.push_back({c.raw_base[p], raw_size, (c.planes >> p & 1) != 0, 0});
  for (int v = 0; v < 2; ++v) r.push_back({c.mesh_base[v], mesh_size, (views >> v & 1) != 0, 0});
  for (int p = 0; p < 6; ++p) r.push_back({c.rect_base[p], c.rect_size, (c.planes >> p & 1) != 0, 1});
  for (int v = 0; v < 2; ++v) r.push_back({c.valid_base[v], bm_size, (views >> v & 1) != 0, 2});
  for (int k = 0; k < 4; ++k) r.push_back({c.out_base[k], c.out_size[k], (c.outs >> k & 1) != 0, 1});
  bool align = false, overlap = false, beyond = false;
  for (size_t i = 0; i < r.size(); ++i) {
    if (!r[i].en) continue;
    if (r[i].kind != 1) {  // the rectifier's own regions: raw planes, meshes, bitmaps
      align = align || (r[i].base & 3) != 0;
      beyond = beyond || r[i].base + r[i].size > (uint64_t(1) << 32);
    }
    for (size_t j = i + 1; j < r.size(); ++j)
      if (r[j].en && !(r[i].kind == 0 && r[j].kind == 0) && !(r[i].kind == 1 && r[j].kind == 1))
        overlap = overlap || (r[i].base < r[j].base + r[j].size && r[j].base < r[i].base + r[i].size);
  }
  const int s = c.step_log2;
  const bool step_ok = s >= kMeshStepLog2Min && s <= kMeshStepLog2Max;
  if (!step_ok) return 1;
  const bool raw_bad = c.raw_width == 0 || c.raw_width > kMaxWidth || c.raw_height == 0 ||
                       c.raw_height > kMaxHeight || (c.raw_stride & 3) != 0 ||
                       (c.tiled ? uint64_t(c.raw_stride) < 4 * uint64_t(c.raw_height)
                                : uint64_t(c.raw_stride) < uint64_t(c.raw_width));
  if (raw_bad) return 2;
  if (c.mesh_nx != ((c.width - 1) >> s) + 2 || c.mesh_ny != ((c.height - 1) >> s) + 2) return 3;
  if (align) return 4;
  if (overlap) return 5;
  if (beyond) return 6;
  return 0;
}

void check_rect_footprints(const Mesh& m, int raw_w, int raw_h) {
  check_mesh(m);
  for (int b = 0; b * kRectTileH < m.out_height; ++b)
    for (int a = 0; a * kRectTileW < m.out_width; ++a) {
      const TileSource t = tile_source(m, a, b, raw_w, raw_h);
      if (!t.fits())
        throw std::invalid_argument("mesh: the source of output tile (" + std::to_string(a) + ", " +
                                    std::to_string(b) + ") is " + std::to_string(t.cols) + "x" +
                                    std::to_string(t.rows) + " raw pixels, beyond the engine's " +
                                    std::to_string(kRectBufW) + "x" + std::to_string(kRectBufH));
    }
}

Mesh mesh_from_maps(const cv::Mat& map_x, const cv::Mat& map_y, int out_width, int out_height, int step_log2) {
  Mesh m = make_mesh(out_width, out_height, step_log2);
  const int need_w = (m.nx - 1) * m.step() + 1, need_h = (m.ny - 1) * m.step() + 1;
  for (const cv::Mat* map : {&map_x, &map_y})
    if (map->type() != CV_32FC1 || map->cols < need_w || map->rows < need_h)
      throw std::invalid_argument("mesh_from_maps: the maps must be CV_32FC1 of at least " + std::to_string(need_w) +
                                  "x" + std::to_string(need_h) + " pixels");
  for (int j = 0; j < m.ny; ++j)
    for (int i = 0; i < m.nx; ++i) {
      const float fx = map_x.at<float>(j * m.step(), i * m.step()), fy = map_y.at<float>(j * m.step(), i * m.step());
      if (!std::isfinite(fx) || !std::isfinite(fy))
        throw std::invalid_argument("mesh_from_maps: a non-finite map value at node (" + std::to_string(i) + ", " +
                                    std::to_string(j) + ")");
      const double lim = 2.0 * kMeshCoordLimit;  // far outside: no int overflow in the rounding
      const double su = double(fx) * (1 << kMeshFracBits), sv = double(fy) * (1 << kMeshFracBits);
      const int32_t u = std::abs(su) < lim ? int32_t(cvRound(su)) : kMeshCoordLimit,
                    v = std::abs(sv) < lim ? int32_t(cvRound(sv)) : kMeshCoordLimit;
      if (u < -kMeshCoordLimit || u >= kMeshCoordLimit || v < -kMeshCoordLimit || v >= kMeshCoordLimit)
        throw std::invalid_argument("mesh_from_maps: node (" + std::to_string(i) + ", " + std::to_string(j) +
                                    ") outside -4096 .. 4096 pixels");
      m.u[size_t(j) * size_t(m.nx) + size_t(i)] = u;
      m.v[size_t(j) * size_t(m.nx) + size_t(i)] = v;
    }
  return m;
}

Rectified remap_with_opencv(const YuvImage& raw, const cv::Mat& mx, const cv::Mat& my, int interpolation) {
  Rectified r;
  const Plane* in[3] = {&raw.y, &raw.u, &raw.v};
  Plane* out[3] = {&r.image.y, &r.image.u, &r.image.v};
  for (int c = 0; c < 3; ++c) {
    const cv::Mat src(raw.height(), raw.width(), CV_8UC1, const_cast<uint8_t*>(in[c]->px.data()));
    cv::Mat dst;
    cv::remap(src, dst, mx, my, interpolation, cv::BORDER_REPLICATE);
    *out[c] = from_mat(dst);
  }
  const cv::Mat valid = (mx >= 0) & (mx <= raw.width() - 1) & (my >= 0) & (my <= raw.height() - 1);
  r.valid = from_mat(valid / 255);
  for (size_t i = 0; i < r.valid.px.size(); ++i)
    if (!r.valid.px[i]) {
      r.image.y.px[i] = kRectInvalidY;
      r.image.u.px[i] = r.image.v.px[i] = kRectInvalidUV;
    }
  return r;
}

RectifyAgreement compare_with_opencv(const YuvImage& raw, const Mesh& m, const cv::Matx33d& k, const cv::Mat& d,
                                     const cv::Matx33d& r, const cv::Matx34d& p) {
  const Rectified mine = rectify(raw, m);
  cv::Mat mx, my;
  cv::initUndistortRectifyMap(cv::Mat(k), d, cv::Mat(r), cv::Mat(p), cv::Size(m.out_width, m.out_height), CV_32FC1,
                              mx, my);
  const Rectified theirs = remap_with_opencv(raw, mx, my, cv::INTER_LINEAR);
  RectifyAgreement a;
  double sq = 0;
  const Plane* mine_planes[3] = {&mine.image.y, &mine.image.u, &mine.image.v};
  const Plane* their_planes[3] = {&theirs.image.y, &theirs.image.u, &theirs.image.v};
  for (int y = 0; y < m.out_height; ++y)
    for (int x = 0; x < m.out_width; ++x) {
      const auto [pu, pv] = mesh_position(m, x, y);
      a.mesh_deviation = std::max({a.mesh_deviation, std::abs(pu / 32.0 - double(mx.at<float>(y, x))),
                                   std::abs(pv / 32.0 - double(my.at<float>(y, x)))});
      if (!mine.valid.at(x, y) || !theirs.valid.at(x, y)) continue;
      ++a.valid;
      for (int c = 0; c < 3; ++c) {
        const double e = double(mine_planes[c]->at(x, y)) - double(their_planes[c]->at(x, y));
        sq += e * e;
      }
    }
  const double mse = a.valid ? sq / (3.0 * double(a.valid)) : 0.0;
  a.psnr = mse > 0 ? 10 * std::log10(255.0 * 255.0 / mse) : std::numeric_limits<double>::infinity();
  return a;
}

// ---- Calibration files and mesh images ------------------------------------------------------
namespace {

[[noreturn]] void calib_fail(const std::string& path, const std::string& what) {
  throw std::invalid_argument("calibration " + path + ": " + what);
}

cv::Mat read_key(const cv::FileStorage& fs, const std::string& path, const char* key, int rows, int cols) {
  const cv::FileNode n = fs[key];
  if (n.empty()) calib_fail(path, std::string("no key ") + key);
  cv::Mat m;
  n >> m;
  if (m.empty()) calib_fail(path, std::string(key) + " is not a matrix");
  m.convertTo(m, CV_64F);
  if (rows > 0 && (m.rows != rows || m.cols != cols))
    calib_fail(path, std::string(key) + " is " + std::to_string(m.rows) + "x" + std::to_string(m.cols) + ", not " +
                         std::to_string(rows) + "x" + std::to_string(cols));
  if (!cv::checkRange(m)) calib_fail(path, std::string(key) + " has a value that is not finite");
  return m;
}

cv::Mat read_dist(const cv::FileStorage& fs, const std::string& path, const char* key) {
  cv::Mat d = read_key(fs, path, key, 0, 0);
  const int n = int(d.total());
  if (!(d.rows == 1 || d.cols == 1) || !(n == 4 || n == 5 || n == 8 || n == 12 || n == 14))
    calib_fail(path, std::string(key) + " must hold 4, 5, 8, 12 or 14 distortion coefficients");
  return d.reshape(1, 1);
}

int read_int(const cv::FileStorage& fs, const std::string& path, const char* key) {
  const cv::FileNode n = fs[key];
  if (n.empty()) calib_fail(path, std::string("no key ") + key);
  if (!n.isInt()) calib_fail(path, std::string(key) + " is not an integer");
  return int(n);
}

}  // namespace

StereoRectification read_calibration(const std::string& path) {
  cv::FileStorage fs;
  try {
    fs.open(path, cv::FileStorage::READ);
  } catch (const cv::Exception& e) {
    calib_fail(path, std::string("not a YAML or XML file (") + e.what() + ")");
  }
  if (!fs.isOpened()) calib_fail(path, "cannot open it");
  StereoRectification r;
  r.size = cv::Size(read_int(fs, path, "image_width"), read_int(fs, path, "image_height"));
  if (r.size.width < 1 || r.size.width > kMaxWidth || r.size.height < 1 || r.size.height > kMaxHeight)
    calib_fail(path, "image size " + std::to_string(r.size.width) + "x" + std::to_string(r.size.height) +
                         " outside 1.." + std::to_string(kMaxWidth));
  r.k1 = cv::Matx33d(read_key(fs, path, "K1", 3, 3));
  r.k2 = cv::Matx33d(read_key(fs, path, "K2", 3, 3));
  r.d1 = read_dist(fs, path, "D1");
  r.d2 = read_dist(fs, path, "D2");
  if (!fs["R1"].empty() || !fs["P1"].empty()) {  // the rectification itself
    r.r1 = cv::Matx33d(read_key(fs, path, "R1", 3, 3));
    r.r2 = cv::Matx33d(read_key(fs, path, "R2", 3, 3));
    r.p1 = cv::Matx34d(read_key(fs, path, "P1", 3, 4));
    r.p2 = cv::Matx34d(read_key(fs, path, "P2", 3, 4));
    return r;
  }
  const cv::Mat rot = read_key(fs, path, "R", 3, 3), t = read_key(fs, path, "T", 3, 1);
  cv::Mat r1, r2, p1, p2, q;
  cv::stereoRectify(cv::Mat(r.k1), r.d1, cv::Mat(r.k2), r.d2, r.size, rot, t, r1, r2, p1, p2, q,
                    cv::CALIB_ZERO_DISPARITY, 0.0);
  r.r1 = cv::Matx33d(r1);
  r.r2 = cv::Matx33d(r2);
  r.p1 = cv::Matx34d(p1);
  r.p2 = cv::Matx34d(p2);
  return r;
}

std::pair<Mesh, Mesh> meshes_from_rectification(const StereoRectification& r, int out_width, int out_height,
                                                int step_log2) {
  const Mesh shape = make_mesh(out_width, out_height, step_log2);
  const cv::Size cover((shape.nx - 1) * shape.step() + 1, (shape.ny - 1) * shape.step() + 1);
  cv::Mat mx, my;
  cv::initUndistortRectifyMap(cv::Mat(r.k1), r.d1, cv::Mat(r.r1), cv::Mat(r.p1), cover, CV_32FC1, mx, my);
  Mesh left = mesh_from_maps(mx, my, out_width, out_height, step_log2);
  cv::initUndistortRectifyMap(cv::Mat(r.k2), r.d2, cv::Mat(r.r2), cv::Mat(r.p2), cover, CV_32FC1, mx, my);
  return {std::move(left), mesh_from_maps(mx, my, out_width, out_height, step_log2)};
}

void write_meshes(const std::string& path, const Mesh& left, const Mesh& right) {
  check_mesh(left);
  check_mesh(right);
  std::ofstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error("cannot write " + path);
  for (const Mesh* m : {&left, &right})
    for (size_t k = 0; k < m->u.size(); ++k)
      for (const int32_t c : {m->u[k], m->v[k]}) {
        const uint32_t w = uint32_t(c);
        const char b[4] = {char(w & 0xff), char(w >> 8 & 0xff), char(w >> 16 & 0xff), char(w >> 24 & 0xff)};
        f.write(b, 4);
      }
  if (!f) throw std::runtime_error("write failed: " + path);
}

std::pair<Mesh, Mesh> read_meshes(const std::string& path, int out_width, int out_height, int step_log2) {
  Mesh left = make_mesh(out_width, out_height, step_log2), right = left;
  std::ifstream f(path, std::ios::binary | std::ios::ate);
  if (!f) throw std::invalid_argument("mesh " + path + ": cannot open it");
  const long long want = 2LL * 2 * 4 * (long long)left.u.size(), got = (long long)f.tellg();
  if (got != want)
    throw std::invalid_argument("mesh " + path + ": " + std::to_string(got) + " bytes; a " +
                                std::to_string(out_width) + "x" + std::to_string(out_height) + " frame at step " +
                                std::to_string(left.step()) + " needs " + std::to_string(want));
  f.seekg(0);
  for (Mesh* m : {&left, &right})
    for (size_t k = 0; k < m->u.size(); ++k)
      for (int32_t* c : {&m->u[k], &m->v[k]}) {
        unsigned char b[4];
        f.read(reinterpret_cast<char*>(b), 4);
        *c = int32_t(uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24);
      }
  check_mesh(left);
  check_mesh(right);
  return {std::move(left), std::move(right)};
}

}  // namespace mcadsw
