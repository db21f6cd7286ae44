#pragma once
// The recorded observables (docs/design.md §5.7): one list, declared once, with each series'
// name, unit, description and how it is computed. The recorder (run.cpp) fills one value of
// every series per row, in list order; the run file, `wirepack export --csv`, the table of series
// in docs/reference.md, `wirepack analyze` (the kept series) and `wirepack accuracy` (the
// compared series) take their columns from it. A new output column is one more entry in
// recorded_series().
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "analysis/observables.hpp"
#include "engine/simulation.hpp"
#include "sweep/runfile/wire_profile.hpp"

namespace wirepack::sweep {

// What a series sees at one recorded row. The order parameter and the coil radii are computed
// on first use and kept for the row's other series.
class SeriesContext {
 public:
  // `params`: the scene's engine parameters (those the simulation was made from).
  SeriesContext(const Simulation& sim, const SceneParams& params, double wall_s);
  SeriesContext(const SeriesContext&) = delete;
  SeriesContext& operator=(const SeriesContext&) = delete;

  const Simulation& sim() const { return sim_; }
  const SceneParams& params() const { return params_; }
  std::span<const Vec3> x() const { return x_; }  // the inside wire, tip first [m]
  const Energies& energies() const { return energies_; }
  double R() const { return params().R(); }  // sphere radius [m]
  double wall_s() const { return wall_s_; }  // wall-clock seconds since the run started
  const analysis::Order& order() const;
  const analysis::CoilRadii& radii() const;
  // Index where the entry chord starts (sweep/runfile/wire_profile.hpp: nodes chord_start..n-1).
  std::size_t chord_start() const;

 private:
  const Simulation& sim_;
  const SceneParams& params_;
  std::span<const Vec3> x_;
  Energies energies_;
  double wall_s_;
  mutable std::optional<analysis::Order> order_;
  mutable std::optional<analysis::CoilRadii> radii_;
  mutable std::optional<std::size_t> chord_start_;
};

struct SeriesDef {
  std::string name;         // column name, e.g. "U_b_hat"
  std::string unit;         // "-" when dimensionless
  std::string description;  // one line (the table in docs/reference.md)
  std::function<double(const SeriesContext&)> compute;
  // Position among the series `wirepack analyze` keeps per complete run (series.csv columns,
  // 1 first); 0: not kept.
  int analysis_rank = 0;
  bool compared_by_accuracy = false;  // a relative RMS error column err_<name> of accuracy.csv
};
using SeriesList = std::vector<SeriesDef>;

// The recorded series, in column order: l, U_b_hat, U_b, U_t, U_s, U_m, U_sb, E_kin, K, N, S, D,
// R_t, R_x, R_y, dt, wall_s, steps, S_kappa, D_chord, chord (descriptions and units in
// sweep/runfile/series.cpp and docs/reference.md).
const SeriesList& recorded_series();

// The names of `list`, in column order.
std::vector<std::string> names_of(const SeriesList& list);
// The series of `list` called `name`, or nullptr.
const SeriesDef* find_series_def(const std::string& name,
                                 const SeriesList& list = recorded_series());
// The series kept by the analysis, by analysis_rank.
std::vector<std::string> analysis_series(const SeriesList& list = recorded_series());
// The series compared by the accuracy study, in column order.
std::vector<std::string> accuracy_series(const SeriesList& list = recorded_series());

// docs/reference.md's table of series (name, unit, meaning), one row per series, in column order.
std::string series_markdown(const SeriesList& list = recorded_series());

}  // namespace wirepack::sweep
