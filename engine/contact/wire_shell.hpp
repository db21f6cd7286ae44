#pragma once
// Contact of the wire (capsules of radius r around its edges) with the elastic shell
// (triangles thickened by the half-thickness h = t/2), Engine III.
//
// The shell is a union of overlapping slabs: neighbouring faces share their edge and vertex
// regions. Counting every (wire edge, face) pair would press twice where the wire lies over a
// shell edge and three to six times over a vertex, a modulation at the scale of the mesh. The
// shell side is therefore taken by inclusion-exclusion:
//   U = sum over wire edges e of [ sum_faces U_H - sum_edges U_H + sum_vertices U_H ](e),
// over the faces near e, the edges shared by two of them and the vertices inside a closed fan
// (the rim of the hole overlaps nothing); for a flat patch this is exactly one contact per
// wire edge, and continuous as the contact slides over the mesh. The wire side is per edge, as
// in the self-contact (a line contact's force grows with its length). Normal force: Hertz with
// R* = r and 1/E* = (1 - nu_w^2)/E_w + (1 - nu_s^2)/E_s, plus a normal dashpot. Friction
// (the Engine II mechanism) acts on the (edge, face) pairs, each bounded by its share of the
// net normal force. Forces go to the wire nodes by the segment parameter and to the shell
// vertices by barycentric weights (action = reaction).
//
// The guide (optional, `guide`): outside the hole the wire is kinematic and moves on the feed
// axis (engine/feeder.hpp); a soft shell pushed out below the clamped rim can wrap that axis,
// and the next released node would then start inside the shell. The guide is therefore a
// contact body too: a rigid capsule of radius r on the feed axis (x = y = 0) from the first
// guide node down to z = guide_bottom_z, against the shell by the same inclusion-exclusion and
// the same normal law (Hertz, barrier, dashpot with the vertex mass), frictionless (a smooth
// nozzle, no history). Pieces that are clamped throughout take no part. Its force goes to the
// shell vertices and, by the segment parameter, its reaction to the first guide node (so the
// feeder's power counts the work of the moving guide). Its candidate faces are rebuilt with the
// wire's list (a function of the shell at the build), so a checkpoint needs nothing more.
#include <array>
#include <limits>
#include <utility>
#include <vector>

#include "engine/contact/cell_grid.hpp"
#include "engine/contact/friction.hpp"
#include "engine/contact/frictional_term.hpp"
#include "engine/contact/hertz.hpp"
#include "engine/contact/segment_distance.hpp"
#include "engine/contact/triangle_distance.hpp"
#include "engine/contact/verlet.hpp"
#include "engine/shell/shell_term.hpp"
#include "engine/term.hpp"

namespace wirepack {

struct WireShellParams {
  double r = 0;               // wire radius [m]
  double half_thickness = 0;  // h = t / 2 [m]
  double E_star = 0;          // effective modulus [Pa]
  double skin = 0;            // Verlet-list margin [m]
  double damping_ratio = 0;   // normal dashpot ratio [-]
  double node_mass = 0;     // effective wire node mass of a point load [kg] (WireMass::point_mass)
  double vertex_mass = 0;   // shell vertex mass [kg]
  FrictionParams friction;  // off when mu_s = 0
  bool guide = false;       // the kinematic guide on the feed axis is a contact body
  double guide_bottom_z = 0;  // z of the guide capsule's far end [m] (below the hole)
};

class WireShellTerm : public FrictionalTerm {
 public:
  WireShellTerm(const ShellMesh& mesh, const WireShellParams& p);
  std::string name() const override { return "wire_shell"; }
  TermType type() const override { return TermType::kWireShell; }
  DofGroup dofs() const override { return DofGroup::kCoupling; }
  double accumulate(const State& s, Forces& out) override;
  double energy(const State& s) override { return evaluate(s, nullptr); }
  double omega_max_sq(const RodInertia& inertia) const override;
  void save(StateWriter& out) const override;
  void load(StateReader& in) override;
  // The wire's axis reached the shell's mid-surface in a contact (overlap r + t/2).
  std::string failure() const override;

  // (wire edge, face) pairs whose pieces overlap at the last accumulate.
  int contacts() const { return static_cast<int>(face_pairs_.size()); }
  long rebuilds() const { return rebuilds_; }
  // Largest overlap of a (wire edge, face, shell edge or vertex) piece at the last accumulate
  // (0 when none) [m].
  double max_overlap() const { return max_overlap_; }
  // Guide-shell contacts (faces touching the guide) and their largest overlap [m] at the last
  // evaluation.
  int guide_contacts() const { return guide_contacts_; }
  double guide_max_overlap() const { return guide_max_overlap_; }

 private:
  // Checkpoints: save() and load() in one (engine/state_archive.hpp).
  template <class Self, class Archive>
  static void serialize(Self& term, Archive& ar);
  // One (wire edge, face) pair in contact: closest points, normal (from shell to wire), overlap
  // and its net normal force (after its share of the corrections) [N].
  struct FacePair {
    int e, f;
    double s;
    std::array<double, 3> w;
    Vec3 n;
    double delta;
    double force;
  };
  double evaluate(const State& s, Forces* out);
  void maybe_rebuild(const State& s);
  void rebuild(const State& s);
  int active_edges(const State& s) const { return std::min(s.n_free, s.num_edges()); }
  // The guide's candidate pieces from the shell (x_shell) and the guide's top at the build.
  void rebuild_guide(const Vec3List& x_shell, const Vec3& top);
  // Guide-shell contact energy [J]; adds its forces into out when given.
  double guide_evaluate(const State& s, Forces* out);

  const ShellMesh& mesh_;
  WireShellParams p_;
  Hertz hertz_;
  std::vector<std::vector<int>> vertex_faces_;  // faces around each vertex
  std::vector<char> boundary_vertex_;           // 1 on the rim of the hole
  CellGrid grid_;
  Vec3List points_;
  std::vector<std::pair<int, int>> broad_;
  std::vector<std::pair<int, int>> candidates_;  // (wire edge, face), sorted
  std::vector<std::pair<int, int>> seg_edge_;    // (wire edge, shell edge) of the candidates
  std::vector<std::pair<int, int>> seg_vert_;    // (wire edge, interior vertex) of them
  // Owner candidates of each correction (indices into candidates_, -1: not a candidate): the
  // two faces of a shell edge; the fan of a vertex (CSR: vert_owner_start_, one per pair + 1).
  std::vector<std::array<int, 2>> edge_owner_;
  std::vector<int> vert_owner_start_, vert_owner_;
  // A quarter of each pair's squared slack at the build (distance - (r + t/2), less 1e-9 r):
  // while every point of the pair moved less than its square root, the pair cannot touch
  // (its distance shrinks by at most the wire's plus the shell's move), so it is skipped.
  std::vector<double> cand_slack2_4_, edge_slack2_4_, vert_slack2_4_;  // [m^2]
  struct FoundPair {
    int e, f;
    double slack2_4;
  };
  std::vector<FoundPair> found_;          // scratch of rebuild()
  std::vector<double> broad_dist2_;       // scratch of rebuild(): per broad pair [m^2]
  VerletReference wire_ref_, shell_ref_;  // nodes / vertices at the list's build, their moves
  int edges_at_build_ = -1;
  long rebuilds_ = 0;
  double face_reach_ = 0;  // largest distance from a face centroid to its vertices [m]
  std::vector<FacePair> face_pairs_;
  // Closest points per candidate (dist2 >= (r + t/2)^2 when skipped by its slack) and per
  // (wire edge, shell edge) pair (dist2 infinite when skipped), of the last evaluation.
  std::vector<TriangleClosest> cand_geo_;
  std::vector<int> cand_face_pair_;  // index into face_pairs_ per candidate, -1 when apart
  std::vector<SegmentClosest> edge_geo_;
  // One contact of a pair, computed in parallel and added in pair order: unit normal (from
  // shell to wire), overlap [m], signed energy [J], signed normal force [N] and the force on
  // the wire [N] (-F on the shell); touching false when apart.
  struct Hit {
    bool touching = false;
    Vec3 n = Vec3::Zero();
    double delta = 0, energy = 0, force = 0;
    Vec3 F = Vec3::Zero();
  };
  std::vector<Hit> cand_hit_, edge_hit_, vert_hit_;
  std::vector<double> vert_t_;  // closest point x_e + t (x_e+1 - x_e) to each vertex pair's vertex
  double max_stiffness_ = 0;
  double max_overlap_ = 0;                       // largest overlap of the last evaluation [m]
  std::vector<FrictionHistory::Query> queries_;  // scratch of accumulate(): one per face pair
  std::vector<Vec3> friction_force_;             // friction on the wire per face pair [N]
  Vec3List edge_t_;                              // unit tangent of each face pair's wire edge
  // Guide: pieces that take part (a face with an unclamped vertex; an edge whose two faces
  // do; an interior vertex whose fan does), and the candidates within reach at the build.
  std::vector<char> guide_face_ok_, guide_edge_ok_, guide_vertex_ok_;
  std::vector<int> guide_faces_, guide_edges_, guide_verts_;
  int guide_contacts_ = 0;
  double guide_max_overlap_ = 0, guide_max_stiffness_ = 0;
};

}  // namespace wirepack
