// Tests for the CellGrid broad phase: identical pair sets to the O(n^2) all-pairs answer on
// uniform, clustered, collinear and coincident point sets; sorted output; buffer reuse.
#include "engine/contact/cell_grid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace wirepack {
namespace {

using Pairs = std::vector<std::pair<int, int>>;

// O(n^2) reference: every (i, j), i < j, with |x_i - x_j| < cutoff, in (i, j) order.
Pairs all_pairs(const Vec3List& x, double cutoff) {
  Pairs out;
  for (int i = 0; i < static_cast<int>(x.size()); ++i) {
    for (int j = i + 1; j < static_cast<int>(x.size()); ++j) {
      if ((x[i] - x[j]).squaredNorm() < cutoff * cutoff) out.emplace_back(i, j);
    }
  }
  return out;
}

// Runs the grid and checks the result equals the reference exactly (same set, same order).
void expect_same_as_all_pairs(CellGrid& grid, const Vec3List& x, double cutoff) {
  Pairs got;
  grid.find_pairs(x, cutoff, got);
  EXPECT_TRUE(std::is_sorted(got.begin(), got.end()));
  for (const auto& [i, j] : got) ASSERT_LT(i, j);
  const Pairs want = all_pairs(x, cutoff);
  ASSERT_EQ(got.size(), want.size()) << "n = " << x.size() << ", cutoff = " << cutoff;
  EXPECT_EQ(got, want);
}

Vec3List uniform_cloud(int n, double side, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, side);
  Vec3List x(n);
  for (auto& p : x) p = Vec3(u(rng), u(rng), u(rng));
  return x;
}

TEST(CellGrid, UniformCloudsMatchAllPairs) {
  std::mt19937_64 rng(1);
  CellGrid grid;
  for (int n : {2, 3, 10, 100, 1000, 3000}) {
    for (double cutoff : {0.01, 0.05, 0.2}) {
      expect_same_as_all_pairs(grid, uniform_cloud(n, 1.0, rng), cutoff);
    }
  }
}

TEST(CellGrid, ClusteredCloudMatchesAllPairs) {
  // Dense Gaussian clusters far apart in a big box: many empty cells, crowded ones.
  std::mt19937_64 rng(2);
  std::normal_distribution<double> g(0.0, 0.02);
  std::uniform_real_distribution<double> u(0.0, 10.0);
  Vec3List x;
  for (int c = 0; c < 8; ++c) {
    const Vec3 centre(u(rng), u(rng), u(rng));
    for (int k = 0; k < 200; ++k) x.push_back(centre + Vec3(g(rng), g(rng), g(rng)));
  }
  CellGrid grid;
  expect_same_as_all_pairs(grid, x, 0.01);
  expect_same_as_all_pairs(grid, x, 0.05);
}

TEST(CellGrid, PointsOnALineMatchAllPairs) {
  // Degenerate box (zero extent in y, z); also a diagonal line.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Vec3List axis(2000), diag(2000);
  for (auto& p : axis) p = Vec3(u(rng), 0.0, 0.0);
  for (auto& p : diag) p = Vec3::Constant(u(rng));
  CellGrid grid;
  expect_same_as_all_pairs(grid, axis, 1e-3);
  expect_same_as_all_pairs(grid, diag, 1e-3);
}

TEST(CellGrid, IdenticalPointsGiveAllPairs) {
  const Vec3List x(50, Vec3(0.3, -1.0, 2.0));
  CellGrid grid;
  Pairs got;
  grid.find_pairs(x, 1e-6, got);
  EXPECT_EQ(got.size(), 50u * 49u / 2u);
  EXPECT_EQ(got, all_pairs(x, 1e-6));
}

TEST(CellGrid, CutoffLargerThanCloud) {
  std::mt19937_64 rng(4);
  const Vec3List x = uniform_cloud(200, 1.0, rng);
  CellGrid grid;
  Pairs got;
  grid.find_pairs(x, 10.0, got);
  EXPECT_EQ(got.size(), 200u * 199u / 2u);
  EXPECT_EQ(got, all_pairs(x, 10.0));
}

TEST(CellGrid, TinyCutoffInHugeBoxKeepsGridBounded) {
  // Box / cutoff = 1e9 per axis would be 1e27 cells; the grid must enlarge its cells instead
  // and still find the close pairs.
  std::mt19937_64 rng(5);
  Vec3List x = uniform_cloud(500, 1.0, rng);
  for (int k = 0; k < 20; ++k) x.push_back(x[k] + Vec3(3e-10, 0, 0));  // close partners
  CellGrid grid;
  expect_same_as_all_pairs(grid, x, 1e-9);
  Pairs got;
  grid.find_pairs(x, 1e-9, got);
  EXPECT_EQ(got.size(), 20u);
}

TEST(CellGrid, PairsAtExactlyTheCutoffAreExcluded) {
  // Strict inequality: points on a lattice of spacing 1 with cutoff 1 have no pairs; a
  // slightly larger cutoff finds the lattice neighbours.
  Vec3List x;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) x.emplace_back(i, j, k);
  CellGrid grid;
  Pairs got;
  grid.find_pairs(x, 1.0, got);
  EXPECT_TRUE(got.empty());
  expect_same_as_all_pairs(grid, x, 1.0 + 1e-12);
  expect_same_as_all_pairs(grid, x, 1.5);
}

TEST(CellGrid, EmptyAndSinglePoint) {
  CellGrid grid;
  Pairs got = {{0, 1}};  // stale content must be cleared
  grid.find_pairs(Vec3List{}, 1.0, got);
  EXPECT_TRUE(got.empty());
  got = {{0, 1}};
  grid.find_pairs(Vec3List{Vec3(1, 2, 3)}, 1.0, got);
  EXPECT_TRUE(got.empty());
}

TEST(CellGrid, ReusedGridGivesFreshAnswers) {
  // One grid, alternating inputs of different sizes and extents: no stale cells or counts.
  std::mt19937_64 rng(6);
  CellGrid grid;
  const Vec3List big = uniform_cloud(2000, 1.0, rng);
  const Vec3List small = uniform_cloud(30, 0.1, rng);
  const Vec3List wide = uniform_cloud(300, 50.0, rng);
  for (int rep = 0; rep < 2; ++rep) {
    expect_same_as_all_pairs(grid, big, 0.05);
    expect_same_as_all_pairs(grid, small, 0.03);
    expect_same_as_all_pairs(grid, wide, 4.0);
  }
  // Warm grid, same input again: the output vector keeps its storage.
  Pairs got;
  grid.find_pairs(big, 0.05, got);
  const auto* data = got.data();
  const std::size_t cap = got.capacity();
  grid.find_pairs(big, 0.05, got);
  EXPECT_EQ(got.data(), data);
  EXPECT_EQ(got.capacity(), cap);
}

// Two sets: exactly the all-pairs answer restricted to i < split <= j, in (i, j) order.
TEST(CellGrid, PairsBetweenTwoSetsMatchFilteredAllPairs) {
  std::mt19937_64 rng(3);
  CellGrid grid;
  for (int n : {2, 10, 500, 2000}) {
    const Vec3List x = uniform_cloud(n, 1.0, rng);
    for (int split : {0, 1, n / 3, n - 1, n}) {
      for (double cutoff : {0.03, 0.2}) {
        Pairs want;
        for (const auto& p : all_pairs(x, cutoff))
          if (p.first < split && p.second >= split) want.push_back(p);
        Pairs got;
        grid.find_pairs_between(x, split, cutoff, got);
        EXPECT_EQ(got, want) << "n = " << n << ", split = " << split;
      }
    }
    // The grid still answers the one-set question afterwards.
    expect_same_as_all_pairs(grid, x, 0.1);
  }
  Pairs got;
  EXPECT_THROW(grid.find_pairs_between(uniform_cloud(5, 1.0, rng), 6, 0.1, got),
               std::invalid_argument);
  EXPECT_THROW(grid.find_pairs_between(uniform_cloud(5, 1.0, rng), -1, 0.1, got),
               std::invalid_argument);
}

TEST(CellGrid, RejectsBadInput) {
  CellGrid grid;
  Pairs got;
  const Vec3List x = {Vec3(0, 0, 0), Vec3(1, 0, 0)};
  EXPECT_THROW(grid.find_pairs(x, 0.0, got), std::invalid_argument);
  EXPECT_THROW(grid.find_pairs(x, std::nan(""), got), std::invalid_argument);
  const Vec3List bad = {Vec3(0, 0, 0), Vec3(std::nan(""), 0, 0)};
  EXPECT_THROW(grid.find_pairs(bad, 1.0, got), SimulationError);
}

}  // namespace
}  // namespace wirepack
