// Reference-model speed. MDE/s = million disparity evaluations per second
// (width x height x D / seconds), the paper's Table IV unit.
#include <benchmark/benchmark.h>

#include <string>

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
BENCHMARK_CAPTURE(BM_DisparityMap, cif_teddy_D64, "cif", "teddy", 64, 0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_DisparityMap, cif_teddy_D64_1thread, "cif", "teddy", 64, 1)
    ->Unit(benchmark::kMillisecond);
// The four Middlebury pairs at their native size and usual D.
BENCHMARK_CAPTURE(BM_DisparityMap, tsukuba_D16, "middlebury", "tsukuba", 16, 0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_DisparityMap, venus_D20, "middlebury", "venus", 20, 0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_DisparityMap, teddy_D60, "middlebury", "teddy", 60, 0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_DisparityMap, cones_D60, "middlebury", "cones", 60, 0)->Unit(benchmark::kMillisecond);

// Per-block cost on CIF, to see where the time goes.
void BM_CensusTransform(benchmark::State& state) {
  const Pair p = load("cif", "teddy");
  for (auto _ : state) benchmark::DoNotOptimize(mcadsw::census_transform(p.left.y));
}
BENCHMARK(BM_CensusTransform)->Unit(benchmark::kMillisecond);

void BM_GenerateWeights(benchmark::State& state) {
  const Pair p = load("cif", "teddy");
  const auto table = mcadsw::make_weight_table(mcadsw::kDefaultGamma);
  for (auto _ : state) benchmark::DoNotOptimize(mcadsw::generate_weights(p.left, table));
}
BENCHMARK(BM_GenerateWeights)->Unit(benchmark::kMillisecond);

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
BENCHMARK(BM_AggregateOneDisparity)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
