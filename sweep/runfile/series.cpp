#include "sweep/runfile/series.hpp"

#include <algorithm>
#include <limits>

namespace wirepack::sweep {

SeriesContext::SeriesContext(const Simulation& sim, const SceneParams& params, double wall_s)
    : sim_(sim),
      params_(params),
      x_(sim.inside_nodes()),
      energies_(sim.energies()),
      wall_s_(wall_s) {}

const analysis::Order& SeriesContext::order() const {
  if (!order_) order_ = analysis::order_parameter(x_);
  return *order_;
}

std::size_t SeriesContext::chord_start() const {
  if (!chord_start_)
    chord_start_ = entry_chord_start(x_, params_, sim_.shell_vertices(), sim_.shell_triangles());
  return *chord_start_;
}

const analysis::CoilRadii& SeriesContext::radii() const {
  if (!radii_) radii_ = analysis::coil_radii(x_, params_.wire.radius);
  return *radii_;
}

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A coil radius over R, NaN when the fit fails (docs/design.md §5.4).
double radius_over_R(const SeriesContext& c, double analysis::CoilRadii::*radius) {
  return c.radii().ok ? c.radii().*radius / c.R() : kNaN;
}

}  // namespace

const SeriesList& recorded_series() {
  using C = const SeriesContext&;
  // {name, unit, description, compute[, analysis_rank[, compared_by_accuracy]]}; a new series
  // goes at the end (docs/design.md §5.7).
  static const SeriesList list = {
      {"l", "-", "injected length / R", [](C c) { return c.sim().l(); }},
      {"U_b_hat", "-", "U_b r² / (R E_w I) (paper)",
       [](C c) {
         const auto& w = c.params().wire;
         return analysis::bending_energy_hat(c.energies().U_b, w.radius, c.R(), w.youngs_modulus);
       },
       2, true},
      {"U_b", "J", "wire bending energy", [](C c) { return c.energies().U_b; }},
      {"U_t", "J", "wire twisting energy", [](C c) { return c.energies().U_t; }},
      {"U_s", "J", "wire stretching energy", [](C c) { return c.energies().U_s; }},
      {"U_m", "J", "shell membrane energy (0 for a rigid sphere)",
       [](C c) { return c.energies().U_m; }},
      {"U_sb", "J", "shell bending energy (0 for a rigid sphere)",
       [](C c) { return c.energies().U_sb; }},
      {"E_kin", "J", "kinetic energy ½ vᵀ M v with the simulated masses (wire, twist, shell)",
       [](C c) { return c.energies().E_kin; }},
      {"K", "-", "total curvature Σ κ_i ℓ_i", [](C c) { return analysis::total_curvature(c.x()); },
       3, true},
      {"N", "-", "number of wire element pairs in contact",
       [](C c) { return static_cast<double>(c.sim().wire_contacts()); }, 4, true},
      {"S", "-", "average turning sense about the coil normal (docs/design.md §5.3)",
       [](C c) { return c.order().S; }},
      {"D", "-", "disorder D = 1 − abs(S)", [](C c) { return c.order().D; }, 1},
      {"R_t", "-",
       "innermost coil radius / R, half-ellipse cross-section fit (NaN if the wire is not "
       "coil-like)",
       [](C c) { return radius_over_R(c, &analysis::CoilRadii::R_t); }, 5},
      {"R_x", "-", "axial semi-axis of the coil's cross-section / R (NaN as R_t)",
       [](C c) { return radius_over_R(c, &analysis::CoilRadii::R_x); }, 6},
      {"R_y", "-", "radial semi-axis of the coil's cross-section / R (NaN as R_t)",
       [](C c) { return radius_over_R(c, &analysis::CoilRadii::R_y); }, 7},
      {"dt", "s", "current time step", [](C c) { return c.sim().dt(); }},
      {"wall_s", "s", "wall-clock time since the run started (not reproducible)",
       [](C c) { return c.wall_s(); }},
      {"steps", "-", "accepted time steps so far",
       [](C c) { return static_cast<double>(c.sim().steps()); }},
      {"S_kappa", "-",
       "curvature-weighted order S_kappa = ∫κ_n ds / ∫|κ_n| ds (docs/design.md §5.3)",
       [](C c) { return analysis::curvature_weighted_order(c.x()).S; }, 8},
      {"D_chord", "-",
       "D of the wire without its entry chord (from the hole to its first contact; "
       "docs/design.md §5.3); 1 while nothing touches",
       [](C c) { return analysis::order_parameter(c.x().first(c.chord_start())).D; }, 9},
      {"chord", "-", "length of the entry chord / R",
       [](C c) {
         double length = 0;
         for (std::size_t i = c.chord_start(); i + 1 < c.x().size(); ++i)
           length += (c.x()[i + 1] - c.x()[i]).norm();
         return length / c.R();
       }},
  };
  return list;
}

std::vector<std::string> names_of(const SeriesList& list) {
  std::vector<std::string> names;
  for (const auto& s : list) names.push_back(s.name);
  return names;
}

const SeriesDef* find_series_def(const std::string& name, const SeriesList& list) {
  for (const auto& s : list)
    if (s.name == name) return &s;
  return nullptr;
}

std::vector<std::string> analysis_series(const SeriesList& list) {
  std::vector<const SeriesDef*> kept;
  for (const auto& s : list)
    if (s.analysis_rank > 0) kept.push_back(&s);
  std::stable_sort(kept.begin(), kept.end(), [](const SeriesDef* a, const SeriesDef* b) {
    return a->analysis_rank < b->analysis_rank;
  });
  std::vector<std::string> names;
  for (const auto* s : kept) names.push_back(s->name);
  return names;
}

std::vector<std::string> accuracy_series(const SeriesList& list) {
  std::vector<std::string> names;
  for (const auto& s : list)
    if (s.compared_by_accuracy) names.push_back(s.name);
  return names;
}

std::string series_markdown(const SeriesList& list) {
  // A '|' inside a cell is written as "\|" (GitHub's tables).
  const auto cell = [](const std::string& text) {
    std::string out;
    for (const char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
  };
  std::string md = "| name | unit | meaning |\n| --- | --- | --- |\n";
  for (const auto& s : list)
    md += "| `" + s.name + "` | " + cell(s.unit) + " | " + cell(s.description) + " |\n";
  return md;
}

}  // namespace wirepack::sweep
