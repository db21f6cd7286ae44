#pragma once
// Deterministic parallel assembly of per-element contributions (faces, edges) into per-target
// sums (vertices, edges, faces). Each element writes its `width` contributions into its own
// slots of a buffer (no two threads write one place); gather_add() then adds, for every target,
// its contributions in increasing (element, slot) order: the order a serial loop over the
// elements would have added them in. The sums are therefore bitwise those of the serial loop,
// whatever the number of threads.
#include <vector>

#include "engine/types.hpp"

namespace wirepack {

class ScatterPlan {
 public:
  ScatterPlan() = default;
  // targets[k * width + j]: the target of slot j of element k, or -1 for none; n_targets
  // targets in all.
  ScatterPlan(const std::vector<int>& targets, int width, int n_targets);

  int width() const { return width_; }
  int elements() const { return width_ > 0 ? static_cast<int>(slots_) / width_ : 0; }
  // out[t] += values[s] over the slots s of target t, in increasing s (values: one per slot).
  void gather_add(const Vec3List& values, Vec3List& out) const;
  // out[t] = sum of its slots (from zero, in the same order).
  void gather_set(const Vec3List& values, Vec3List& out) const;
  void gather_set(const std::vector<double>& values, std::vector<double>& out) const;

 private:
  int width_ = 0;
  size_t slots_ = 0;
  std::vector<int> start_;  // CSR offsets into slot_ (n_targets + 1)
  std::vector<int> slot_;   // slot indices per target, increasing
};

// Sum of v in index order (serial: bitwise the sum of a serial loop).
double ordered_sum(const std::vector<double>& v);

}  // namespace wirepack
