#pragma once
// Stretching energy of the discrete rod: U_s = sum_j 1/2 E A eps_j^2 lbar_j with the axial
// strain eps_j = |e_j| / lbar_j - 1 (paper Eq. (1), last term).
#include "engine/term.hpp"

namespace wirepack {

class StretchTerm : public Term {
 public:
  explicit StretchTerm(double EA) : EA_(EA) {}
  std::string name() const override { return "stretch"; }
  TermType type() const override { return TermType::kStretch; }
  double accumulate(const State& s, Forces& out) override;
  double energy(const State& s) override;
  double omega_max_sq(const RodInertia& inertia) const override;

 private:
  double EA_;              // axial stiffness [N]
  double min_rest_ = 0.0;  // shortest rest length seen at the last accumulate [m]
};

}  // namespace wirepack
