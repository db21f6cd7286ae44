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
  if (p.friction.enabled()) friction_ = std::make_unique<FrictionHistory>(p.friction);
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

// A closest point at the far end of an edge is the same point as the start of the next edge of
// that polyline: counting it on both would double the force where a wire crosses a joint of
// the other (a bump at every element boundary). The pair with the next edge owns it, unless
// that pair is excluded as neighbours along the wire.
bool SelfContactTerm::shared_endpoint(const SegmentClosest& c, int a, int b, int ne) const {
  if (c.t == 1.0 && b + 1 < ne) return true;
  if (c.s == 1.0 && a + 1 < ne && b - (a + 1) > exclude_) return true;
  return false;
}

double SelfContactTerm::accumulate(const RodState& s, RodForces& out) {
  maybe_rebuild(s);
  const int ne = active_edges(s);
  contacts_.clear();
  double U = 0.0;
  const double contact = 2.0 * p_.r;
  // Narrow phase: every touching pair with its closest points and normal.
  for (const auto& [a, b] : candidates_) {
    const Vec3 &a0 = s.x[a], &a1 = s.x[a + 1], &b0 = s.x[b], &b1 = s.x[b + 1];
    const SegmentClosest c = segment_segment_closest(a0, a1, b0, b1);
    if (c.dist2 >= contact * contact || shared_endpoint(c, a, b, ne)) continue;
    const double dist = std::sqrt(c.dist2);
    Vec3 n;
    if (dist > 1e-12 * p_.r) {
      n = (a0 + c.s * (a1 - a0) - b0 - c.t * (b1 - b0)) / dist;
    } else {
      // Axes intersect: push apart along the common normal of the two segments.
      n = (a1 - a0).cross(b1 - b0);
      if (n.squaredNorm() == 0.0) continue;
      n.normalize();
    }
    const double delta = contact - dist;
    U += hertz_.energy(delta);
    contacts_.push_back(WireContact{a, b, c.s, c.t, n, delta, 0.0});
  }
  if (friction_) {
    for (const WireContact& c : contacts_) friction_->mark(ContactKey{c.a, c.b});
    friction_->finish_marking();
  }
  // Forces: Hertz + normal dashpot, then Coulomb friction at the surfaces.
  double kmax = 0.0;
  const double m_eff = 0.5 * p_.node_mass;
  const bool twist = s.has_twist();
  const double r = p_.r;
  for (WireContact& c : contacts_) {
    const int a = c.a, b = c.b;
    const Vec3& n = c.normal;  // from b to a
    const Vec3 va = (1.0 - c.s) * s.v[a] + c.s * s.v[a + 1];
    const Vec3 vb = (1.0 - c.t) * s.v[b] + c.t * s.v[b + 1];
    const double approach = -(va - vb).dot(n);
    const double fn = damped_normal_force(hertz_, c.delta, approach, p_.damping_ratio, m_eff);
    c.force = fn;
    Vec3 F = fn * n;  // on edge a; -F on edge b
    const double kn = hertz_.stiffness(c.delta);
    kmax = std::max(kmax, kn);
    Vec3 ta, tb;
    if (friction_) {
      // Surface points: a at -r n from its axis, b at +r n; spin adds omega t x (offset).
      Vec3 v_rel = va - vb;
      if (twist) {
        ta = (s.x[a + 1] - s.x[a]).normalized();
        tb = (s.x[b + 1] - s.x[b]).normalized();
        v_rel += s.omega[a] * ta.cross(-r * n) - s.omega[b] * tb.cross(r * n);
      }
      const ContactKey nb[8] = {{a + 1, b},     {a - 1, b},     {a, b + 1},     {a, b - 1},
                                {a + 1, b + 1}, {a - 1, b - 1}, {a + 1, b - 1}, {a - 1, b + 1}};
      const Vec3 ft = friction_->force(ContactKey{a, b}, n, fn, kn, v_rel, m_eff, nb, 8);
      F += ft;
      if (twist) {
        out.torque[a] += (-r * n).cross(ft).dot(ta);
        out.torque[b] += (r * n).cross(-ft).dot(tb);
      }
    }
    out.f[a] += (1.0 - c.s) * F;
    out.f[a + 1] += c.s * F;
    out.f[b] -= (1.0 - c.t) * F;
    out.f[b + 1] -= c.t * F;
  }
  max_stiffness_ = kmax * (friction_ ? 1.0 + p_.friction.stiffness_ratio : 1.0);
  return U;
}

double SelfContactTerm::energy(const RodState& s) {
  maybe_rebuild(s);
  const int ne = active_edges(s);
  double U = 0.0;
  const double contact = 2.0 * p_.r;
  for (const auto& [a, b] : candidates_) {
    const SegmentClosest c = segment_segment_closest(s.x[a], s.x[a + 1], s.x[b], s.x[b + 1]);
    if (c.dist2 >= contact * contact || shared_endpoint(c, a, b, ne)) continue;
    U += hertz_.energy(contact - std::sqrt(c.dist2));
  }
  return U;
}

double SelfContactTerm::omega_max_sq(const RodInertia& inertia) const {
  // The force of one contact is shared by two nodes per edge: effective mass m / 2.
  return 2.0 * max_stiffness_ / inertia.node_mass;
}

}  // namespace wirepack
