#pragma once
// Mass matrix of the wire's translational DOFs. Two models:
//  - uniform (the classic mass scaling): M = m_s I, every mode of the wire carries the scaled
//    density rho_eff = E q^2 / v^2;
//  - selective (after the idea of selective mass scaling in explicit FEM, Olovsson et al.,
//    IJNME 2005): M = m_p I + beta L, with m_p the physical node mass, L the graph Laplacian of
//    the chain of nodes (unit weights: (L x)_i = 2 x_i - x_{i-1} - x_{i+1}) and
//    beta = (m_s - m_p) / 4, so that the element-scale zig-zag mode (eigenvalue 4 of L), which
//    bounds the explicit step, keeps the scaled mass m_s, while a rigid translation (L 1 = 0)
//    and a slow slide along a smooth curve (|L v| ~ (l kappa)^2 |v|) carry the physical mass.
// The guide outside the hole is kinematic at constant velocity (acceleration 0): the edge between
// the last free node and the guide adds beta to that node's diagonal and nothing else.
// Solving M a = f is one tridiagonal (Thomas) solve shared by the three components, O(n).
// The twist DOFs (one angle per edge) get the same model along the chain of edges: with
// friction a wire rolls (omega r = v), and a spin inertia at the scaled density would give a
// rolling wire half the uniform scaling's kinetic energy.
#include <vector>

#include "engine/types.hpp"

namespace wirepack {

class WireMass {
 public:
  // m_p: node mass of the slow modes [kg]; beta: Laplacian mass [kg] (0: uniform, M = m_p I).
  WireMass(double m_p, double beta);
  WireMass() : WireMass(1.0, 0.0) {}
  // The effective masses that follow from the two parameters [kg]:
  //  - mode_mass: of the zig-zag mode, m_p + 4 beta (the internal terms' stability bound);
  //  - point_mass: 1 / (M^-1)_00 at the free tip of a long chain, the smallest effective mass
  //    a point load sees (contacts: stability bound and dashpots); m_p for uniform mass.
  double mode_mass() const { return m_ + 4.0 * beta_; }
  double point_mass() const { return point_mass_; }
  double slow_mass() const { return m_; }
  double beta() const { return beta_; }
  bool uniform() const { return beta_ == 0.0; }

  // Factorises M for nodes [0, n_free) (tip first); `joined_to_guide`: node n_free - 1 has an
  // edge to a kinematic node.
  void factorise(int n_free, bool joined_to_guide);
  // a[i] = (M^-1 f)[i] for the free nodes of the last factorisation, a[i] = 0 for i >= n_free;
  // a is resized to f.size(). Vec3 per node, or double per edge (twist).
  void solve(const Vec3List& f, Vec3List& a) const;
  void solve(const std::vector<double>& f, std::vector<double>& a) const;
  // Kinetic energy 1/2 v^T M v of the free nodes, the edge to the (moving) guide included when
  // `joined_to_guide` (as in factorise) [J].
  double kinetic_energy(const Vec3List& v, int n_free, bool joined_to_guide = true) const;
  double kinetic_energy(const std::vector<double>& v, int n_free,
                        bool joined_to_guide = true) const;
  // Linear momentum M v summed over the free nodes (the guide edge's coupling included) [kg m/s].
  Vec3 momentum(const Vec3List& v, int n_free) const;

 private:
  template <class T>
  void solve_impl(const std::vector<T>& f, std::vector<T>& a) const;
  template <class T>
  double kinetic_impl(const std::vector<T>& v, int n_free, bool joined_to_guide) const;

  double m_, beta_, point_mass_;
  double inv_m_;
  int n_ = 0;
  std::vector<double> inv_pivot_;  // 1 / d_i of the forward elimination (n)
};

}  // namespace wirepack
