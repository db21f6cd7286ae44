#include "engine/contact/sphere_wall.hpp"

#include <algorithm>
#include <cmath>

namespace wirepack {

SphereWallTerm::SphereWallTerm(const SphereWallParams& p)
    : FrictionalTerm(p.friction),
      p_(p),
      wall_(Hertz::from(p.E_star, p.r * p.R / (p.R - p.r))),
      rim_(Hertz::from(p.E_star, p.r)),
      z_rim_(-std::sqrt(p.R * p.R - p.hole_radius * p.hole_radius)),
      free_radius2_((p.R - p.r) * (p.R - p.r) * (1.0 - 1e-12)) {}

bool SphereWallTerm::overlap(const Vec3& x, double& delta, Vec3& normal, bool& rim) const {
  const double rho_perp2 = x[0] * x[0] + x[1] * x[1];
  rim = x[2] < 0.0 && rho_perp2 < p_.hole_radius * p_.hole_radius && x[2] < z_rim_ + 2.0 * p_.r;
  if (rim) {
    // Nearest point of the rim circle; the node pushes away from it.
    const double rho_perp = std::sqrt(rho_perp2);
    Vec3 radial = rho_perp > 0 ? Vec3(x[0] / rho_perp, x[1] / rho_perp, 0.0) : Vec3::UnitX();
    const Vec3 rim_point = p_.hole_radius * radial + Vec3(0, 0, z_rim_);
    const Vec3 d = rim_point - x;  // from the node towards the rim
    const double dist = d.norm();
    delta = p_.r - dist;
    if (delta <= 0.0 || dist == 0.0) return false;
    normal = d / dist;
    return true;
  }
  // Clearly inside (|x| < R - r with a margin far above rounding): no square root needed.
  const double sq = x.squaredNorm();
  if (sq < free_radius2_) {
    delta = -1.0;
    return false;
  }
  const double dist = std::sqrt(sq);
  delta = dist + p_.r - p_.R;
  if (delta <= 0.0 || dist == 0.0) return false;
  normal = x / dist;
  return true;
}

double SphereWallTerm::accumulate(const State& s, Forces& out) {
  double U = 0.0;
  touching_.clear();
  for (int i = 0; i < s.n_free; ++i) {
    double delta;
    Vec3 n;
    bool rim;
    if (!overlap(s.x[i], delta, n, rim)) continue;
    U += (rim ? rim_ : wall_).energy(delta);
    touching_.push_back(Touch{i, delta, n, rim});
  }
  double kmax = 0.0;
  if (friction_) {
    for (const Touch& t : touching_) friction_->mark(ContactKey{t.node, -1});
    friction_->finish_marking();
  }
  const bool twist = s.has_twist();
  const double r = p_.r;
  for (const Touch& t : touching_) {
    const int i = t.node;
    const Hertz& h = t.rim ? rim_ : wall_;
    const Vec3& n = t.normal;               // from the node towards the wall
    const double approach = s.v[i].dot(n);  // speed towards the wall [m/s]
    const double fn = damped_normal_force(h, t.delta, approach, p_.damping_ratio, p_.node_mass);
    out.f[i] -= fn * n;
    const double kn = h.stiffness(t.delta);
    kmax = std::max(kmax, kn);
    if (!friction_) continue;
    // Surface point of the wire at the contact: x_i + r n; its velocity includes the spin of
    // the adjacent edges (omega t x r n), averaged over the two edges of the node.
    // Weights w_e of the node's edges (1/2 each, 1 at an end): the same weights spread the
    // torque, so the friction power is the same seen from the forces and from the velocities.
    Vec3 v_surf = s.v[i];
    const int e_lo = std::max(i - 1, 0), e_hi = std::min(i, s.num_edges() - 1);
    const double w = e_hi > e_lo ? 0.5 : 1.0;
    if (twist) {
      for (int e = e_lo; e <= e_hi; ++e) v_surf += w * s.omega[e] * out.edge_t[e].cross(r * n);
    }
    // The wall is body B (at rest); the normal of the contact points from B to A: -n.
    // Neighbours: the nodes beside i, in that order (the tip, node 0, has only node 1).
    const ContactKey both[2] = {{i - 1, -1}, {i + 1, -1}};
    const ContactKey* nb = i > 0 ? both : both + 1;
    const Vec3 ft =
        friction_->force(ContactKey{i, -1}, -n, fn, kn, v_surf, p_.node_mass, nb, i > 0 ? 2 : 1);
    out.f[i] += ft;
    if (twist) {
      // Torque of the surface force about the centreline, shared by the two edges.
      for (int e = e_lo; e <= e_hi; ++e) out.torque[e] += w * (r * n).cross(ft).dot(out.edge_t[e]);
    }
  }
  max_stiffness_ = kmax * (friction_ ? 1.0 + p_.friction.stiffness_ratio : 1.0);
  contacts_ = static_cast<int>(touching_.size());
  return U;
}

double SphereWallTerm::energy(const State& s) {
  double U = 0.0;
  for (int i = 0; i < s.n_free; ++i) {
    double delta;
    Vec3 n;
    bool rim;
    if (overlap(s.x[i], delta, n, rim)) U += (rim ? rim_ : wall_).energy(delta);
  }
  return U;
}

double SphereWallTerm::omega_max_sq(const RodInertia&) const {
  return max_stiffness_ / p_.node_mass;
}

template <class Self, class Archive>
void SphereWallTerm::serialize(Self& t, Archive& ar) {
  ar.tag("WALL");
  serialize_friction(ar, t.friction_.get());
}

void SphereWallTerm::save(StateWriter& out) const {
  serialize(*this, out);
}
void SphereWallTerm::load(StateReader& in) {
  serialize(*this, in);
}

}  // namespace wirepack
