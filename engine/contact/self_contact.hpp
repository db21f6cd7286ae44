#pragma once
// Wire self-contact: capsules of radius r around the edges (segments) of the rod.
// Broad phase: a cell grid over edge midpoints gives candidate pairs closer than
// l_max + 2 r + skin, refined to capsule distance < 2 r + skin; the list is kept until some node
// has moved more than skin / 2 (a Verlet list), so every step only runs the narrow phase.
// Pairs closer than pi r in arc length along the wire (a hairpin of radius r) are excluded, so a
// bent wire does not repel itself. Normal force: Hertz with E* = E_w / (2 (1 - nu_w^2)) and the
// crossed-cylinders radius R* = r.
//
// Every touching pair of edges is one Hertz point contact (the per-element-pair model: the
// force of a line contact grows with its length, and the energy is continuous). Consecutive
// capsules overlap around their shared node, so where a wire crosses a joint of the other, two
// pairs share the crossing (within sqrt(4 r delta) of the joint), and aligned parallel wires
// touch in up to three pairs per element (two when staggered): the contact stiffness is
// modulated at the element scale. Schemes that count each contact point once (local minima
// of the distance) drop contacts abruptly where a minimum merges with a joint, which happens
// at every element boundary of a curved coil, and inclusion-exclusion over the union of
// capsules collapses a whole line contact into one; both were tried and rejected.
#include <utility>
#include <vector>

#include "engine/contact/cell_grid.hpp"
#include "engine/contact/friction.hpp"
#include "engine/contact/frictional_term.hpp"
#include "engine/contact/hertz.hpp"
#include "engine/contact/segment_distance.hpp"
#include "engine/contact/verlet.hpp"
#include "engine/term.hpp"

namespace wirepack {

struct SelfContactParams {
  double r = 0;               // wire radius [m]
  double E_star = 0;          // effective modulus [Pa]
  double element_length = 0;  // rest element length [m] (sets the neighbour exclusion)
  double skin = 0;            // Verlet-list margin [m]
  double damping_ratio = 0;   // contact dashpot zeta [-]
  double node_mass = 0;     // effective wire node mass of a point load [kg] (WireMass::point_mass)
  FrictionParams friction;  // off when mu_s = 0
};

// One touching pair at the last accumulate: edges a < b, closest-point parameters, unit normal
// from b to a, overlap [m] and normal force [N].
struct WireContact {
  int a = 0, b = 0;
  double s = 0, t = 0;
  Vec3 normal = Vec3::Zero();
  double delta = 0;
  double force = 0;  // normal force [N]
};

class SelfContactTerm : public FrictionalTerm {
 public:
  explicit SelfContactTerm(const SelfContactParams& p);
  std::string name() const override { return "self_contact"; }
  TermType type() const override { return TermType::kSelfContact; }
  double accumulate(const State& s, Forces& out) override;
  double energy(const State& s) override;
  double omega_max_sq(const RodInertia& inertia) const override;

  // N of docs/design.md §5.2: touching edge pairs.
  int contacts() const { return static_cast<int>(contacts_.size()); }
  const std::vector<WireContact>& contact_list() const { return contacts_; }
  // Largest overlap 2 r - d of a touching pair at the last accumulate (0 when none) [m].
  double max_overlap() const {
    double worst = 0.0;
    for (const WireContact& c : contacts_) worst = c.delta > worst ? c.delta : worst;
    return worst;
  }
  void save(StateWriter& out) const override;
  void load(StateReader& in) override;
  int exclusion() const { return exclude_; }
  long rebuilds() const { return rebuilds_; }

 private:
  // Checkpoints: save() and load() in one (engine/state_archive.hpp).
  template <class Self, class Archive>
  static void serialize(Self& term, Archive& ar);
  // Number of edges that take part: those with at least one dynamic node.
  static int active_edges(const State& s) { return std::min(s.n_free, s.num_edges()); }
  void maybe_rebuild(const State& s);
  // Energy of all touching pairs; with `out`, also forces and the contact list.
  double evaluate(const State& s, Forces* out);
  void rebuild(const State& s);

  SelfContactParams p_;
  Hertz hertz_;
  int exclude_;  // pairs with |a - b| <= exclude_ never interact
  CellGrid grid_;
  std::vector<Vec3> midpoints_;
  std::vector<std::pair<int, int>> broad_;  // broad-phase pairs (scratch)
  // Verlet list: edge pairs within 2 r + skin at the build, each with a quarter of its squared
  // slack (distance at the build - 2 r); while every node of the pair has moved less than
  // sqrt(slack2_4) the pair cannot touch (its distance shrinks by at most the two edges' moves).
  struct Candidate {
    int a, b;
    double slack2_4;  // [m^2]
  };
  std::vector<Candidate> candidates_;
  // Closest points per candidate of the last evaluation (dist2 infinite when skipped by its
  // slack), and per broad-phase pair of the last build: computed in parallel, used in order.
  std::vector<SegmentClosest> geo_, broad_geo_;
  VerletReference ref_;  // the nodes at the list's build and their moves since
  int edges_at_build_ = -1;
  long rebuilds_ = 0;
  std::vector<WireContact> contacts_;
  double max_stiffness_ = 0;
  std::vector<FrictionHistory::Query> queries_;  // scratch of accumulate(): one per contact
  std::vector<Vec3> friction_force_;             // friction on edge a per contact [N]
};

}  // namespace wirepack
