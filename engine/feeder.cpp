#include "engine/feeder.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "engine/rod/frames.hpp"

namespace wirepack {

Feeder::Feeder(const FeederParams& p)
    : p_(p),
      z_hole_(-std::sqrt(p.R * p.R - p.hole_radius * p.hole_radius)),
      rng_(p.seed ^ 0x9e3779b97f4a7c15ULL) {
  // About two wire diameters of wire inside at the start (at least two elements).
  n_inside0_ = std::max(3, static_cast<int>(std::ceil(4.0 * p.r / p.element_length)) + 1);
  L0_ = (n_inside0_ - 0.5) * p.element_length;
}

State Feeder::initial_state() const {
  State s;
  const double ell = p_.element_length;
  const int n = n_inside0_ + p_.guide_nodes;
  std::mt19937_64 rng(p_.seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const double z_tip = z_hole_ + L0_;
  for (int i = 0; i < n; ++i) {
    Vec3 x(0.0, 0.0, z_tip - i * ell);
    if (i < n_inside0_) {
      // Deflection grows quadratically from the hole to the tip (a slightly bent cantilever),
      // with an independent random transverse component per node.
      const double s_rel = (x[2] - z_hole_) / L0_;
      x[0] += p_.deflection * s_rel * s_rel * gauss(rng);
      x[1] += p_.deflection * s_rel * s_rel * gauss(rng);
      if (p_.offset != 0.0) x[0] += p_.offset * s_rel * s_rel;
    }
    s.x.push_back(x);
  }
  s.v.assign(n, Vec3(0.0, 0.0, p_.speed));
  s.rest_length.assign(n - 1, ell);
  s.n_free = n_inside0_;
  if (p_.twist) {
    s.theta.assign(n - 1, 0.0);
    s.omega.assign(n - 1, 0.0);
    init_reference_frames(s, 0);
  }
  return s;
}

int Feeder::release(State& s) {
  int released = 0;
  std::normal_distribution<double> gauss(0.0, 1.0);
  while (s.n_free < s.num_nodes() && s.x[s.n_free][2] > z_hole_) {
    s.x[s.n_free][0] += p_.release_noise * gauss(rng_);
    s.x[s.n_free][1] += p_.release_noise * gauss(rng_);
    ++s.n_free;
    ++released;
    if (s.has_twist() && p_.spin_free && s.n_free >= 3) {
      // Edge j = n_free - 2 is now free; m_j = theta_j - theta_{j-1} + ref_twist_j = 0.
      const int j = s.n_free - 2;
      s.theta[j] = s.theta[j - 1] - s.ref_twist[j];
      s.omega[j] = s.omega[j - 1];
    }
    // Keep the guide length: append a node one element behind the tail, on the feed axis.
    const Vec3 tail = s.x.back();
    s.x.push_back(tail - Vec3(0.0, 0.0, p_.element_length));
    s.v.push_back(Vec3(0.0, 0.0, p_.speed));
    s.rest_length.push_back(p_.element_length);
    if (s.has_twist()) {
      s.theta.push_back(0.0);
      s.omega.push_back(0.0);
      s.ref_twist.push_back(0.0);
      init_reference_frames(s, s.num_edges() - 1);
    }
  }
  return released;
}

void Feeder::save(StateWriter& out) const {
  out.tag("FEED");
  std::ostringstream text;
  text << rng_;
  out.put(text.str());
}

void Feeder::load(StateReader& in) {
  in.tag("FEED");
  std::string text;
  in.get(text);
  std::istringstream stream(text);
  stream >> rng_;
  if (!stream) in.fail("the feeder's random stream does not parse");
}

}  // namespace wirepack
