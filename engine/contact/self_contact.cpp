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

int SelfContactTerm::find_contact(int a, int b) const {
  const auto it = std::lower_bound(contacts_.begin(), contacts_.end(), std::make_pair(a, b),
                                   [](const WireContact& c, const std::pair<int, int>& k) {
                                     return std::make_pair(c.a, c.b) < k;
                                   });
  return it != contacts_.end() && it->a == a && it->b == b
             ? static_cast<int>(it - contacts_.begin())
             : -1;
}

namespace {

// Parameter of the point of segment [b0, b1] closest to x, in [0, 1].
double closest_on_segment(const Vec3& x, const Vec3& b0, const Vec3& b1) {
  const Vec3 d = b1 - b0;
  const double dd = d.squaredNorm();
  if (dd == 0.0) return 0.0;
  return std::clamp((x - b0).dot(d) / dd, 0.0, 1.0);
}

}  // namespace

double SelfContactTerm::evaluate(const RodState& s, RodForces* out) {
  maybe_rebuild(s);
  const int ne = active_edges(s);
  const double contact = 2.0 * p_.r;
  const double m_eff = 0.5 * p_.node_mass;
  double U = 0.0;
  contacts_.clear();
  // Edge pairs: capsule against capsule (candidates are sorted, so contacts_ is too).
  for (const auto& [a, b] : candidates_) {
    const Vec3 &a0 = s.x[a], &a1 = s.x[a + 1], &b0 = s.x[b], &b1 = s.x[b + 1];
    const SegmentClosest c = segment_segment_closest(a0, a1, b0, b1);
    if (c.dist2 >= contact * contact) continue;
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
    WireContact w{a, b, c.s, c.t, n, contact - dist, 0.0};
    U += hertz_.energy(w.delta);
    contacts_.push_back(w);
  }
  if (out) {
    for (WireContact& c : contacts_) {
      const Vec3 va = (1.0 - c.s) * s.v[c.a] + c.s * s.v[c.a + 1];
      const Vec3 vb = (1.0 - c.t) * s.v[c.b] + c.t * s.v[c.b + 1];
      c.force =
          damped_normal_force(hertz_, c.delta, -(va - vb).dot(c.normal), p_.damping_ratio, m_eff);
      const Vec3 F = c.force * c.normal;
      out->f[c.a] += (1.0 - c.s) * F;
      out->f[c.a + 1] += c.s * F;
      out->f[c.b] -= (1.0 - c.t) * F;
      out->f[c.b + 1] -= c.t * F;
    }
  }
  // Joint corrections (inclusion-exclusion), each owned by the pair (a, b) at its lower-left:
  // the ball of joint a+1 against edge b and the ball of joint b+1 against edge a are
  // subtracted, the two balls against each other added back. A correction only matters where
  // the pair (a, b) itself touches (a ball is inside its edge's capsule).
  const size_t num_pairs = contacts_.size();
  for (size_t k = 0; k < num_pairs; ++k) {
    const int a = contacts_[k].a, b = contacts_[k].b;
    const bool ja = pair_valid(a + 1, b, ne);  // joint a+1 is shared by pairs (a,b), (a+1,b)
    const bool jb = b + 1 < ne;                // joint b+1 is shared by pairs (a,b), (a,b+1)
    struct Part {
      int node;        // the joint node
      int e0, e1;      // the edge it is checked against (nodes e0, e0+1) or, for ball-ball, -1
      int other;       // ball-ball: the other joint node
      double sign;     // -1 subtract, +1 add back
      int k2, k3, k4;  // the other pairs that share this correction
    };
    Part parts[3];
    int np = 0;
    if (ja) parts[np++] = Part{a + 1, b, b + 1, -1, -1.0, find_contact(a + 1, b), -1, -1};
    if (jb) parts[np++] = Part{b + 1, a, a + 1, -1, -1.0, find_contact(a, b + 1), -1, -1};
    if (ja && jb && pair_valid(a + 1, b + 1, ne)) {
      parts[np++] = Part{a + 1,
                         -1,
                         -1,
                         b + 1,
                         +1.0,
                         find_contact(a + 1, b),
                         find_contact(a, b + 1),
                         find_contact(a + 1, b + 1)};
    }
    for (int q = 0; q < np; ++q) {
      const Part& pt = parts[q];
      const Vec3& x = s.x[pt.node];
      double t = 0.0;
      Vec3 y;  // the closest point of the other body [m]
      Vec3 vy;
      if (pt.e0 >= 0) {
        t = closest_on_segment(x, s.x[pt.e0], s.x[pt.e1]);
        y = s.x[pt.e0] + t * (s.x[pt.e1] - s.x[pt.e0]);
        vy = (1.0 - t) * s.v[pt.e0] + t * s.v[pt.e1];
      } else {
        y = s.x[pt.other];
        vy = s.v[pt.other];
      }
      const Vec3 d = x - y;
      const double dist2 = d.squaredNorm();
      if (dist2 >= contact * contact || dist2 == 0.0) continue;
      const double dist = std::sqrt(dist2);
      const double delta = contact - dist;
      U += pt.sign * hertz_.energy(delta);
      if (!out) continue;
      const Vec3 n = d / dist;
      const double f =
          damped_normal_force(hertz_, delta, -(s.v[pt.node] - vy).dot(n), p_.damping_ratio, m_eff);
      const Vec3 F = pt.sign * f * n;  // on the joint node; -F on the other body
      out->f[pt.node] += F;
      if (pt.e0 >= 0) {
        out->f[pt.e0] -= (1.0 - t) * F;
        out->f[pt.e1] -= t * F;
      } else {
        out->f[pt.other] -= F;
      }
      // Share the correction among the pairs it belongs to (their friction bounds).
      const int ks[4] = {static_cast<int>(k), pt.k2, pt.k3, pt.k4};
      const int owners = pt.e0 >= 0 ? 2 : 4;
      for (int o = 0; o < owners; ++o) {
        if (ks[o] >= 0) contacts_[ks[o]].force += pt.sign * f / owners;
      }
    }
  }
  return U;
}

double SelfContactTerm::accumulate(const RodState& s, RodForces& out) {
  const double U = evaluate(s, &out);
  double kmax = 0.0;
  for (const WireContact& c : contacts_) kmax = std::max(kmax, hertz_.stiffness(c.delta));
  if (friction_) {
    for (const WireContact& c : contacts_) friction_->mark(ContactKey{c.a, c.b});
    friction_->finish_marking();
    // Coulomb friction at the surfaces of every pair, bounded by its net normal force.
    const double m_eff = 0.5 * p_.node_mass;
    const bool twist = s.has_twist();
    const double r = p_.r;
    for (const WireContact& c : contacts_) {
      const int a = c.a, b = c.b;
      const Vec3& n = c.normal;  // from b to a
      const double fn = std::max(c.force, 0.0);
      // Surface points: a at -r n from its axis, b at +r n; spin adds omega t x (offset).
      Vec3 v_rel =
          (1.0 - c.s) * s.v[a] + c.s * s.v[a + 1] - (1.0 - c.t) * s.v[b] - c.t * s.v[b + 1];
      Vec3 ta, tb;
      if (twist) {
        ta = (s.x[a + 1] - s.x[a]).normalized();
        tb = (s.x[b + 1] - s.x[b]).normalized();
        v_rel += s.omega[a] * ta.cross(-r * n) - s.omega[b] * tb.cross(r * n);
      }
      const ContactKey nb[8] = {{a + 1, b},     {a - 1, b},     {a, b + 1},     {a, b - 1},
                                {a + 1, b + 1}, {a - 1, b - 1}, {a + 1, b - 1}, {a - 1, b + 1}};
      const Vec3 ft =
          friction_->force(ContactKey{a, b}, n, fn, hertz_.stiffness(c.delta), v_rel, m_eff, nb, 8);
      out.f[a] += (1.0 - c.s) * ft;
      out.f[a + 1] += c.s * ft;
      out.f[b] -= (1.0 - c.t) * ft;
      out.f[b + 1] -= c.t * ft;
      if (twist) {
        out.torque[a] += (-r * n).cross(ft).dot(ta);
        out.torque[b] += (r * n).cross(-ft).dot(tb);
      }
    }
  }
  max_stiffness_ = kmax * (friction_ ? 1.0 + p_.friction.stiffness_ratio : 1.0);
  return U;
}

double SelfContactTerm::energy(const RodState& s) {
  return evaluate(s, nullptr);
}

double SelfContactTerm::omega_max_sq(const RodInertia& inertia) const {
  // The force of one contact is shared by two nodes per edge: effective mass m / 2.
  return 2.0 * max_stiffness_ / inertia.node_mass;
}

}  // namespace wirepack
