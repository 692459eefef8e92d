#include "mcadsw/rectify.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

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
      const double lim = double(kMeshCoordLimit) / (1 << kMeshFracBits);
      if (fx < -lim || fx >= lim || fy < -lim || fy >= lim)
        throw std::invalid_argument("mesh_from_maps: node (" + std::to_string(i) + ", " + std::to_string(j) +
                                    ") outside -4096 .. 4096 pixels");
      m.u[size_t(j) * size_t(m.nx) + size_t(i)] = cvRound(double(fx) * (1 << kMeshFracBits));
      m.v[size_t(j) * size_t(m.nx) + size_t(i)] = cvRound(double(fy) * (1 << kMeshFracBits));
    }
  return m;
}

}  // namespace mcadsw
