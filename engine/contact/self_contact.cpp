#include "engine/contact/self_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/contact/segment_distance.hpp"
#include "engine/contact/verlet.hpp"

namespace wirepack {

SelfContactTerm::SelfContactTerm(const SelfContactParams& p)
    : FrictionalTerm(p.friction), p_(p), hertz_(Hertz::from(p.E_star, p.r)) {
  // Exclude |a - b| - 1 edges of arc-length gap shorter than pi r (a hairpin of radius r).
  exclude_ = static_cast<int>(std::ceil(1.0 + M_PI * p.r / p.element_length)) - 1;
  exclude_ = std::max(exclude_, 1);
}

void SelfContactTerm::maybe_rebuild(const State& s) {
  const int ne = active_edges(s);
  if (ne != edges_at_build_ || ref_.moved_beyond(s.x, std::min(ne + 1, s.num_nodes()), p_.skin))
    rebuild(s);
}

void SelfContactTerm::rebuild(const State& s) {
  const int ne = active_edges(s);
  ++rebuilds_;
  edges_at_build_ = ne;
  ref_.build(s.x, std::min(ne + 1, s.num_nodes()));
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
  // Distances in parallel (each pair its own entry), the list in the broad phase's order.
  const int nb = static_cast<int>(broad_.size());
  broad_geo_.resize(nb);
#pragma omp parallel for schedule(dynamic, 64)
  for (int k = 0; k < nb; ++k) {
    const auto [a, b] = broad_[k];
    if (b - a <= exclude_) continue;
    broad_geo_[k] = segment_segment_closest(s.x[a], s.x[a + 1], s.x[b], s.x[b + 1]);
  }
  for (int k = 0; k < nb; ++k) {
    const auto [a, b] = broad_[k];
    if (b - a <= exclude_) continue;
    const double dist2 = broad_geo_[k].dist2;
    if (dist2 >= reach * reach) continue;
    candidates_.push_back(Candidate{a, b, quarter_slack2(dist2, 2.0 * p_.r, p_.r)});
  }
}

double SelfContactTerm::evaluate(const State& s, Forces* out) {
  maybe_rebuild(s);
  const double contact = 2.0 * p_.r;
  const double m_eff = 0.5 * p_.node_mass;
  double U = 0.0;
  contacts_.clear();
  // Closest points in parallel (each candidate its own entry); the forces below in order.
  const int nc = static_cast<int>(candidates_.size());
  geo_.resize(nc);
#pragma omp parallel for schedule(dynamic, 64)
  for (int k = 0; k < nc; ++k) {
    const int a = candidates_[k].a, b = candidates_[k].b;
    // Cannot touch yet: each end moved less than half the slack since the build.
    const double moved2 = std::max(std::max(ref_.moved2[a], ref_.moved2[a + 1]),
                                   std::max(ref_.moved2[b], ref_.moved2[b + 1]));
    if (moved2 < candidates_[k].slack2_4) {
      geo_[k].dist2 = std::numeric_limits<double>::infinity();
      continue;
    }
    geo_[k] = segment_segment_closest(s.x[a], s.x[a + 1], s.x[b], s.x[b + 1]);
  }
  for (int k = 0; k < nc; ++k) {
    const SegmentClosest& c = geo_[k];
    if (c.dist2 >= contact * contact) continue;
    const int a = candidates_[k].a, b = candidates_[k].b;
    const Vec3 &a0 = s.x[a], &a1 = s.x[a + 1], &b0 = s.x[b], &b1 = s.x[b + 1];
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
    if (out) {
      const Vec3 va = (1.0 - c.s) * s.v[a] + c.s * s.v[a + 1];
      const Vec3 vb = (1.0 - c.t) * s.v[b] + c.t * s.v[b + 1];
      w.force = damped_normal_force(hertz_, w.delta, -(va - vb).dot(n), p_.damping_ratio, m_eff);
      const Vec3 F = w.force * n;  // on edge a; -F on edge b
      out->f[a] += (1.0 - c.s) * F;
      out->f[a + 1] += c.s * F;
      out->f[b] -= (1.0 - c.t) * F;
      out->f[b + 1] -= c.t * F;
    }
    contacts_.push_back(w);
  }
  return U;
}

double SelfContactTerm::accumulate(const State& s, Forces& out) {
  const double U = evaluate(s, &out);
  double kmax = 0.0;
  for (const WireContact& c : contacts_) kmax = std::max(kmax, hertz_.stiffness(c.delta));
  if (friction_) {
    for (const WireContact& c : contacts_) friction_->mark(ContactKey{c.a, c.b});
    friction_->finish_marking();
    // Coulomb friction at the surfaces of every pair, bounded by its net normal force. The
    // queries in parallel (each its own entry), the forces added in pair order.
    const double m_eff = 0.5 * p_.node_mass;
    const bool twist = s.has_twist();
    const double r = p_.r;
    const int nc = static_cast<int>(contacts_.size());
    queries_.resize(nc);
#pragma omp parallel for schedule(dynamic, 64)
    for (int i = 0; i < nc; ++i) {
      const WireContact& c = contacts_[i];
      const int a = c.a, b = c.b;
      const Vec3& n = c.normal;  // from b to a
      // Surface points: a at -r n from its axis, b at +r n; spin adds omega t x (offset).
      Vec3 v_rel =
          (1.0 - c.s) * s.v[a] + c.s * s.v[a + 1] - (1.0 - c.t) * s.v[b] - c.t * s.v[b + 1];
      if (twist) {
        v_rel += s.omega[a] * out.edge_t[a].cross(-r * n) - s.omega[b] * out.edge_t[b].cross(r * n);
      }
      FrictionHistory::Query& q = queries_[i];
      q.key = ContactKey{a, b};
      q.n = n;
      q.F_n = std::max(c.force, 0.0);
      q.k_n = hertz_.stiffness(c.delta);
      q.v_rel = v_rel;
      q.m_eff = m_eff;
      const ContactKey nb[8] = {{a + 1, b},     {a - 1, b},     {a, b + 1},     {a, b - 1},
                                {a + 1, b + 1}, {a - 1, b - 1}, {a + 1, b - 1}, {a - 1, b + 1}};
      std::copy(nb, nb + 8, q.neighbours);
      q.num_neighbours = 8;
    }
    friction_->forces(queries_, friction_force_);
    for (int i = 0; i < nc; ++i) {
      const WireContact& c = contacts_[i];
      const int a = c.a, b = c.b;
      const Vec3& n = c.normal;
      const Vec3& ft = friction_force_[i];
      out.f[a] += (1.0 - c.s) * ft;
      out.f[a + 1] += c.s * ft;
      out.f[b] -= (1.0 - c.t) * ft;
      out.f[b + 1] -= c.t * ft;
      if (twist) {
        out.torque[a] += (-r * n).cross(ft).dot(out.edge_t[a]);
        out.torque[b] += (r * n).cross(-ft).dot(out.edge_t[b]);
      }
    }
  }
  max_stiffness_ = kmax * (friction_ ? 1.0 + p_.friction.stiffness_ratio : 1.0);
  return U;
}

double SelfContactTerm::energy(const State& s) {
  return evaluate(s, nullptr);
}

double SelfContactTerm::omega_max_sq(const RodInertia&) const {
  // The force of one contact is shared by two nodes per edge: effective mass m / 2.
  return 2.0 * max_stiffness_ / p_.node_mass;
}

template <class Self, class Archive>
void SelfContactTerm::serialize(Self& t, Archive& ar) {
  ar.tag("SELF");
  ar(t.edges_at_build_);
  ar(t.rebuilds_);
  ar(t.ref_.at_build);
  ar(t.candidates_);
  serialize_friction(ar, t.friction_.get());
}

void SelfContactTerm::save(StateWriter& out) const {
  serialize(*this, out);
}
void SelfContactTerm::load(StateReader& in) {
  serialize(*this, in);
}

}  // namespace wirepack
