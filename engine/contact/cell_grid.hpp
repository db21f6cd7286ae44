#pragma once
// O(n) broad phase: a uniform cell grid over the bounding box of a point set. Finds every pair
// of points closer than a cutoff without testing all pairs. Buffers are reused between calls,
// so a warmed-up grid does not allocate.
#include <span>
#include <utility>
#include <vector>

#include "engine/types.hpp"

namespace wirepack {

class CellGrid {
 public:
  // Appends to `pairs` (after clearing it) every (i, j) with i < j and
  // |points[i] - points[j]| < cutoff, each pair exactly once, sorted by (i, j) so that the
  // result is deterministic. cutoff > 0 [m].
  void find_pairs(std::span<const Vec3> points, double cutoff,
                  std::vector<std::pair<int, int>>& pairs);
  // The same for two sets stored one after the other: only the pairs (i, j) with
  // i < split <= j, i.e. between points[0, split) and points[split, n). Pairs within one set
  // are skipped before their distance is computed (a wire against a shell mesh: neither the
  // wire's nor the mesh's own neighbours are wanted). 0 <= split <= n.
  void find_pairs_between(std::span<const Vec3> points, int split, double cutoff,
                          std::vector<std::pair<int, int>>& pairs);

 private:
  void scan(std::span<const Vec3> points, int split, double cutoff,
            std::vector<std::pair<int, int>>& pairs);  // split < 0: every pair
  // Sorts the pairs of n points by (i, j) (two stable counting passes, O(pairs + n)).
  void sort_pairs(int n, std::vector<std::pair<int, int>>& pairs);

  std::vector<int> cell_start_;  // first sorted slot of each cell (num_cells + 1)
  std::vector<int> cell_of_;     // cell index of each point (n)
  std::vector<int> sorted_;      // point indices sorted by cell (n)
};

}  // namespace wirepack
