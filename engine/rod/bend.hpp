#pragma once
// Isotropic bending energy of the discrete rod (Bergou et al. 2008): at interior node i with
// turning angle phi_i, the curvature binormal has |kappa b_i| = 2 tan(phi_i / 2) and
//   U_b = sum_i E I |kappa b_i|^2 / (2 lbar_i),   lbar_i = (lbar_{i-1} + lbar_i) / 2,
// the discrete form of 1/2 int E I kappa^2 ds (paper Eq. (1)). With c = t_{i-1} . t_i,
// |kappa b|^2 = 4 (1 - c) / (1 + c), so the energy depends on c alone.
#include "engine/term.hpp"

namespace wirepack {

class BendTerm : public Term {
 public:
  explicit BendTerm(double EI) : EI_(EI) {}
  std::string name() const override { return "bend"; }
  TermType type() const override { return TermType::kBend; }
  double accumulate(const State& s, Forces& out) override;
  double energy(const State& s) override;
  double omega_max_sq(const RodInertia& inertia) const override;

 private:
  double EI_;              // bending stiffness [N m^2]
  double min_rest_ = 0.0;  // shortest rest length at the last accumulate [m]
};

}  // namespace wirepack
