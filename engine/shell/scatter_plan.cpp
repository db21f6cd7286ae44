#include "engine/shell/scatter_plan.hpp"

#include <stdexcept>

namespace wirepack {

ScatterPlan::ScatterPlan(const std::vector<int>& targets, int width, int n_targets)
    : width_(width), slots_(targets.size()) {
  if (width <= 0 || targets.size() % static_cast<size_t>(width) != 0)
    throw std::invalid_argument("ScatterPlan: slot count is not a multiple of the width");
  start_.assign(n_targets + 1, 0);
  for (int t : targets) {
    if (t >= n_targets) throw std::invalid_argument("ScatterPlan: target out of range");
    if (t >= 0) ++start_[t + 1];
  }
  for (int t = 0; t < n_targets; ++t) start_[t + 1] += start_[t];
  slot_.resize(start_[n_targets]);
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  // Slots in increasing order, so each target's list is increasing.
  for (size_t s = 0; s < targets.size(); ++s) {
    if (targets[s] >= 0) slot_[fill[targets[s]]++] = static_cast<int>(s);
  }
}

void ScatterPlan::gather_add(const Vec3List& values, Vec3List& out) const {
  const int nt = static_cast<int>(start_.size()) - 1;
#pragma omp parallel for schedule(static)
  for (int t = 0; t < nt; ++t) {
    Vec3 sum = out[t];
    for (int k = start_[t]; k < start_[t + 1]; ++k) sum += values[slot_[k]];
    out[t] = sum;
  }
}

void ScatterPlan::gather_set(const Vec3List& values, Vec3List& out) const {
  const int nt = static_cast<int>(start_.size()) - 1;
#pragma omp parallel for schedule(static)
  for (int t = 0; t < nt; ++t) {
    Vec3 sum = Vec3::Zero();
    for (int k = start_[t]; k < start_[t + 1]; ++k) sum += values[slot_[k]];
    out[t] = sum;
  }
}

void ScatterPlan::gather_set(const std::vector<double>& values, std::vector<double>& out) const {
  const int nt = static_cast<int>(start_.size()) - 1;
#pragma omp parallel for schedule(static)
  for (int t = 0; t < nt; ++t) {
    double sum = 0.0;
    for (int k = start_[t]; k < start_[t + 1]; ++k) sum += values[slot_[k]];
    out[t] = sum;
  }
}

double ordered_sum(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x;
  return s;
}

}  // namespace wirepack
