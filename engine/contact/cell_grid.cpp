#include "engine/contact/cell_grid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace wirepack {

namespace {

// The 13 "forward" neighbour offsets (dx, dy, dz): the half of the 26 neighbours that comes
// after the own cell in (z, y, x) order. Scanning own cell + these finds every pair once.
constexpr std::array<std::array<int, 3>, 13> kForward = {{{1, 0, 0},
                                                          {-1, 1, 0},
                                                          {0, 1, 0},
                                                          {1, 1, 0},
                                                          {-1, -1, 1},
                                                          {0, -1, 1},
                                                          {1, -1, 1},
                                                          {-1, 0, 1},
                                                          {0, 0, 1},
                                                          {1, 0, 1},
                                                          {-1, 1, 1},
                                                          {0, 1, 1},
                                                          {1, 1, 1}}};

// Number of cells along one axis of extent `ext` [m] for cell size `h` [m], as a double so that
// a tiny cutoff over a huge box cannot overflow an int.
double cells_along(double ext, double h) {
  return std::floor(ext / h) + 1.0;
}

}  // namespace

void CellGrid::find_pairs(std::span<const Vec3> points, double cutoff,
                          std::vector<std::pair<int, int>>& pairs) {
  scan(points, -1, cutoff, pairs);
}

void CellGrid::find_pairs_between(std::span<const Vec3> points, int split, double cutoff,
                                  std::vector<std::pair<int, int>>& pairs) {
  if (split < 0 || static_cast<std::size_t>(split) > points.size()) {
    throw std::invalid_argument("CellGrid::find_pairs_between: split outside [0, n]");
  }
  scan(points, split, cutoff, pairs);
}

void CellGrid::scan(std::span<const Vec3> points, int split, double cutoff,
                    std::vector<std::pair<int, int>>& pairs) {
  pairs.clear();
  if (!(cutoff > 0.0) || !std::isfinite(cutoff)) {
    throw std::invalid_argument("CellGrid::find_pairs: cutoff must be finite and > 0");
  }
  const std::size_t n_points = points.size();
  // Cell count bound below (8 n + 1000) must fit an int, as must the point indices.
  if (n_points > static_cast<std::size_t>(std::numeric_limits<int>::max() / 16)) {
    throw std::invalid_argument("CellGrid::find_pairs: too many points");
  }
  const int n = static_cast<int>(n_points);
  if (n < 2) return;

  // Bounding box [m]; a non-finite coordinate would make the cell index meaningless.
  Vec3 lo = points[0];
  Vec3 hi = points[0];
  for (const Vec3& x : points) {
    if (!x.allFinite()) throw SimulationError("non-finite point in contact broad phase");
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  const Vec3 ext = hi - lo;  // [m]
  if (!ext.allFinite()) throw SimulationError("contact broad phase: bounding box overflows");

  // Cell size h >= cutoff [m]. If the box is huge compared with the cutoff, grow h until the
  // grid has at most 8 n + 1000 cells: larger cells still contain every pair, just test more.
  const double max_cells = 8.0 * n + 1000.0;
  double h = cutoff;
  auto total_cells = [&](double hh) {
    return cells_along(ext.x(), hh) * cells_along(ext.y(), hh) * cells_along(ext.z(), hh);
  };
  for (double total = total_cells(h); total > max_cells; total = total_cells(h)) {
    h *= std::max(1.01, std::cbrt(total / max_cells));
  }
  // Rounding margin: the cell coordinate (x - lo) / h carries an error of a few ulps of the
  // cell count per axis; growing h by that relative amount guarantees that two points closer
  // than the cutoff are never two cells apart.
  const double max_dim =
      std::max({cells_along(ext.x(), h), cells_along(ext.y(), h), cells_along(ext.z(), h)});
  h *= 1.0 + 16.0 * std::numeric_limits<double>::epsilon() * (max_dim + 1.0);
  const int nx = static_cast<int>(cells_along(ext.x(), h));
  const int ny = static_cast<int>(cells_along(ext.y(), h));
  const int nz = static_cast<int>(cells_along(ext.z(), h));
  const int num_cells = nx * ny * nz;
  const double inv_h = 1.0 / h;  // [1/m]

  // Cell of each point, linear index ix + nx (iy + ny iz).
  auto axis_cell = [inv_h](double x, double x_lo, int dim) {
    return std::min(static_cast<int>((x - x_lo) * inv_h), dim - 1);
  };
  cell_of_.resize(n);
  for (int i = 0; i < n; ++i) {
    const Vec3& x = points[i];
    cell_of_[i] = axis_cell(x.x(), lo.x(), nx) +
                  nx * (axis_cell(x.y(), lo.y(), ny) + ny * axis_cell(x.z(), lo.z(), nz));
  }

  // Counting sort by cell (stable, so each cell lists its points by increasing index):
  // count into cell_start_[c + 1], prefix sum, scatter with cell_start_[c] as the cursor
  // (which leaves it at the cell's end), then shift back by one.
  cell_start_.assign(static_cast<std::size_t>(num_cells) + 1, 0);
  for (int i = 0; i < n; ++i) ++cell_start_[cell_of_[i] + 1];
  for (int c = 0; c < num_cells; ++c) cell_start_[c + 1] += cell_start_[c];
  sorted_.resize(n);
  for (int i = 0; i < n; ++i) sorted_[cell_start_[cell_of_[i]]++] = i;
  for (int c = num_cells; c > 0; --c) cell_start_[c] = cell_start_[c - 1];
  cell_start_[0] = 0;

  const double cutoff2 = cutoff * cutoff;  // [m^2]
  if (split >= 0) {
    // Two sets: each point of the smaller set against the points of the other set in its own
    // and its 26 neighbouring cells. Pairs within a set are never visited (a mesh's faces
    // against each other outnumber the wire-mesh pairs many times over).
    const bool first_small = split <= n - split;
    const int from = first_small ? 0 : split, to = first_small ? split : n;
    for (int i = from; i < to; ++i) {
      const int c = cell_of_[i];
      const int ix = c % nx, iy = (c / nx) % ny, iz = c / (nx * ny);
      const Vec3& xi = points[i];
      for (int jz = std::max(0, iz - 1); jz <= std::min(nz - 1, iz + 1); ++jz) {
        for (int jy = std::max(0, iy - 1); jy <= std::min(ny - 1, iy + 1); ++jy) {
          for (int jx = std::max(0, ix - 1); jx <= std::min(nx - 1, ix + 1); ++jx) {
            const int cn = jx + nx * (jy + ny * jz);
            for (int b = cell_start_[cn]; b < cell_start_[cn + 1]; ++b) {
              const int j = sorted_[b];
              if ((j < split) == first_small) continue;  // same set as i
              if ((xi - points[j]).squaredNorm() < cutoff2) {
                pairs.emplace_back(std::min(i, j), std::max(i, j));
              }
            }
          }
        }
      }
    }
    sort_pairs(n, pairs);
    return;
  }

  // One set: own cell (pairs a < b within it) and the 13 forward neighbours (all pairs).
  for (int iz = 0; iz < nz; ++iz) {
    for (int iy = 0; iy < ny; ++iy) {
      for (int ix = 0; ix < nx; ++ix) {
        const int c = ix + nx * (iy + ny * iz);
        const int begin = cell_start_[c];
        const int end = cell_start_[c + 1];
        if (begin == end) continue;
        for (int a = begin; a < end; ++a) {
          const int i = sorted_[a];
          for (int b = a + 1; b < end; ++b) {
            const int j = sorted_[b];  // j > i: stable sort
            if ((points[i] - points[j]).squaredNorm() < cutoff2) pairs.emplace_back(i, j);
          }
        }
        for (const auto& [dx, dy, dz] : kForward) {
          const int jx = ix + dx;
          const int jy = iy + dy;
          const int jz = iz + dz;
          if (jx < 0 || jx >= nx || jy < 0 || jy >= ny || jz >= nz) continue;
          const int cn = jx + nx * (jy + ny * jz);
          const int nbegin = cell_start_[cn];
          const int nend = cell_start_[cn + 1];
          for (int a = begin; a < end; ++a) {
            const int i = sorted_[a];
            const Vec3& xi = points[i];
            for (int b = nbegin; b < nend; ++b) {
              const int j = sorted_[b];
              if ((xi - points[j]).squaredNorm() < cutoff2) {
                pairs.emplace_back(std::min(i, j), std::max(i, j));
              }
            }
          }
        }
      }
    }
  }
  sort_pairs(n, pairs);
}

void CellGrid::sort_pairs(int n, std::vector<std::pair<int, int>>& pairs) {
  // Deterministic (i, j) order, independent of the grid. A comparison sort of all pairs costs
  // several times the scan, so: LSD radix sort, a stable counting pass by j then one by i, each
  // O(pairs + n). The counts live in cell_start_ (free now) and the scratch half is the tail of
  // `pairs` itself, so a warm grid still does not allocate.
  const std::size_t num_pairs = pairs.size();
  if (num_pairs > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    std::sort(pairs.begin(), pairs.end());  // prefix sums would overflow int
    return;
  }
  pairs.resize(2 * num_pairs);
  auto counting_pass = [&](std::size_t from, std::size_t to, bool by_first) {
    cell_start_.assign(static_cast<std::size_t>(n) + 1, 0);
    for (std::size_t k = from; k < from + num_pairs; ++k) {
      ++cell_start_[(by_first ? pairs[k].first : pairs[k].second) + 1];
    }
    for (int i = 0; i < n; ++i) cell_start_[i + 1] += cell_start_[i];
    for (std::size_t k = from; k < from + num_pairs; ++k) {
      const int key = by_first ? pairs[k].first : pairs[k].second;
      pairs[to + cell_start_[key]++] = pairs[k];
    }
  };
  counting_pass(0, num_pairs, false);  // by j into the scratch half
  counting_pass(num_pairs, 0, true);   // stably by i back into place
  pairs.resize(num_pairs);
}

}  // namespace wirepack
