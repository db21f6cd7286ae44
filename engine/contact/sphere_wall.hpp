#pragma once
// Contact of the wire with the inner surface of a rigid sphere of radius R (Engine I).
// Each dynamic node is a sphere of radius r; the overlap with the wall is
// delta = |x| + r - R. Effective radius R* = r R / (R - r) (sphere inside a concave sphere),
// E* = E_w / (1 - nu_w^2) (rigid wall). Around the entrance hole (radius r_h, at the south pole
// (0,0,-R)) the wall is absent; there the node touches the hole's rim circle instead, treated as
// an edge (R* = r).

#include "engine/contact/friction.hpp"
#include "engine/contact/frictional_term.hpp"
#include "engine/contact/hertz.hpp"
#include "engine/term.hpp"

namespace wirepack {

struct SphereWallParams {
  double R = 0;              // sphere radius [m]
  double r = 0;              // wire radius [m]
  double hole_radius = 0;    // r_h [m]
  double E_star = 0;         // effective modulus [Pa]
  double damping_ratio = 0;  // contact dashpot zeta [-]
  double node_mass = 0;      // effective wire node mass of a point load [kg] (WireMass::point_mass)
  FrictionParams friction;   // off when mu_s = 0
};

class SphereWallTerm : public FrictionalTerm {
 public:
  explicit SphereWallTerm(const SphereWallParams& p);
  std::string name() const override { return "wall"; }
  TermType type() const override { return TermType::kWall; }
  double accumulate(const State& s, Forces& out) override;
  double energy(const State& s) override;
  double omega_max_sq(const RodInertia& inertia) const override;
  int contacts() const { return contacts_; }  // nodes touching the wall at the last accumulate
  // Largest overlap delta of a node with the wall at the last accumulate (0 when none
  // touches) [m]. The hole's rim is left out: there the feeder pushes the wire in by design.
  double max_overlap() const {
    double worst = 0.0;
    for (const Touch& t : touching_)
      if (!t.rim) worst = t.delta > worst ? t.delta : worst;
    return worst;
  }
  void save(StateWriter& out) const override;
  void load(StateReader& in) override;

 private:
  // Checkpoints: save() and load() in one (engine/state_archive.hpp).
  template <class Self, class Archive>
  static void serialize(Self& term, Archive& ar);
  // Overlap and outward unit normal (from the wire towards the wall) of node x; false if none.
  bool overlap(const Vec3& x, double& delta, Vec3& normal, bool& rim) const;

  SphereWallParams p_;
  Hertz wall_, rim_;
  double z_rim_;              // z of the hole rim circle [m]
  double free_radius2_;       // below this |x|^2 a node cannot touch the wall [m^2]
  double max_stiffness_ = 0;  // largest contact stiffness at the last accumulate [N/m]
  int contacts_ = 0;
  struct Touch {
    int node;
    double delta;
    Vec3 normal;
    bool rim;
  };
  std::vector<Touch> touching_;  // nodes in contact at the last accumulate
};

}  // namespace wirepack
