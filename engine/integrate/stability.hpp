#pragma once
// The system's highest angular frequency from the terms' bounds (paper, section "Model": the
// explicit step is bounded by 2 / omega_max).
// With M^-1 K = K_wire + K_shell + K_coupling, where K_wire and K_shell act on disjoint DOFs
// (block-diagonal), Weyl's inequality gives
//   omega_max^2 <= max(sum of the wire terms, sum of the shell terms) + sum of the coupling terms,
// each term's bound being an upper bound of its own largest eigenvalue [1/s^2]. Adding every
// term instead (the former bound) counted the shell's modes on top of the wire's.
#include <algorithm>

#include "engine/term.hpp"

namespace wirepack {

class StabilityBound {
 public:
  void add(DofGroup group, double omega2) {
    switch (group) {
      case DofGroup::kWire:
        wire_ += omega2;
        break;
      case DofGroup::kShell:
        shell_ += omega2;
        break;
      case DofGroup::kCoupling:
        coupling_ += omega2;
        break;
    }
  }
  double omega_max_sq() const { return std::max(wire_, shell_) + coupling_; }

 private:
  double wire_ = 0.0, shell_ = 0.0, coupling_ = 0.0;  // [1/s^2]
};

}  // namespace wirepack
