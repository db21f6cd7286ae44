#pragma once
// Twisting energy of the discrete rod (Bergou et al. 2010):
//   U_t = sum_i G J m_i^2 / (2 lbar_i),   m_i = theta_i - theta_{i-1} + ref_twist_i,
// the discrete form of 1/2 int G J k_3^2 ds (paper Eq. (1)). The position gradient uses
// d ref_twist_i / d e^{i-1} = kb_i / (2 |e^{i-1}|), d ref_twist_i / d e^i = kb_i / (2 |e^i|)
// with the curvature binormal kb_i = 2 t_{i-1} x t_i / (1 + t_{i-1} . t_i). accumulate()
// expects reference frames updated to the current positions (update_reference_frames).
#include <algorithm>

#include "engine/term.hpp"

namespace wirepack {

// Nodes i in [1, end) carry twist and its dashpot: all interior nodes, or, with a swivel at the
// hole (free_at_guide), those before the node n_free - 1 that joins the last free edge to the
// guide.
inline int twist_end_node(const State& s, bool free_at_guide) {
  const int n = s.num_nodes();
  return free_at_guide ? std::min(n - 1, s.n_free - 1) : n - 1;
}

class TwistTerm : public Term {
 public:
  // free_at_guide: a swivel at the hole (FeederSpin::Free): the sum stops before the node that
  // joins the last free edge to the guide, so no twisting moment is transmitted there.
  explicit TwistTerm(double GJ, bool free_at_guide = false)
      : GJ_(GJ), free_at_guide_(free_at_guide) {}
  std::string name() const override { return "twist"; }
  TermType type() const override { return TermType::kTwist; }
  double accumulate(const State& s, Forces& out) override;
  // Transports the reference frames of a copy of `s` to its positions first, so the energy is
  // a function of (x, theta) given the stored frames: this is what finite differences see.
  double energy(const State& s) override;
  double omega_max_sq(const RodInertia& inertia) const override;

 private:
  double GJ_;  // torsional stiffness [N m^2]
  bool free_at_guide_;
  double min_rest_ = 0.0;  // shortest rest length at the last accumulate [m]
};

}  // namespace wirepack
