#include "engine/integrate/damping.hpp"

#include <algorithm>

#include "engine/rod/twist.hpp"

namespace wirepack {

void RodDamping::add_forces(const State& s, Forces& out) const {
  const int n = s.num_nodes();
  const int nf = s.n_free;
  if (n < 2) return;
  // Edge tangents (computed by out.reset) serve both the axial and the transverse parts.
  Vec3 t_prev = Vec3::Zero();
  tau_.resize(n);  // node tangents of the free nodes, shared with the bending-rate dashpot
  for (int j = 0; j < n - 1 && j < nf; ++j) {
    const Vec3& t = out.edge_t[j];
    // Axial dashpot on edge j (acts on the dynamic nodes only; the guide is kinematic).
    const double rate = (s.v[j + 1] - s.v[j]).dot(t);
    const Vec3 fa = (p_.eta_axial * rate) * t;
    out.f[j] += fa;
    out.f[j + 1] -= fa;
    // Transverse damping of node j about its tangent tau_j (absolute form: the whole v_j).
    const Vec3 tau = j == 0 ? t : (t_prev + t).normalized();
    tau_[j] = tau;
    const Vec3& v = s.v[j];
    const double m_gamma = p_.c_transverse;
    out.f[j] -= p_.absolute ? Vec3(m_gamma * v) : Vec3(m_gamma * (v - v.dot(tau) * tau));
    t_prev = t;
  }
  if (p_.eta_bending > 0.0) {
    // Bending-rate dashpot at interior nodes i with a dynamic neighbourhood: w_i = eta P_i d2v_i,
    // forces -dD/dv: -w_i on i - 1 and i + 1, +2 w_i on i (rows of the guide are dropped).
    for (int i = 1; i < n - 1 && i <= nf; ++i) {
      // tau_i from the loop above; the first guide node (i = nf) has none there.
      const Vec3 tau = i < nf ? tau_[i] : Vec3((out.edge_t[i - 1] + out.edge_t[i]).normalized());
      const Vec3 d2 = s.v[i - 1] - 2.0 * s.v[i] + s.v[i + 1];
      const Vec3 w = p_.eta_bending * (d2 - d2.dot(tau) * tau);
      out.f[i - 1] -= w;
      out.f[i] += 2.0 * w;
      out.f[i + 1] -= w;
    }
  }
  if (!s.has_twist()) return;
  const int end = twist_end_node(s, p_.twist_free_at_guide);  // the same nodes as the twist sum
  if (p_.absolute) {
    // Spin drag of every dynamic edge (j + 1 < n_free): -gamma I_theta omega_j [N m].
    for (int j = 0; j + 1 < nf; ++j) out.torque[j] -= p_.c_spin * s.omega[j];
  }
  for (int i = 1; i < end; ++i) {
    const double rel = s.omega[i] - s.omega[i - 1];
    out.torque[i] -= p_.eta_twist * rel;
    out.torque[i - 1] += p_.eta_twist * rel;
  }
}

}  // namespace wirepack
