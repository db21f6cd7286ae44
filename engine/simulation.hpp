#pragma once
// One scene -> one trajectory: the wire injected through the hole at the south pole of a
// sphere of radius R = rho r. Physics only: no files, no threads.
#include <array>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "engine/params.hpp"
#include "engine/types.hpp"

namespace wirepack {

struct Energies {
  double U_b = 0, U_t = 0, U_s = 0;  // wire bending, twist, stretch [J]
  double U_m = 0, U_sb = 0;          // shell membrane, shell bending [J]
  double U_contact = 0;              // stored elastic energy in contacts [J]
  double E_kin = 0;                  // kinetic energy, v^T M v / 2 with the simulated masses [J]
};

// Largest contact overlaps of the last evaluation [m] (0 where the scene has no such contact).
struct ContactOverlaps {
  double wire_wire = 0;   // 2 r - d of two wire capsules
  double wall = 0;        // |x| + r - R of a node with the rigid sphere (not its hole's rim)
  double wire_shell = 0;  // r + t/2 - d of a wire capsule with the elastic shell's slab
  double guide = 0;       // r + t/2 - d of the guide outside the hole with the shell's slab
};

class Simulation {
 public:
  explicit Simulation(const SceneParams& params);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  // Threads of the force loops (default 1). The trajectory is bitwise the same for any count.
  void set_threads(int threads);
  int threads() const;
  // Advances by one accepted adaptive step. Throws SimulationError (NaN, step collapse,
  // tunnelling through the wall) with the reason.
  void step();
  // Steps until l() >= l_target.
  void advance_to(double l_target);
  bool finished() const { return l() >= params().l_max; }

  // Checkpoints (docs/design.md §4.8): the dynamic state after the last accepted step (the
  // rod and shell, the integrator, the feeder's random stream, every term's contact lists and
  // friction springs) as bytes; restore_state() puts it into a Simulation built from the same
  // parameters, which then continues bitwise as the saved one would have. restore_state throws
  // CheckpointError (engine/state_archive.hpp) for bytes of another scene or layout, leaving
  // this Simulation unusable.
  std::string save_state() const;
  void restore_state(std::string_view bytes);

  const SceneParams& params() const;
  double l() const;     // injected length / R
  double L() const;     // injected length [m]
  double time() const;  // simulated time [s]
  double dt() const;    // current time step [s]
  long steps() const;   // accepted steps
  long rejected_steps() const;
  // Stability step of the last evaluation, 2/omega_max with the damping factor [s], and each
  // term's share of omega_max^2 [1/s^2] (same order as term_names()): what limits the step.
  double dt_stable() const;
  std::vector<double> term_omega_sq() const;

  // Wire centerline inside the cavity (the released nodes), tip first [m].
  std::span<const Vec3> inside_nodes() const;
  // Every simulated node, including the kinematic guide outside the hole [m].
  std::span<const Vec3> all_nodes() const;
  Energies energies() const;  // at the last evaluated state
  // Energy put in by the feeder since the start [J]: the force that holds the guide at the feed
  // speed times that speed, integrated over the accepted steps (trapezoid), plus the jump of
  // the total energy at each node release (the released node's kinetic energy at the feed
  // speed and its imperfection). Damping and friction only take energy out, so the total
  // energy (Energies, all terms) minus its initial value stays below this.
  double feeder_work() const;
  ContactOverlaps max_overlaps() const;
  int wire_contacts() const;  // N: wire element pairs in contact
  // Names of the terms assembled for this scene, e.g. {"stretch", "bend", "wall", ...}.
  std::vector<std::string> term_names() const;
  // Shell mesh (empty for a rigid shell).
  std::span<const Vec3> shell_vertices() const;
  std::span<const std::array<int, 3>> shell_triangles() const;
  // Rest positions of the shell's vertices (nv) [m] and its clamped rim (nv; 1 = held fixed).
  std::span<const Vec3> shell_rest_vertices() const;
  std::span<const char> shell_clamped() const;
  // Normal contact force of the wire on each shell vertex at the current state (nv) [N]:
  // Hertz plus dashpot, friction left out (engine/contact/wire_shell_probe.hpp). Read-only:
  // evaluated apart from the simulation's own term. Empty for a rigid shell.
  Vec3List shell_contact_forces() const;
  // Wire self-contacts per inside node (n_free): each touching edge pair counted once on
  // each of its two edges, at the edge's node nearer the contact point; sums to 2 N.
  std::vector<int> wire_contacts_per_node() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace wirepack
