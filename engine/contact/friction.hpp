#pragma once
// Coulomb friction with true stick-slip (Cundall & Strack 1979; docs/design.md §2.6), one mechanism
// for every contact type (wire-wire, wire-wall, and later wire-shell, shell-shell).
//
// Each contact keeps a tangential force F_t in a history keyed by the pair of elements. Every
// step F_t is rotated into the current tangent plane (keeping its magnitude) and incremented by
// -k_t v_t dt (an elastic tangential spring; v_t the relative tangential surface velocity).
// Stick while |F_t| <= mu_s F_n; beyond, the contact slips with |F_t| = mu_d F_n and the spring
// is reset to that bound; a slipping contact sticks again once the spring force falls below
// mu_d F_n. The tangential stiffness follows Mindlin: k_t = 2 (1 - nu) / (2 - nu) k_n with the
// Hertz normal stiffness k_n = dF_n/d delta. A history entry is dropped when its contact opens;
// a new contact first inherits the entry of a neighbouring element pair that has just opened,
// so a wire sliding along another wire or the wall keeps its stick state across element
// boundaries; a new contact next to one that is still touching (one contact region shared by
// two pairs) starts in that pair's state, its force scaled by the ratio of normal loads.
//
// The history is transactional: evaluate() writes trial values for the step being tried;
// commit() makes the trial of the accepted step the new state and drops contacts that were not
// seen in it; a rejected step is simply evaluated again.
#include <cstdint>
#include <vector>

#include "engine/state_archive.hpp"
#include "engine/types.hpp"

namespace wirepack {

struct FrictionParams {
  double mu_s = 0;             // static coefficient [-]
  double mu_d = 0;             // dynamic coefficient [-], <= mu_s
  double stiffness_ratio = 0;  // k_t / k_n (Mindlin: 2 (1 - nu) / (2 - nu)) [-]
  double damping_ratio = 0;    // tangential dashpot ratio while sticking [-]
  bool enabled() const { return mu_s > 0.0; }
};

// Key of a contact: two element ids (b = -1 for a rigid wall).
struct ContactKey {
  int a = 0, b = 0;
  std::uint64_t packed() const {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
           static_cast<std::uint32_t>(b);
  }
};

class FrictionHistory {
 public:
  explicit FrictionHistory(const FrictionParams& p) : p_(p) {}

  // Starts the evaluation of a trial step of size dt [s] (0 for a re-evaluation that must not
  // advance the springs).
  void begin_trial(double dt) {
    dt_ = dt;
    ++trial_;
    seen_.clear();
  }
  // Marks a contact as present in this trial (first pass over all contacts, before forces),
  // so neighbour transfer only takes entries whose own contact has opened.
  void mark(ContactKey k) { seen_.push_back(k.packed()); }
  void finish_marking();

  // Friction force on body A of contact `k` [N], given the unit normal n (from B to A), the
  // normal force F_n >= 0 [N], the normal stiffness k_n [N/m], the relative tangential-plane
  // velocity v_rel = v_A - v_B of the surfaces at the contact [m/s] and the effective mass
  // [kg] for the tangential dashpot. `neighbours` lists keys whose history a new contact may
  // inherit, in order of preference.
  Vec3 force(ContactKey k, const Vec3& n, double F_n, double k_n, const Vec3& v_rel, double m_eff,
             const ContactKey* neighbours, int num_neighbours);

  // One contact of a batch: the arguments of force().
  struct Query {
    ContactKey key;
    Vec3 n;
    double F_n, k_n;
    Vec3 v_rel;
    double m_eff;
    ContactKey neighbours[8];
    int num_neighbours = 0;
  };
  // force() of each query, into out (same length): contacts that already have an entry in
  // parallel (each reads and writes only its own entry), the new ones after them in query
  // order, so the result is that of calling force() in query order, for any thread count.
  void forces(const std::vector<Query>& queries, std::vector<Vec3>& out);

  // Accepts the last trial: its springs become the state, contacts not seen are dropped.
  void commit();

  std::size_t size() const { return map_.size(); }
  // Checkpoints: the committed springs (the table slot by slot) and the trial counter.
  void save(StateWriter& out) const;
  void load(StateReader& in);
  long slipping() const { return slipping_; }  // contacts slipping in the last trial
  const FrictionParams& params() const { return p_; }

 private:
  // save() and load() in one (Self: FrictionHistory or const FrictionHistory).
  template <class Self, class Archive>
  static void serialize(Self& history, Archive& ar);
  struct Entry {
    Vec3 F = Vec3::Zero();  // committed tangential force on A [N]
    bool sliding = false;   // committed state
    double Fn = 0;          // committed normal force [N]
    double Fn_trial = 0;
    Vec3 F_trial = Vec3::Zero();  // value in the current trial
    bool sliding_trial = false;
    long trial = -1;  // last trial that evaluated this contact
  };
  bool seen_this_trial(std::uint64_t key) const;
  // The spring update of force() on an existing entry; sets *sliding.
  Vec3 update(Entry& e, const Vec3& n, double F_n, double k_n, const Vec3& v_rel, double m_eff,
              bool* sliding) const;

  // Open-addressing hash table of the entries (linear probing, at most half full): one probe
  // per lookup where a node-based map chased a pointer. Iteration order never matters (commit
  // treats each entry alone), so the results equal those of any other map.
  class Table {
   public:
    Entry* find(std::uint64_t key);
    Entry& insert(std::uint64_t key, const Entry& e);  // key not present
    // Keeps the entries for which keep(entry) is true (and may update them in place).
    template <class Keep>
    void retain(Keep keep);
    std::size_t size() const { return size_; }
    // Checkpoints: with StateWriter (Self const) or StateReader (engine/state_archive.hpp).
    template <class Self, class Archive>
    static void serialize(Self& table, Archive& ar);

   private:
    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};  // (-1, -1): find() refuses it
    std::size_t slot(std::uint64_t key) const {
      return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_);
    }
    void grow();
    std::vector<std::uint64_t> keys_;
    std::vector<Entry> entries_;
    std::vector<char> keep_;  // scratch of retain(): per slot
    std::vector<std::uint64_t> kept_keys_;
    std::vector<Entry> kept_entries_;
    std::size_t size_ = 0;
    int shift_ = 64;
  };

  FrictionParams p_;
  Table map_;
  std::vector<std::uint64_t> seen_;  // sorted keys present in the current trial
  std::vector<char> fresh_;          // scratch of forces(): 1 where a query's entry is new
  double dt_ = 0;
  long trial_ = 0;
  long slipping_ = 0;
};

// A contact term's optional history in a checkpoint: a flag, then the history (F: FrictionHistory
// or const FrictionHistory; null when the term has no friction).
template <class Archive, class F>
void serialize_friction(Archive& ar, F* f) {
  char present = f != nullptr;
  ar(present);
  if ((present != 0) != (f != nullptr)) ar.fail("friction on one side only");
  if constexpr (Archive::kLoading) {
    if (f) f->load(ar);
  } else {
    if (f) f->save(ar);
  }
}

}  // namespace wirepack
