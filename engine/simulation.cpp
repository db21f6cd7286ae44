#include "engine/simulation.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include "engine/contact/wire_shell_probe.hpp"
#include "engine/integrate/stability.hpp"
#include "engine/rod/frames.hpp"
#include "engine/scene.hpp"
#include "engine/shell/winding.hpp"

namespace wirepack {

struct Simulation::Impl {
  SceneParams params;
  Assembly assembly;
  Feeder feeder;
  RodDamping damping;
  PredictorCorrector integrator;
  State state;
  Forces forces;
  std::vector<double> term_energy;  // per term, at the last evaluation [J]
  std::vector<double> term_omega2;  // per term, omega_max^2 at the last evaluation [1/s^2]
  double time = 0.0;
  long steps = 0;
  int mass_nodes = -1;        // free nodes of the last factorisation of the wire's mass matrix
  int twist_mass_nodes = -1;  // the same for the twist angles' matrix
  std::unique_ptr<ShellWinding> winding;  // inside test (elastic shell only)
  std::vector<char> inside;               // per released node, of the last inside test
  long next_inside_check = 0;             // step of the next inside test
  int threads = 1;                        // threads of the force loops (set_threads)
  double feeder_work = 0.0;               // energy put in by the feeder (feeder_work()) [J]
  double feeder_power = 0.0;              // its power at the last accepted state [W]

  explicit Impl(const SceneParams& p)
      : params(p),
        assembly(assemble(p)),
        feeder(assembly.feeder),
        damping(assembly.damping),
        integrator(assembly.control, p.wire.radius),
        state(feeder.initial_state()),
        term_energy(assembly.terms.size(), 0.0),
        term_omega2(assembly.terms.size(), 0.0) {
    if (assembly.mesh) {
      winding = std::make_unique<ShellWinding>(*assembly.mesh);
      state.shell_x = assembly.mesh->rest;
      state.shell_v.assign(state.shell_x.size(), Vec3::Zero());
    }
    integrator.initialise(state, eval_fn(), moved_fn());
    // A step far below the initial stability limit means the run has collapsed.
    StepControl c = assembly.control;
    c.dt_floor = SceneConstants::kDtFloorFraction * integrator.dt_stable();
    PredictorCorrector fresh(c, p.wire.radius);
    integrator = fresh;
    integrator.initialise(state, eval_fn(), moved_fn());
    feeder_power = guide_power();
  }

  // Power the feeder puts into the wire at the last evaluation [W]: the guide moves at its
  // fixed velocity, so the feeder supplies -f on each guide node (f: the forces of the terms
  // and the damping there).
  double guide_power() const {
    double P = 0.0;
    for (int i = state.n_free; i < state.num_nodes(); ++i) P -= forces.f[i].dot(state.v[i]);
    return P;
  }

  // Kinetic energy of the wire (its first n_free nodes and their edges' twist) and the shell at
  // the current velocities [J].
  double kinetic_energy(int n_free) const {
    const State& s = state;
    double E = assembly.mass.kinetic_energy(s.v, n_free);
    if (s.has_twist())
      E += assembly.twist_mass.kinetic_energy(s.omega, std::max(0, n_free - 1),
                                              !assembly.feeder.spin_free);
    const auto& vm = assembly.vertex_mass;
    for (size_t k = 0; k < s.shell_v.size(); ++k) E += 0.5 * vm[k] * s.shell_v[k].squaredNorm();
    return E;
  }

  // Every term's energy at the last evaluation plus the kinetic energy of n_free nodes [J].
  double total_energy(int n_free) const {
    double U = kinetic_energy(n_free);
    for (double e : term_energy) U += e;
    return U;
  }

  // Generalised accelerations of the dynamic DOFs; returns omega_max^2 [1/s^2].
  double evaluate(State& s, Vec3List& a, std::vector<double>& alpha, Vec3List& shell_a) {
    forces.reset(s);
    // Reference frames follow the new positions (twist only), from the tangents reset() found.
    update_reference_frames(s, forces);
    for (auto& t : assembly.terms) t->begin_trial(integrator.trial_dt());
    StabilityBound bound;
    for (size_t k = 0; k < assembly.terms.size(); ++k) {
      term_energy[k] = assembly.terms[k]->accumulate(s, forces);
      term_omega2[k] = assembly.terms[k]->omega_max_sq(assembly.inertia);
      bound.add(assembly.terms[k]->dofs(), term_omega2[k]);
    }
    const double omega2 = bound.omega_max_sq();
    damping.add_forces(s, forces);
    // a = M^-1 f over the free nodes (zero for the guide); M changes only when nodes are released.
    if (s.n_free != mass_nodes) {
      assembly.mass.factorise(s.n_free, s.num_nodes() > s.n_free);
      mass_nodes = s.n_free;
    }
    assembly.mass.solve(forces.f, a);
    shell_a.assign(s.shell_x.size(), Vec3::Zero());
    if (assembly.mesh) {
      // Shell vertices: forces of the terms minus the vertex damping; clamped ones held.
      const auto& clamped = assembly.mesh->clamped;
      const double gamma = assembly.shell_damping_rate;
      for (size_t k = 0; k < s.shell_x.size(); ++k) {
        if (clamped[k]) continue;
        shell_a[k] = forces.shell_f[k] / assembly.vertex_mass[k] - gamma * s.shell_v[k];
      }
    }
    alpha.clear();  // no twist DOFs; with them the solve below fills every edge
    if (s.has_twist()) {
      // Free edges [0, n_free - 1), joined to the kinematic edge into the guide unless the
      // feeder is a swivel.
      if (s.n_free != twist_mass_nodes) {
        assembly.twist_mass.factorise(std::max(0, s.n_free - 1), !assembly.feeder.spin_free);
        twist_mass_nodes = s.n_free;
      }
      assembly.twist_mass.solve(forces.torque, alpha);
    }
    return omega2;
  }

  EvaluateFn eval_fn() {
    return [this](State& s, Vec3List& a, std::vector<double>& al, Vec3List& sa) {
      return evaluate(s, a, al, sa);
    };
  }
  // The reference frames are updated inside evaluate(), which every position change precedes.
  static PositionsChangedFn moved_fn() {
    return [](State&) {};
  }

  // Accepts the history of the last evaluation (friction springs).
  void commit() {
    for (auto& t : assembly.terms) t->commit();
  }

  void check_state() const {
    const double R = params.R();
    const double r = params.wire.radius;
    const double beyond2 = (R + r) * (R + r);
    for (int i = 0; i < state.n_free; ++i) {
      const Vec3& x = state.x[i];
      if (!x.allFinite() || !state.v[i].allFinite()) {
        throw SimulationError("non-finite state (NaN/Inf) at node " + std::to_string(i));
      }
      // A node centre a whole radius beyond the wall has passed through it.
      if (assembly.wall && x.squaredNorm() > beyond2 && x[2] > feeder.z_hole()) {
        throw SimulationError("wire node " + std::to_string(i) + " tunnelled through the wall");
      }
      // Rigid sphere: a released node back below the rim's plane has left the cavity: the
      // packing has pushed the wire out through the hole beside the guide, which the feeder
      // cannot undo (a jam; found by the hard-scene suite at rho = 10, l = 98.8, where the node
      // then sat inside the wall). Not for the elastic shell, which may bulge out below the
      // plane with the wire inside it (tip 0.27 r below it at rho = 10, eps = 1e3, l = 5.5).
      const double below = feeder.z_hole() - x[2];
      if (assembly.wall && below > SceneConstants::kJamDepth * r) {
        throw SimulationError("the packing jams the feed: wire node " + std::to_string(i) +
                              " was pushed back out through the hole (" +
                              std::to_string(below / r) + " r below the rim's plane)");
      }
    }
  }

  void check_shell() {
    if (!assembly.wire_shell) return;
    for (const auto& t : assembly.terms) {
      const std::string why = t->failure();
      if (!why.empty()) throw SimulationError(why);
    }
    for (const Vec3& x : state.shell_x) {
      if (!x.allFinite()) throw SimulationError("non-finite shell state (NaN/Inf)");
    }
    // Each released node must be inside the shell: a winding number per node, O(nodes x faces),
    // about 0.2 n steps' worth of force evaluations for n released nodes. Checked every
    // max(100, 4 n) steps (at most ~5 % of the run; every 100 steps made it half the cost of
    // a step at l = 30) and at the end of the run.
    const bool last = feeder.injected_length(time) >= params.l_max * params.R();
    if (steps < next_inside_check && !last) return;
    next_inside_check = steps + std::max(100, 4 * state.n_free);
    const double z_min = feeder.z_hole() + 2.0 * params.wire.radius;
    // Winding numbers in parallel (threads over nodes), the first failing node reported.
    const int n = state.n_free;
    inside.assign(n, 1);
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; ++i) {
      if (state.x[i][2] < z_min) continue;  // in the entrance hole
      inside[i] = (*winding)(state.x[i], state.shell_x) >= 0.5;
    }
    for (int i = 0; i < n; ++i) {
      if (!inside[i]) {
        throw SimulationError("wire node " + std::to_string(i) + " passed through the shell");
      }
    }
  }

  void step() {
    double dt = 0;
    try {
      dt = integrator.step(state, eval_fn(), moved_fn());
    } catch (const SimulationError& e) {
      throw SimulationError(std::string(e.what()) + "; " + stiffest_term());
    }
    commit();
    time += dt;
    ++steps;
    check_state();
    check_shell();
    // Feeder work over the step, trapezoid between the powers at its two ends.
    const double P = guide_power();
    feeder_work += 0.5 * dt * (feeder_power + P);
    feeder_power = P;
    const int n_before = state.n_free;
    if (feeder.release(state) > 0) {
      // What the released nodes brought in: the total energy at the new layout minus that of
      // the last evaluation (term energies not yet updated, the kinetic energy of the nodes
      // that were free; release() keeps every velocity).
      const double E_before = total_energy(n_before);
      integrator.initialise(state, eval_fn(), moved_fn());
      commit();
      feeder_work += total_energy(state.n_free) - E_before;
      feeder_power = guide_power();
    }
  }

  // The term whose omega_max^2 was largest at the last evaluation, with its stable step [s].
  std::string stiffest_term() const {
    std::size_t k_max = 0;
    for (std::size_t k = 1; k < term_omega2.size(); ++k)
      if (term_omega2[k] > term_omega2[k_max]) k_max = k;
    if (term_omega2.empty() || !(term_omega2[k_max] > 0)) return "no term bounds the step";
    std::ostringstream out;
    out << std::setprecision(3) << "stiffest term " << assembly.terms[k_max]->name()
        << " (2/omega_max " << 2.0 / std::sqrt(term_omega2[k_max]) << " s)";
    return out.str();
  }

  // Checkpoint layout; bump it whenever what save() writes changes.
  static constexpr int kStateLayout = 1;

  // save() and load() in one (engine/state_archive.hpp); Self: Impl or const Impl.
  template <class Self, class Archive>
  static void serialize(Self& m, Archive& ar) {
    ar.tag("SIMU");
    int layout = kStateLayout;
    ar(layout);
    if (layout != kStateLayout)
      ar.fail("layout " + std::to_string(layout) + ", this build reads " +
              std::to_string(kStateLayout));
    // The scene's terms by name: a state of another scene is refused here.
    std::vector<std::string> names;
    for (const auto& t : m.assembly.terms) names.push_back(t->name());
    const std::size_t n_terms = names.size();
    ar.count(names, 1000);
    for (std::size_t k = 0; k < names.size(); ++k) {
      std::string name = k < n_terms ? m.assembly.terms[k]->name() : "";
      ar(name);
      const std::string here = k < n_terms ? m.assembly.terms[k]->name() : "no term";
      if (k >= n_terms || name != here) ar.fail("term " + name + " where this scene has " + here);
    }
    if (names.size() != n_terms) ar.fail("another set of terms");
    ar(m.time);
    ar(m.steps);
    ar(m.feeder_work);
    ar(m.feeder_power);
    ar(m.next_inside_check);
    ar.tag("ROD_");
    auto& st = m.state;
    ar(st.n_free);
    ar(st.x);
    ar(st.v);
    ar(st.rest_length);
    ar(st.theta);
    ar(st.omega);
    ar(st.ref1);
    ar(st.ref_tangent);
    ar(st.ref_twist);
    ar(st.shell_x);
    ar(st.shell_v);
    const std::size_t n = st.x.size();
    const bool twist = !st.theta.empty();
    if (n < 2 || st.n_free < 0 || st.n_free > static_cast<int>(n) || st.v.size() != n ||
        st.rest_length.size() != n - 1 ||
        (twist &&
         (st.theta.size() != n - 1 || st.omega.size() != n - 1 || st.ref1.size() != n - 1 ||
          st.ref_tangent.size() != n - 1 || st.ref_twist.size() != n)) ||
        twist != m.params.twist_enabled() ||
        st.shell_x.size() != (m.assembly.mesh ? m.assembly.mesh->rest.size() : 0) ||
        st.shell_v.size() != st.shell_x.size())
      ar.fail("the rod or shell does not fit this scene");
    ar(m.term_energy);
    ar(m.term_omega2);
    if (m.term_energy.size() != n_terms || m.term_omega2.size() != n_terms)
      ar.fail("per-term values of another scene");
    if constexpr (Archive::kLoading) {
      m.integrator.load(ar);
      m.feeder.load(ar);
      for (auto& t : m.assembly.terms) t->load(ar);
    } else {
      m.integrator.save(ar);
      m.feeder.save(ar);
      for (const auto& t : m.assembly.terms) t->save(ar);
    }
    ar.tag("END_");
    if constexpr (Archive::kLoading) {
      ar.expect_end();
      // Rebuilt from the state by the next evaluation.
      m.mass_nodes = -1;
      m.twist_mass_nodes = -1;
      m.inside.clear();
    }
  }

  // The energy of the last evaluation summed per term type.
  std::array<double, kTermTypes> energy_by_type() const {
    std::array<double, kTermTypes> U{};
    for (size_t k = 0; k < assembly.terms.size(); ++k)
      U[static_cast<int>(assembly.terms[k]->type())] += term_energy[k];
    return U;
  }
};

namespace {
// The engine's parallel loops use `threads` threads while in scope; the caller's setting is
// restored after (the results do not depend on it: every parallel loop writes its own entries
// and sums in a fixed order).
class ThreadScope {
 public:
  explicit ThreadScope(int threads) : saved_(omp_get_max_threads()) {
    omp_set_num_threads(threads);
  }
  ~ThreadScope() { omp_set_num_threads(saved_); }
  ThreadScope(const ThreadScope&) = delete;
  ThreadScope& operator=(const ThreadScope&) = delete;

 private:
  int saved_;
};
}  // namespace

// Built on one thread (the count is set after, by set_threads): a run inside a sweep spawns no
// nested team of all the machine's threads.
Simulation::Simulation(const SceneParams& params) {
  ThreadScope scope(1);
  impl_ = std::make_unique<Impl>(params);
}
Simulation::~Simulation() = default;

void Simulation::set_threads(int threads) {
  impl_->threads = std::max(1, threads);
}
int Simulation::threads() const {
  return impl_->threads;
}

void Simulation::step() {
  ThreadScope scope(impl_->threads);
  impl_->step();
}

void Simulation::advance_to(double l_target) {
  ThreadScope scope(impl_->threads);
  while (l() < l_target) impl_->step();
}

std::string Simulation::save_state() const {
  StateWriter out;
  Impl::serialize(*impl_, out);
  return out.take();
}

void Simulation::restore_state(std::string_view bytes) {
  StateReader in(bytes);
  Impl::serialize(*impl_, in);
}

const SceneParams& Simulation::params() const {
  return impl_->params;
}
double Simulation::L() const {
  return impl_->feeder.injected_length(impl_->time);
}
double Simulation::l() const {
  return L() / impl_->params.R();
}
double Simulation::time() const {
  return impl_->time;
}
double Simulation::dt() const {
  return impl_->integrator.dt();
}
long Simulation::steps() const {
  return impl_->steps;
}
long Simulation::rejected_steps() const {
  return impl_->integrator.rejected();
}

double Simulation::dt_stable() const {
  return impl_->integrator.dt_stable();
}
std::vector<double> Simulation::term_omega_sq() const {
  return impl_->term_omega2;
}

std::span<const Vec3> Simulation::inside_nodes() const {
  return {impl_->state.x.data(), static_cast<size_t>(impl_->state.n_free)};
}
std::span<const Vec3> Simulation::all_nodes() const {
  return impl_->state.x;
}

Energies Simulation::energies() const {
  ThreadScope scope(impl_->threads);  // the terms' energies run the parallel force loops
  const auto U = impl_->energy_by_type();
  const auto of = [&](TermType t) { return U[static_cast<int>(t)]; };
  Energies e;
  e.U_b = of(TermType::kBend);
  e.U_t = of(TermType::kTwist);
  e.U_s = of(TermType::kStretch);
  e.U_m = of(TermType::kMembrane);
  e.U_sb = of(TermType::kShellBending);
  e.U_contact = of(TermType::kWall) + of(TermType::kSelfContact) + of(TermType::kWireShell) +
                of(TermType::kShellSelf);
  e.E_kin = impl_->kinetic_energy(impl_->state.n_free);
  return e;
}

double Simulation::feeder_work() const {
  return impl_->feeder_work;
}

ContactOverlaps Simulation::max_overlaps() const {
  const Assembly& a = impl_->assembly;
  ContactOverlaps o;
  if (a.self_contact) o.wire_wire = a.self_contact->max_overlap();
  if (a.wall) o.wall = a.wall->max_overlap();
  if (a.wire_shell) o.wire_shell = a.wire_shell->max_overlap();
  if (a.wire_shell) o.guide = a.wire_shell->guide_max_overlap();
  return o;
}

int Simulation::wire_contacts() const {
  return impl_->assembly.self_contact ? impl_->assembly.self_contact->contacts() : 0;
}

std::vector<std::string> Simulation::term_names() const {
  std::vector<std::string> names;
  bool friction = false;
  for (const auto& t : impl_->assembly.terms) {
    names.push_back(t->name());
    friction = friction || t->has_friction();
  }
  if (friction) names.push_back("friction");
  return names;
}

std::span<const Vec3> Simulation::shell_vertices() const {
  return impl_->state.shell_x;
}
std::span<const std::array<int, 3>> Simulation::shell_triangles() const {
  if (!impl_->assembly.mesh) return {};
  return impl_->assembly.mesh->faces;
}

std::span<const Vec3> Simulation::shell_rest_vertices() const {
  if (!impl_->assembly.mesh) return {};
  return impl_->assembly.mesh->rest;
}
std::span<const char> Simulation::shell_clamped() const {
  if (!impl_->assembly.mesh) return {};
  return impl_->assembly.mesh->clamped;
}

Vec3List Simulation::shell_contact_forces() const {
  const Assembly& a = impl_->assembly;
  if (!a.mesh || !a.wire_shell) return {};
  ThreadScope scope(impl_->threads);
  return wire_shell_vertex_forces(*a.mesh, a.wire_shell_params, impl_->state);
}

std::vector<int> Simulation::wire_contacts_per_node() const {
  const int n = impl_->state.n_free;
  std::vector<int> count(static_cast<size_t>(std::max(n, 0)), 0);
  if (!impl_->assembly.self_contact || n == 0) return count;
  const auto at = [&](int edge, double param) {
    const int node = std::clamp(edge + (param > 0.5 ? 1 : 0), 0, n - 1);
    ++count[static_cast<size_t>(node)];
  };
  for (const WireContact& c : impl_->assembly.self_contact->contact_list()) {
    at(c.a, c.s);
    at(c.b, c.t);
  }
  return count;
}

}  // namespace wirepack
