// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// make_raw_cameras DATA DST [--camera A|B|C] [--pair SET/NAME]: the raw camera pairs
// of docs/algorithm.md 13.6. Each bundled pair (DATA/middlebury/{tsukuba,
// venus,teddy,cones}, DATA/cif/teddy; camera C: the Teddy pairs only) is taken as rectified with
// P = [W 0 (W-1)/2; 0 W (H-1)/2]; each view is rendered as a raw camera (K, distortion
// k1 k2 p1 p2, a rotation of at most 2 degrees) would see it: every raw pixel is the
// mean of 4 x 4 point samples over its footprint, each carried to rectified
// coordinates by cv::undistortPoints (the iterative form, OpenCV's
// undistortPointsIter) and sampled bilinearly in the bundled view. Writes
// DST/<camera>/<set>/<name>/left.png, right.png and calib.yml (K1 D1 R1 P1 K2 D2 R2
// P2, image_width, image_height), whose rectification maps the raw pair back onto
// the bundled geometry, so the bundled ground truth applies.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

namespace fs = std::filesystem;

namespace {

// One raw camera of a stereo rig (docs/algorithm.md 13.6, table "Cameras").
struct View {
  double fx, fy;          // focal lengths, in units of the rectified f = W
  double dx, dy;          // principal point offset from ((W-1)/2, (H-1)/2), pixels
  double k1, k2, p1, p2;  // OpenCV's distortion model (k3 = 0)
  double degrees;         // rotation angle ...
  std::array<double, 3> axis;  // ... about this axis (normalised here)
};

struct Camera {
  const char* name;
  View left, right;
  bool teddy_only;  // C: the Teddy pairs only (its point is the invalid strips)
};

// Axes: mostly about the optical axis (an image rotation), with some pitch and yaw
// (a vertical / horizontal shift of the view); the same for both cameras.
constexpr std::array<double, 3> kAxisLeft{0.3, -0.5, 0.8}, kAxisRight{-0.4, 0.3, 0.85};

const Camera kCameras[] = {
    {"A",
     {0.95, 0.952, +3, -2, -0.05, 0.01, 0.0005, -0.0003, 0.5, kAxisLeft},
     {0.94, 0.941, -2, +1, -0.04, 0.008, -0.0004, 0.0002, 0.7, kAxisRight},
     false},
    {"B",
     {0.87, 0.872, +6, -4, -0.12, 0.03, 0.001, -0.0008, 1.5, kAxisLeft},
     {0.85, 0.853, -5, +3, -0.10, 0.025, -0.0009, 0.0006, 2.0, kAxisRight},
     false},
    // Off-centre: parts of the rectified frame lie outside the raw views (invalid pixels).
    {"C",
     {0.93, 0.931, -40, -24, -0.08, 0.02, 0.0007, -0.0005, 1.0, kAxisLeft},
     {0.92, 0.921, +36, +20, -0.07, 0.015, -0.0006, 0.0004, 1.2, kAxisRight},
     true},
};

struct Pair {
  const char* set;
  const char* name;
};
const Pair kPairs[] = {{"middlebury", "tsukuba"}, {"middlebury", "venus"}, {"middlebury", "teddy"},
                       {"middlebury", "cones"},   {"cif", "teddy"}};

cv::Matx33d rectified_p(cv::Size size) {
  const double f = size.width;
  return {f, 0, (size.width - 1) / 2.0, 0, f, (size.height - 1) / 2.0, 0, 0, 1};
}

cv::Matx33d camera_k(const View& v, cv::Size size) {
  const double f = size.width;
  return {v.fx * f, 0, (size.width - 1) / 2.0 + v.dx, 0, v.fy * f, (size.height - 1) / 2.0 + v.dy, 0, 0, 1};
}

cv::Mat camera_d(const View& v) { return (cv::Mat_<double>(1, 5) << v.k1, v.k2, v.p1, v.p2, 0.0); }

cv::Vec3d rodrigues_vector(const View& v) {
  const cv::Vec3d a(v.axis[0], v.axis[1], v.axis[2]);
  return a * (v.degrees * CV_PI / 180.0 / cv::norm(a));
}

// The raw view of camera `v` of the rectified (bundled) view `scene`, same size.
cv::Mat render(const cv::Mat& scene, const View& v, cv::Matx33d& r_out) {
  const cv::Size size = scene.size();
  const cv::Matx33d k = camera_k(v, size), p = rectified_p(size);
  const cv::Mat d = camera_d(v);
  cv::Mat r;
  cv::Rodrigues(rodrigues_vector(v), r);
  r_out = cv::Matx33d(r);
  const int w = size.width, h = size.height, ch = scene.channels();
  cv::Mat raw(size, scene.type());
  const cv::TermCriteria crit(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-10);
  cv::parallel_for_(cv::Range(0, h), [&](const cv::Range& rows) {
    std::vector<cv::Point2d> pts(size_t(16) * size_t(w)), rect;
    std::vector<double> acc(size_t(w) * size_t(ch));
    for (int b = rows.start; b < rows.end; ++b) {
      size_t n = 0;
      for (int a = 0; a < w; ++a)
        for (int j = 0; j < 4; ++j)
          for (int i = 0; i < 4; ++i) pts[n++] = {a + (i + 0.5) / 4 - 0.5, b + (j + 0.5) / 4 - 0.5};
      cv::undistortPoints(pts, rect, k, d, r, p, crit);
      std::fill(acc.begin(), acc.end(), 0.0);
      for (size_t s = 0; s < rect.size(); ++s) {
        // Bilinear in float (views of at least 2 x 2); a point outside the view takes
        // the nearest edge.
        const double x = std::clamp(rect[s].x, 0.0, double(w - 1)), y = std::clamp(rect[s].y, 0.0, double(h - 1));
        const int x0 = std::min(int(x), w - 2), y0 = std::min(int(y), h - 2), x1 = x0 + 1, y1 = y0 + 1;
        const double fx = x - x0, fy = y - y0;
        const uchar *r0 = scene.ptr<uchar>(y0), *r1 = scene.ptr<uchar>(y1);
        double* out = &acc[s / 16 * size_t(ch)];
        for (int c = 0; c < ch; ++c)
          out[c] += (1 - fy) * ((1 - fx) * r0[x0 * ch + c] + fx * r0[x1 * ch + c]) +
                    fy * ((1 - fx) * r1[x0 * ch + c] + fx * r1[x1 * ch + c]);
      }
      uchar* o = raw.ptr<uchar>(b);
      for (size_t q = 0; q < acc.size(); ++q) o[q] = cv::saturate_cast<uchar>(std::floor(acc[q] / 16 + 0.5));
    }
  });
  return raw;
}

bool write_calibration(const fs::path& path, const Camera& cam, cv::Size size, const cv::Matx33d& r1,
                       const cv::Matx33d& r2) {
  cv::FileStorage out(path.string(), cv::FileStorage::WRITE);
  if (!out.isOpened()) return false;
  out.writeComment(std::string("Test camera ") + cam.name +
                   " (docs/algorithm.md 13.6), written by make_raw_cameras.\n"
                   "Rectification K D R P of each view; it maps the raw pair back onto the bundled pair.");
  const cv::Matx33d p = rectified_p(size);
  const cv::Matx34d p34(p(0, 0), p(0, 1), p(0, 2), 0, p(1, 0), p(1, 1), p(1, 2), 0, 0, 0, 1, 0);
  out << "image_width" << size.width << "image_height" << size.height;
  out << "K1" << cv::Mat(camera_k(cam.left, size)) << "D1" << camera_d(cam.left) << "R1" << cv::Mat(r1) << "P1"
      << cv::Mat(p34);
  out << "K2" << cv::Mat(camera_k(cam.right, size)) << "D2" << camera_d(cam.right) << "R2" << cv::Mat(r2) << "P2"
      << cv::Mat(p34);
  out << "rvec1" << cv::Mat(rodrigues_vector(cam.left)) << "rvec2" << cv::Mat(rodrigues_vector(cam.right));
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  std::string only_camera, only_pair;
  bool usage_ok = argc >= 3;
  for (int i = 3; usage_ok && i < argc; i += 2) {
    const std::string o = argv[i];
    if (i + 1 >= argc) usage_ok = false;
    else if (o == "--camera") only_camera = argv[i + 1];
    else if (o == "--pair") only_pair = argv[i + 1];
    else usage_ok = false;
  }
  if (!usage_ok) {
    std::cerr << "usage: make_raw_cameras DATA_DIR DST_DIR [--camera A|B|C] [--pair SET/NAME]\n"
                 "       (e.g. data data/raw; SET/NAME: middlebury/teddy, cif/teddy, ...)\n";
    return 2;
  }
  const fs::path src(argv[1]), dst(argv[2]);
  int made = 0;
  for (const Camera& cam : kCameras) {
    if (!only_camera.empty() && only_camera != cam.name) continue;
    for (const Pair& pair : kPairs) {
      if (!only_pair.empty() && only_pair != std::string(pair.set) + "/" + pair.name) continue;
      if (cam.teddy_only && std::string(pair.name) != "teddy") continue;
      const fs::path in = src / pair.set / pair.name, out = dst / cam.name / pair.set / pair.name;
      fs::create_directories(out);
      cv::Matx33d rot[2];
      cv::Size size;
      for (const int view : {0, 1}) {
        const char* file = view == 0 ? "left.png" : "right.png";
        const cv::Mat scene = cv::imread((in / file).string(), cv::IMREAD_COLOR);
        if (scene.empty() || scene.cols < 2 || scene.rows < 2) {
          std::cerr << "make_raw_cameras: cannot read " << (in / file) << "\n";
          return 1;
        }
        if (view == 1 && scene.size() != size) {
          std::cerr << "make_raw_cameras: " << (in / file) << " differs in size from its left view\n";
          return 1;
        }
        size = scene.size();
        const cv::Mat raw = render(scene, view == 0 ? cam.left : cam.right, rot[view]);
        if (!cv::imwrite((out / file).string(), raw)) {
          std::cerr << "make_raw_cameras: cannot write " << (out / file) << "\n";
          return 1;
        }
      }
      if (!write_calibration(out / "calib.yml", cam, size, rot[0], rot[1])) {
        std::cerr << "make_raw_cameras: cannot write " << (out / "calib.yml") << "\n";
        return 1;
      }
      std::cout << "make_raw_cameras: camera " << cam.name << ", " << pair.set << "/" << pair.name << " ("
                << size.width << "x" << size.height << ") -> " << out << "\n";
      ++made;
    }
  }
  if (made == 0) {
    std::cerr << "make_raw_cameras: no camera and pair match --camera " << only_camera << " --pair " << only_pair
              << "\n";
    return 1;
  }
  return 0;
}
