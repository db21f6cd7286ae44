#include "engine/contact/self_contact.hpp"

#include <algorithm>
#include <cmath>

#include "engine/contact/segment_distance.hpp"

namespace wirepack {

SelfContactTerm::SelfContactTerm(const SelfContactParams& p)
    : p_(p), hertz_(Hertz::from(p.E_star, p.r)) {
  // Exclude |a - b| - 1 edges of arc-length gap shorter than pi r (a hairpin of radius r).
  exclude_ = static_cast<int>(std::ceil(1.0 + M_PI * p.r / p.element_length)) - 1;
  exclude_ = std::max(exclude_, 1);
}

void SelfContactTerm::maybe_rebuild(const RodState& s) {
  const int ne = active_edges(s);
  bool need = ne != edges_at_build_;
  if (!need) {
    const double limit2 = 0.25 * p_.skin * p_.skin;
    const int nn = std::min(ne + 1, s.num_nodes());
    for (int i = 0; i < nn && !need; ++i) need = (s.x[i] - x_at_build_[i]).squaredNorm() > limit2;
  }
  if (need) rebuild(s);
}

void SelfContactTerm::rebuild(const RodState& s) {
  const int ne = active_edges(s);
  ++rebuilds_;
  edges_at_build_ = ne;
  x_at_build_.assign(s.x.begin(), s.x.begin() + std::min(ne + 1, s.num_nodes()));
  candidates_.clear();
  if (ne < 2) return;
  midpoints_.resize(ne);
  double lmax = 0.0;
  for (int j = 0; j < ne; ++j) {
    midpoints_[j] = 0.5 * (s.x[j] + s.x[j + 1]);
    lmax = std::max(lmax, (s.x[j + 1] - s.x[j]).squaredNorm());
  }
  lmax = std::sqrt(lmax);
  const double reach = 2.0 * p_.r + p_.skin;
  grid_.find_pairs(midpoints_, lmax + reach, broad_);
  for (const auto& [a, b] : broad_) {
    if (b - a <= exclude_) continue;
    const SegmentClosest c = segment_segment_closest(s.x[a], s.x[a + 1], s.x[b], s.x[b + 1]);
    if (c.dist2 < reach * reach) candidates_.emplace_back(a, b);
  }
}

double SelfContactTerm::accumulate(const RodState& s, RodForces& out) {
  maybe_rebuild(s);
  contacts_.clear();
  double U = 0.0;
  double kmax = 0.0;
  const double contact = 2.0 * p_.r;
  const double m_eff = 0.5 * p_.node_mass;
  for (const auto& [a, b] : candidates_) {
    const Vec3 &a0 = s.x[a], &a1 = s.x[a + 1], &b0 = s.x[b], &b1 = s.x[b + 1];
    const SegmentClosest c = segment_segment_closest(a0, a1, b0, b1);
    if (c.dist2 >= contact * contact) continue;
    const double dist = std::sqrt(c.dist2);
    const Vec3 pa = a0 + c.s * (a1 - a0);
    const Vec3 pb = b0 + c.t * (b1 - b0);
    Vec3 n;
    if (dist > 1e-12 * p_.r) {
      n = (pa - pb) / dist;
    } else {
      // Axes intersect: push apart along the common normal of the two segments.
      n = (a1 - a0).cross(b1 - b0);
      if (n.squaredNorm() == 0.0) continue;
      n.normalize();
    }
    const double delta = contact - dist;
    U += hertz_.energy(delta);
    const Vec3 va = (1.0 - c.s) * s.v[a] + c.s * s.v[a + 1];
    const Vec3 vb = (1.0 - c.t) * s.v[b] + c.t * s.v[b + 1];
    const double approach = -(va - vb).dot(n);
    const double f = damped_normal_force(hertz_, delta, approach, p_.damping_ratio, m_eff);
    const Vec3 F = f * n;  // on edge a; -F on edge b
    out.f[a] += (1.0 - c.s) * F;
    out.f[a + 1] += c.s * F;
    out.f[b] -= (1.0 - c.t) * F;
    out.f[b + 1] -= c.t * F;
    kmax = std::max(kmax, hertz_.stiffness(delta));
    contacts_.push_back(WireContact{a, b, c.s, c.t, n, delta, f});
  }
  max_stiffness_ = kmax;
  return U;
}

double SelfContactTerm::energy(const RodState& s) {
  maybe_rebuild(s);
  double U = 0.0;
  const double contact = 2.0 * p_.r;
  for (const auto& [a, b] : candidates_) {
    const SegmentClosest c = segment_segment_closest(s.x[a], s.x[a + 1], s.x[b], s.x[b + 1]);
    if (c.dist2 >= contact * contact) continue;
    U += hertz_.energy(contact - std::sqrt(c.dist2));
  }
  return U;
}

double SelfContactTerm::omega_max_sq(const RodInertia& inertia) const {
  // The force of one contact is shared by two nodes per edge: effective mass m / 2.
  return 2.0 * max_stiffness_ / inertia.node_mass;
}

}  // namespace wirepack
