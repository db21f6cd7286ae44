#include "engine/contact/friction.hpp"

#include <algorithm>
#include <cmath>

namespace wirepack {

void FrictionHistory::finish_marking() {
  std::sort(seen_.begin(), seen_.end());
  slipping_ = 0;
}

bool FrictionHistory::seen_this_trial(std::uint64_t key) const {
  return std::binary_search(seen_.begin(), seen_.end(), key);
}

Vec3 FrictionHistory::force(ContactKey k, const Vec3& n, double F_n, double k_n, const Vec3& v_rel,
                            double m_eff, const ContactKey* neighbours, int num_neighbours) {
  const std::uint64_t key = k.packed();
  auto it = map_.find(key);
  if (it == map_.end()) {
    Entry e;
    // A new contact takes over the spring of a neighbouring pair whose contact has just
    // opened (the contact point moved across an element boundary); failing that, it starts
    // in the state of a neighbouring pair that is still touching (the same contact region
    // spread over two pairs), with the force scaled to its own normal load.
    const Entry* still = nullptr;
    bool moved = false;
    for (int i = 0; i < num_neighbours && !moved; ++i) {
      const std::uint64_t nk = neighbours[i].packed();
      const auto old = map_.find(nk);
      if (old == map_.end()) continue;
      if (!seen_this_trial(nk)) {
        e.F = old->second.F;
        e.sliding = old->second.sliding;
        moved = true;
      } else if (!still) {
        still = &old->second;
      }
    }
    if (!moved && still && still->Fn > 0.0) {
      e.F = still->F * (F_n / still->Fn);
      e.sliding = still->sliding;
    }
    it = map_.emplace(key, e).first;
  }
  Entry& e = it->second;
  // Rotate the committed force into the current tangent plane, keeping its magnitude.
  Vec3 F = e.F - e.F.dot(n) * n;
  const double old_mag = e.F.norm();
  const double new_mag = F.norm();
  if (new_mag > 0.0) F *= old_mag / new_mag;
  // Elastic increment of the tangential spring over the step.
  const Vec3 v_t = v_rel - v_rel.dot(n) * n;
  const double k_t = p_.stiffness_ratio * k_n;
  F -= (k_t * dt_) * v_t;
  const double bound = (e.sliding ? p_.mu_d : p_.mu_s) * F_n;
  const double mag = F.norm();
  bool sliding = false;
  Vec3 total;
  if (mag > bound) {
    // Slip: the force sits on the dynamic bound, along the spring's direction.
    sliding = true;
    F = mag > 0.0 ? Vec3((p_.mu_d * F_n / mag) * F) : Vec3::Zero();
    total = F;
  } else {
    // Stick: spring plus a dashpot on the tangential velocity, still within the bound.
    total = F;
    if (p_.damping_ratio > 0.0 && k_t > 0.0) {
      total -= (2.0 * p_.damping_ratio * std::sqrt(k_t * m_eff)) * v_t;
      const double tmag = total.norm();
      const double cap = p_.mu_s * F_n;
      if (tmag > cap) total *= cap / tmag;
    }
  }
  e.F_trial = F;
  e.sliding_trial = sliding;
  e.Fn_trial = F_n;
  e.trial = trial_;
  slipping_ += sliding ? 1 : 0;
  return total;
}

void FrictionHistory::commit() {
  for (auto it = map_.begin(); it != map_.end();) {
    Entry& e = it->second;
    if (e.trial != trial_) {
      it = map_.erase(it);
      continue;
    }
    e.F = e.F_trial;
    e.sliding = e.sliding_trial;
    e.Fn = e.Fn_trial;
    ++it;
  }
}

}  // namespace wirepack
