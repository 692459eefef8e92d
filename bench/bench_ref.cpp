// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Reference-model speed. MDE/s = million disparity evaluations per second
// (width x height x D / seconds), the paper's Table IV unit. Wall-clock time
// (UseRealTime): the reference and OpenCV SGBM both run on every core.
#include <benchmark/benchmark.h>

#include <string>

#include "mcadsw/baselines.hpp"
#include "mcadsw/image_io.hpp"
#include "mcadsw/ref.hpp"

namespace {

struct Pair {
  mcadsw::YuvImage left, right;
};

Pair load(const std::string& set, const std::string& name) {
  const std::string dir = std::string(MCADSW_DATA_DIR) + "/" + set + "/" + name + "/";
  return {mcadsw::load_yuv(dir + "left.png"), mcadsw::load_yuv(dir + "right.png")};
}

void set_mde(benchmark::State& state, const mcadsw::YuvImage& img, int d) {
  state.counters["MDE/s"] = benchmark::Counter(double(img.width()) * img.height() * d / 1e6,
                                               benchmark::Counter::kIsIterationInvariantRate);
}

void BM_DisparityMap(benchmark::State& state, std::string set, std::string name, int d, int threads) {
  const Pair p = load(set, name);
  mcadsw::Config cfg;
  cfg.disparities = d;
  cfg.threads = threads;
  for (auto _ : state) benchmark::DoNotOptimize(mcadsw::disparity_map(p.left, p.right, cfg));
  set_mde(state, p.left, d);
}

// CIF at D = 64, the paper's operating point; all cores and one.
BENCHMARK_CAPTURE(BM_DisparityMap, cif_teddy_D64, "cif", "teddy", 64, 0)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_DisparityMap, cif_teddy_D64_1thread, "cif", "teddy", 64, 1)
    ->Unit(benchmark::kMillisecond)->UseRealTime();
// The four Middlebury pairs at their native size and usual D.
BENCHMARK_CAPTURE(BM_DisparityMap, tsukuba_D16, "middlebury", "tsukuba", 16, 0)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_DisparityMap, venus_D20, "middlebury", "venus", 20, 0)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_DisparityMap, teddy_D60, "middlebury", "teddy", 60, 0)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_DisparityMap, cones_D60, "middlebury", "cones", 60, 0)->Unit(benchmark::kMillisecond)->UseRealTime();

// OpenCV's matchers on the same images, in the same run (make_matcher settings
// in sw_ref/src/baselines.cpp); MDE/s counts the same W x H x D.
void BM_Baseline(benchmark::State& state, mcadsw::Baseline b, std::string set, std::string name,
                 int d) {
  const std::string dir = std::string(MCADSW_DATA_DIR) + "/" + set + "/" + name + "/";
  const cv::Mat l = mcadsw::read_color_image(dir + "left.png");
  const cv::Mat r = mcadsw::read_color_image(dir + "right.png");
  for (auto _ : state) benchmark::DoNotOptimize(mcadsw::baseline_disparity(b, l, r, d));
  state.counters["MDE/s"] = benchmark::Counter(double(l.cols) * l.rows * d / 1e6,
                                               benchmark::Counter::kIsIterationInvariantRate);
}
#define MCADSW_BASELINE(tag, b)                                                                  \
  BENCHMARK_CAPTURE(BM_Baseline, tag##_cif_teddy_D64, b, "cif", "teddy", 64)                   \
      ->Unit(benchmark::kMillisecond)->UseRealTime();                                                          \
  BENCHMARK_CAPTURE(BM_Baseline, tag##_tsukuba_D16, b, "middlebury", "tsukuba", 16)            \
      ->Unit(benchmark::kMillisecond)->UseRealTime();                                                          \
  BENCHMARK_CAPTURE(BM_Baseline, tag##_venus_D20, b, "middlebury", "venus", 20)                \
      ->Unit(benchmark::kMillisecond)->UseRealTime();                                                          \
  BENCHMARK_CAPTURE(BM_Baseline, tag##_teddy_D60, b, "middlebury", "teddy", 60)                \
      ->Unit(benchmark::kMillisecond)->UseRealTime();                                                          \
  BENCHMARK_CAPTURE(BM_Baseline, tag##_cones_D60, b, "middlebury", "cones", 60)                \
      ->Unit(benchmark::kMillisecond)->UseRealTime()
MCADSW_BASELINE(sgbm3way, mcadsw::Baseline::kSgbm3Way);
MCADSW_BASELINE(sgbm_hh, mcadsw::Baseline::kSgbmHH);
MCADSW_BASELINE(bm, mcadsw::Baseline::kBm);
#undef MCADSW_BASELINE

// Per-block cost on CIF, to see where the time goes.
void BM_CensusTransform(benchmark::State& state) {
  const Pair p = load("cif", "teddy");
  for (auto _ : state) benchmark::DoNotOptimize(mcadsw::census_transform(p.left.y));
}
BENCHMARK(BM_CensusTransform)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_GenerateWeights(benchmark::State& state) {
  const Pair p = load("cif", "teddy");
  const auto table = mcadsw::make_weight_table(mcadsw::kDefaultGamma);
  for (auto _ : state) benchmark::DoNotOptimize(mcadsw::generate_weights(p.left, table));
}
BENCHMARK(BM_GenerateWeights)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_AggregateOneDisparity(benchmark::State& state) {
  const Pair p = load("cif", "teddy");
  const auto w = mcadsw::generate_weights(p.left, mcadsw::make_weight_table(mcadsw::kDefaultGamma));
  const auto cl = mcadsw::census_transform(p.left.y), cr = mcadsw::census_transform(p.right.y);
  std::vector<uint8_t> cost;
  std::vector<uint16_t> ev;
  std::vector<uint32_t> e;
  for (auto _ : state) {
    mcadsw::census_cost_slice(cl, cr, 20, cost);
    mcadsw::vertical_aggregate(cost, w, ev);
    mcadsw::horizontal_aggregate(ev, w, e);
    benchmark::DoNotOptimize(e.data());
  }
  set_mde(state, p.left, 1);
}
BENCHMARK(BM_AggregateOneDisparity)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
