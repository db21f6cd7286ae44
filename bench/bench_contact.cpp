// Contact micro-benchmarks: broad phase (CellGrid::find_pairs) on a packed wire-like chain,
// and the narrow-phase segment-segment closest points.
#include <benchmark/benchmark.h>

#include <random>

#include "engine/contact/cell_grid.hpp"
#include "engine/contact/segment_distance.hpp"

namespace {

using wirepack::CellGrid;
using wirepack::Vec3;
using wirepack::Vec3List;

// Random-walk chain of n nodes [m]: steps of length `step` in random directions, a step that
// would leave the sphere of radius `radius` is redrawn. Seeded, so every run sees the same chain.
Vec3List packed_chain(int n, double step, double radius, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  Vec3List x;
  x.reserve(n);
  x.emplace_back(Vec3::Zero());
  while (static_cast<int>(x.size()) < n) {
    const Vec3 next = x.back() + step * Vec3(g(rng), g(rng), g(rng)).normalized();
    if (next.norm() <= radius) x.push_back(next);
  }
  return x;
}

constexpr int kNodes = 5000;
constexpr double kStep = 0.5e-3;    // [m]
constexpr double kRadius = 10e-3;   // [m]
constexpr double kCutoff = 1.6e-3;  // [m]

// Time per point of a warm find_pairs (buffers already sized).
void BM_CellGridFindPairs(benchmark::State& state) {
  const Vec3List x = packed_chain(kNodes, kStep, kRadius, 42);
  CellGrid grid;
  std::vector<std::pair<int, int>> pairs;
  grid.find_pairs(x, kCutoff, pairs);  // warm up
  for (auto _ : state) {
    grid.find_pairs(x, kCutoff, pairs);
    benchmark::DoNotOptimize(pairs.data());
  }
  state.counters["pairs"] = static_cast<double>(pairs.size());
  state.counters["per_point"] = benchmark::Counter(
      kNodes, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_CellGridFindPairs);

// Time per segment_segment_closest call on the segment pairs a wire contact pass would test:
// segments (i, i+1) and (j, j+1) for every broad-phase pair with |i - j| > 2.
void BM_SegmentSegmentClosest(benchmark::State& state) {
  const Vec3List x = packed_chain(kNodes, kStep, kRadius, 42);
  CellGrid grid;
  std::vector<std::pair<int, int>> pairs;
  grid.find_pairs(x, kCutoff, pairs);
  std::vector<std::pair<int, int>> seg;
  for (const auto& [i, j] : pairs) {
    if (j - i > 2 && j + 1 < kNodes) seg.emplace_back(i, j);
  }
  double sum = 0;
  for (auto _ : state) {
    for (const auto& [i, j] : seg) {
      sum += wirepack::segment_segment_closest(x[i], x[i + 1], x[j], x[j + 1]).dist2;
    }
    benchmark::DoNotOptimize(sum);
  }
  state.counters["per_call"] = benchmark::Counter(
      static_cast<double>(seg.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_SegmentSegmentClosest);

}  // namespace

BENCHMARK_MAIN();
