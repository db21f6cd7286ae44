#include "engine/contact/friction.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace wirepack {

void FrictionHistory::finish_marking() {
  std::sort(seen_.begin(), seen_.end());
  slipping_ = 0;
}

FrictionHistory::Entry* FrictionHistory::Table::find(std::uint64_t key) {
  // kEmpty marks free slots: as a key (the pair (-1, -1)) it would "find" the first free slot
  // probed and return whatever entry that slot last held.
  if (size_ == 0 || key == kEmpty) return nullptr;
  const std::size_t mask = keys_.size() - 1;
  for (std::size_t i = slot(key);; i = (i + 1) & mask) {
    if (keys_[i] == key) return &entries_[i];
    if (keys_[i] == kEmpty) return nullptr;
  }
}

FrictionHistory::Entry& FrictionHistory::Table::insert(std::uint64_t key, const Entry& e) {
  if (2 * (size_ + 1) > keys_.size()) grow();
  const std::size_t mask = keys_.size() - 1;
  std::size_t i = slot(key);
  while (keys_[i] != kEmpty) i = (i + 1) & mask;
  keys_[i] = key;
  entries_[i] = e;
  ++size_;
  return entries_[i];
}

void FrictionHistory::Table::grow() {
  std::vector<std::uint64_t> keys = std::move(keys_);
  std::vector<Entry> entries = std::move(entries_);
  const std::size_t capacity = std::max<std::size_t>(64, 2 * keys.size());
  keys_.assign(capacity, kEmpty);
  entries_.assign(capacity, Entry{});
  shift_ = 64 - std::countr_zero(capacity);
  size_ = 0;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (keys[i] != kEmpty) insert(keys[i], entries[i]);
  }
}

template <class Keep>
void FrictionHistory::Table::retain(Keep keep) {
  // keep() on every entry in parallel (each slot its own); the table is rebuilt only when an
  // entry goes (instead of deletions with backward shifts), O(capacity) once per step.
  const long capacity = static_cast<long>(keys_.size());
  keep_.resize(capacity);
  long kept = 0;
#pragma omp parallel for schedule(static) reduction(+ : kept)
  for (long i = 0; i < capacity; ++i) {
    keep_[i] = keys_[i] != kEmpty && keep(entries_[i]);
    kept += keep_[i];
  }
  if (static_cast<std::size_t>(kept) == size_) return;  // nothing dropped: the table stands
  kept_keys_.clear();
  kept_entries_.clear();
  for (long i = 0; i < capacity; ++i) {
    if (!keep_[i]) continue;
    kept_keys_.push_back(keys_[i]);
    kept_entries_.push_back(entries_[i]);
  }
  std::fill(keys_.begin(), keys_.end(), kEmpty);
  size_ = 0;
  for (std::size_t i = 0; i < kept_keys_.size(); ++i) insert(kept_keys_[i], kept_entries_[i]);
}

bool FrictionHistory::seen_this_trial(std::uint64_t key) const {
  return std::binary_search(seen_.begin(), seen_.end(), key);
}

Vec3 FrictionHistory::force(ContactKey k, const Vec3& n, double F_n, double k_n, const Vec3& v_rel,
                            double m_eff, const ContactKey* neighbours, int num_neighbours) {
  const std::uint64_t key = k.packed();
  Entry* found = map_.find(key);
  if (!found) {
    Entry e;
    // A new contact takes over the spring of a neighbouring pair whose contact has just
    // opened (the contact point moved across an element boundary); failing that, it starts
    // in the state of a neighbouring pair that is still touching (the same contact region
    // spread over two pairs), with the force scaled to its own normal load.
    const Entry* still = nullptr;
    bool moved = false;
    for (int i = 0; i < num_neighbours && !moved; ++i) {
      const std::uint64_t nk = neighbours[i].packed();
      const Entry* old = map_.find(nk);
      if (!old) continue;
      if (!seen_this_trial(nk)) {
        e.F = old->F;
        e.sliding = old->sliding;
        moved = true;
      } else if (!still) {
        still = old;
      }
    }
    if (!moved && still && still->Fn > 0.0) {
      e.F = still->F * (F_n / still->Fn);
      e.sliding = still->sliding;
    }
    found = &map_.insert(key, e);
  }
  bool sliding = false;
  const Vec3 total = update(*found, n, F_n, k_n, v_rel, m_eff, &sliding);
  slipping_ += sliding ? 1 : 0;
  return total;
}

Vec3 FrictionHistory::update(Entry& e, const Vec3& n, double F_n, double k_n, const Vec3& v_rel,
                             double m_eff, bool* sliding_out) const {
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
  *sliding_out = sliding;
  return total;
}

void FrictionHistory::forces(const std::vector<Query>& queries, std::vector<Vec3>& out) {
  const int n = static_cast<int>(queries.size());
  out.resize(n);
  fresh_.assign(n, 0);
  long slipping = 0;
  // Existing contacts: lookups only (no insertion), each its own entry.
#pragma omp parallel for schedule(dynamic, 64) reduction(+ : slipping)
  for (int i = 0; i < n; ++i) {
    const Query& q = queries[i];
    Entry* e = map_.find(q.key.packed());
    if (!e) {
      fresh_[i] = 1;
      continue;
    }
    bool sliding = false;
    out[i] = update(*e, q.n, q.F_n, q.k_n, q.v_rel, q.m_eff, &sliding);
    slipping += sliding ? 1 : 0;
  }
  slipping_ += slipping;
  // New contacts in query order: each may inherit from a neighbour, including one created
  // earlier in this loop, exactly as force() in query order would.
  for (int i = 0; i < n; ++i) {
    if (!fresh_[i]) continue;
    const Query& q = queries[i];
    out[i] = force(q.key, q.n, q.F_n, q.k_n, q.v_rel, q.m_eff, q.neighbours, q.num_neighbours);
  }
}

template <class Self, class Archive>
void FrictionHistory::Table::serialize(Self& t, Archive& ar) {
  ar.tag("FRTB");
  ar(t.keys_);  // the slots' layout as it is, so the restored table is the same table
  const std::size_t capacity = t.keys_.size();
  if constexpr (Archive::kLoading) {
    if (capacity != 0 && (capacity < 64 || !std::has_single_bit(capacity)))
      ar.fail("friction table capacity " + std::to_string(capacity));
    t.entries_.assign(capacity, Entry{});
    t.shift_ = capacity ? 64 - std::countr_zero(capacity) : 64;
    t.size_ = 0;
  }
  for (std::size_t i = 0; i < capacity; ++i) {
    if (t.keys_[i] == kEmpty) continue;
    auto& e = t.entries_[i];
    ar(e.F);
    ar(e.F_trial);
    ar(e.Fn);
    ar(e.Fn_trial);
    char sliding = e.sliding, sliding_trial = e.sliding_trial;
    ar(sliding);
    ar(sliding_trial);
    ar(e.trial);
    if constexpr (Archive::kLoading) {
      e.sliding = sliding != 0;
      e.sliding_trial = sliding_trial != 0;
      ++t.size_;
    }
  }
}

template <class Self, class Archive>
void FrictionHistory::serialize(Self& f, Archive& ar) {
  ar.tag("FRIC");
  Table::serialize(f.map_, ar);
  ar(f.dt_);
  ar(f.trial_);
  ar(f.slipping_);
}

void FrictionHistory::save(StateWriter& out) const {
  serialize(*this, out);
}
void FrictionHistory::load(StateReader& in) {
  serialize(*this, in);
}

void FrictionHistory::commit() {
  map_.retain([this](Entry& e) {
    if (e.trial != trial_) return false;  // not seen in the accepted step: the contact opened
    e.F = e.F_trial;
    e.sliding = e.sliding_trial;
    e.Fn = e.Fn_trial;
    return true;
  });
}

}  // namespace wirepack
