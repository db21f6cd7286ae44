#pragma once
// Constant-speed injection through the hole at the south pole (paper, section "Model";
// docs/design.md §2.7). The wire outside the hole is a short kinematic guide on the feed axis (+z)
// moving at speed v; a guide node is released (becomes dynamic) once it passes the plane of the
// hole's rim, and a new guide node is added at the tail, so only the injected wire plus the guide
// is simulated. At the start a few nodes are already inside, with a small random transverse
// deflection drawn from the run's seed to break the rotational symmetry about the feed axis.
// A perfectly straight wire would keep that symmetry once the initial deflection has relaxed
// and, pushed head-on into the wall, overshoot its Euler load by an order of magnitude before
// round-off lets it buckle; so every released node also gets a tiny random transverse offset
// (imperfection, `release_noise`), drawn from the same seeded stream.
// With an elastic shell the guide is a contact body of the wire-shell term (a capsule on the
// feed axis below the hole; engine/contact/wire_shell.hpp), so the shell cannot wrap it.
#include <cstdint>
#include <random>

#include "engine/state.hpp"
#include "engine/state_archive.hpp"

namespace wirepack {

struct FeederParams {
  double R = 0;               // sphere radius [m]
  double r = 0;               // wire radius [m]
  double hole_radius = 0;     // [m]
  double element_length = 0;  // rest length of new elements [m]
  double speed = 0;           // injection speed v [m/s]
  int guide_nodes = 3;        // kinematic nodes kept outside the hole
  double deflection = 0;      // rms transverse deflection of the initial inside nodes [m]
  double release_noise = 0;   // rms transverse offset given to each released node [m]
  double offset = 0;          // fixed x offset of the initial tip (s_rel^2 shape; twins) [m]
  std::uint64_t seed = 1;
  bool twist = false;      // create twist DOFs
  bool spin_free = false;  // swivel at the hole (FeederSpin::Free): see release()
};

class Feeder {
 public:
  explicit Feeder(const FeederParams& p);
  // Builds the initial rod: free nodes inside, guide outside, all moving at v along +z.
  State initial_state() const;
  // Injected length at time t: L0 + v t [m].
  double injected_length(double t) const { return L0_ + p_.speed * t; }
  double z_hole() const { return z_hole_; }
  // Releases guide nodes that passed the hole plane and appends new tail nodes. Returns the
  // number of nodes released (0 if the DOF layout did not change). With a swivel the edge that
  // becomes free continues the spun wire: its angle makes the twist m_i at the new joint zero
  // and it spins with its neighbour, so no twist is created at release.
  int release(State& s);
  // Checkpoints: the imperfections' random stream (everything else is set by the parameters).
  void save(StateWriter& out) const;
  void load(StateReader& in);

 private:
  FeederParams p_;
  double z_hole_;        // z of the rim plane [m]
  double L0_;            // injected length at t = 0 [m]
  int n_inside0_;        // free nodes at t = 0
  std::mt19937_64 rng_;  // imperfections of released nodes (seeded; run-local)
};

}  // namespace wirepack
