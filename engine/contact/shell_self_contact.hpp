#pragma once
// Shell-shell (self-)contact of the elastic shell, Engine III (docs/design.md §2.6): two pieces of
// the shell, each a slab of thickness t = 2 h around its mid-surface, touch where their
// mid-surfaces come closer than t. Only for scenes whose shell can fold onto itself.
//
// Pairs. Vertex-triangle (VT: a vertex against the other piece's faces) and edge-edge (EE: two
// edges without a shared vertex). Pairs that are close in the rest mesh (rest distance below
// `exclusion`) never interact: neighbouring elements of a thick shell (t ~ mesh size) are
// always within t of each other, and only genuinely folded-over pieces should touch. The
// exclusion is decided on the rest mesh, so it is a static property of the pair.
//
// Counting. An edge of the other sheet is shared by two faces and a vertex by about six, so
// counting every (vertex, face) pair would press twice where the vertex lies over an edge of
// the other sheet and about six times over one of its vertices (on two flat 1 mm meshes at
// t = 1 mm: 1.4 to 6.7 times one contact per vertex, by offset and overlap). The other side is
// therefore taken by inclusion-exclusion over its slabs, as in the wire-shell contact:
//   U_v = w_v [ sum_faces U - sum_edges U + sum_vertices c_u U ],
// over the faces not excluded for v, the edges both of whose faces are not excluded and their
// vertices u with the Euler weight c_u = 1 - (faces of u kept) + (edges of u kept), which is 1
// inside a closed fan and 0 on the rim of the hole or of the exclusion zone. Against a flat
// sheet this is exactly one contact per vertex wherever it lies over the mesh. Every vertex is
// also a quadrature point of the contact pressure: its contact is scaled by w_v = A_v / A_ref,
// A_v its barycentric rest area and A_ref = (sqrt(3)/2) t^2 the area per vertex of a mesh of
// edge t, so two flat sheets pressed together feel p = 2 F(delta) / A_ref whatever their mesh.
//
// Edge-edge pairs catch what the vertices miss: two edges crossing (a fold's crease over
// another's) with every vertex farther than t from the other sheet, which happens only where
// t is small against the mesh size. In a flat contact the crossings of the two meshes add
// contacts whose number depends on the meshes' relative offset and angle: with the full reach
// t they multiplied the force of two flat 1 mm meshes at t = 1 mm by 5.5 to 15 (offset and
// angle). So edges are capsules of radius h / 2, acting within t / 2 only: a flat contact is
// exact up to the overlap t / 2, where the barrier starts, and gains 10 to 30 % beyond.
//
// Normal force: Hertz (hertz.hpp) with R* = h for VT (the vertex's ball of radius h, the edge
// of its slab, against the other slab's flat face: sphere on flat) and R* = h / 2 for EE
// (crossed cylinders of the capsule radius h / 2), the barrier taking over at half the overlap
// at which the mid-surfaces would meet, plus a normal dashpot. Friction (the Engine II
// mechanism, friction.hpp) acts on the (vertex, face) pairs, each bounded by its share of the
// vertex's net normal force, and on the EE pairs; keys (v, f) for VT and (nv + e1, e2) for EE.
// Forces go to the vertices by barycentric and segment weights: the net force is zero and the
// normal forces have zero net torque; a friction force acts at the two mid-surfaces, a distance
// d apart, and leaves the couple d x F_t that the slabs' bending would carry (the vertices have
// no rotational freedom), as in the wire-shell contact.
//
// Broad phase: cell grids over vertices and face centroids (VT) and over edge midpoints (EE);
// the candidate lists (pairs within reach + skin, not excluded) are kept until some vertex has
// moved more than skin / 2 since the last build (a Verlet list). At rest nothing is a
// candidate, so a step costs the displacement check only.
#include <array>
#include <limits>
#include <utility>
#include <vector>

#include "engine/contact/cell_grid.hpp"
#include "engine/contact/friction.hpp"
#include "engine/contact/frictional_term.hpp"
#include "engine/contact/hertz.hpp"
#include "engine/contact/verlet.hpp"
#include "engine/shell/shell_term.hpp"
#include "engine/term.hpp"

namespace wirepack {

struct ShellSelfContactParams {
  double half_thickness = 0;  // h = t / 2 [m]
  double E_star = 0;  // effective modulus, E_s / (2 (1 - nu_s^2)) for the shell on itself [Pa]
  double skin = 0;    // Verlet-list margin [m]
  double damping_ratio = 0;  // normal dashpot ratio zeta [-]
  double vertex_mass = 0;    // smallest shell vertex mass [kg] (dashpot and time step)
  FrictionParams friction;   // off when mu_s = 0
  double exclusion = 0;      // pairs closer than this in the rest mesh never touch [m], >= t
                             // (suggested_exclusion: 2 t + the longest rest edge)
};

class ShellSelfContactTerm : public FrictionalTerm {
 public:
  // `mesh` must outlive the term. Throws std::invalid_argument for h, E_star, skin or
  // vertex_mass <= 0 or exclusion < t (the rest mesh would then touch itself).
  ShellSelfContactTerm(const ShellMesh& mesh, const ShellSelfContactParams& p);
  std::string name() const override { return "shell_self"; }
  TermType type() const override { return TermType::kShellSelf; }
  DofGroup dofs() const override { return DofGroup::kShell; }
  double accumulate(const State& s, Forces& out) override;
  double energy(const State& s) override { return evaluate(s, nullptr); }
  double omega_max_sq(const RodInertia& inertia) const override;
  void save(StateWriter& out) const override;
  void load(StateReader& in) override;
  // Two pieces of the shell passed through each other (overlap t for vertex-face contacts).
  std::string failure() const override;

  // The exclusion suggested for a mesh: 2 t plus its longest rest edge [m] (a fold must bring
  // two pieces from beyond a hairpin of the slab's size back onto each other).
  static double suggested_exclusion(const ShellMesh& mesh, double half_thickness);

  // (vertex, face) and edge-edge pairs in contact at the last evaluation.
  int vt_contacts() const { return static_cast<int>(face_pairs_.size()); }
  int ee_contacts() const { return static_cast<int>(edge_pairs_.size()); }
  int contacts() const { return vt_contacts() + ee_contacts(); }
  // Candidates (VT, EE) of the current Verlet list, and the number of list builds.
  int vt_candidates() const { return static_cast<int>(vt_faces_.size()); }
  int ee_candidates() const { return static_cast<int>(ee_.size()); }
  long rebuilds() const { return rebuilds_; }
  // Contact weight w_v = A_v / A_ref of vertex v [-].
  double vertex_weight(int v) const { return weight_[v]; }
  // Hertz laws of the two pair types.
  const Hertz& vt_law() const { return hertz_vt_; }
  const Hertz& ee_law() const { return hertz_ee_; }

 private:
  // Checkpoints: save() and load() in one (engine/state_archive.hpp).
  template <class Self, class Archive>
  static void serialize(Self& term, Archive& ar);
  // A (vertex, face) pair in contact: barycentric weights of the closest point, unit normal
  // (from the face to the vertex), overlap [m] and net normal force after its share of the
  // inclusion-exclusion corrections [N].
  struct FacePair {
    int v, f;
    std::array<double, 3> w;
    Vec3 n;
    double delta;
    double force;
  };
  // An edge-edge pair in contact: segment parameters, normal (from e2 to e1), overlap, force.
  struct EdgePair {
    int e1, e2;
    double s, t;
    Vec3 n;
    double delta;
    double force;
  };
  // Inclusion-exclusion piece of the other sheet against vertex v: an edge (weight -1) or a
  // vertex u (weight c_u).
  struct VertexPiece {
    int v, u;
    double c;
  };

  double evaluate(const State& s, Forces* out);
  void maybe_rebuild(const State& s);
  void rebuild(const State& s);
  // Rest distance of vertex v to face f is at least the exclusion.
  bool kept(int v, int f) const;
  int find_face_pair(int v, int f) const;

  const ShellMesh& mesh_;
  ShellSelfContactParams p_;
  double t_;  // thickness [m]
  Hertz hertz_vt_, hertz_ee_;
  std::vector<double> weight_;                  // w_v (nv)
  std::vector<std::vector<int>> vertex_faces_;  // faces around each vertex
  std::vector<std::vector<int>> vertex_edges_;  // edges at each vertex
  std::vector<Vec3> rest_centroid_;             // face centroids at rest (nf) [m]
  std::vector<double> rest_face_reach_;         // centroid-to-vertex distance at rest (nf) [m]
  std::vector<Vec3> rest_mid_;                  // edge midpoints at rest (ne) [m]
  std::vector<double> rest_half_;               // half edge lengths at rest (ne) [m]

  CellGrid grid_vt_, grid_ee_;
  Vec3List points_;
  std::vector<std::pair<int, int>> broad_;
  VerletReference ref_;  // the vertices at the list's build
  long rebuilds_ = 0;
  // Verlet lists: (v, f) sorted; (v, edge) sorted; vertex pieces sorted by (v, u); (e1, e2).
  std::vector<std::pair<int, int>> vt_faces_;
  std::vector<std::pair<int, int>> vt_edges_;
  std::vector<VertexPiece> vt_verts_;
  std::vector<std::pair<int, int>> ee_;

  std::vector<FacePair> face_pairs_;
  std::vector<EdgePair> edge_pairs_;
  std::vector<double> row_stiffness_;  // Gershgorin row sums of the contact stiffness (nv)
  std::vector<int> touched_;
  double max_row_stiffness_ = 0;  // [N/m]
  double max_overlap_ratio_ = 0;  // largest overlap / limit D of the last evaluation [-]
};

}  // namespace wirepack
