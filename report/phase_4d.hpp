#pragma once
// The four-dimensional phase diagram (beyond the paper, its open question of "the full image of
// the four-dimensional parameter space"): the critical points of any set of sweeps in one table
// over the transition parameters of the scene schema (rho, xi, eps, mu_s; KeySpec::Roles), and
// its picture, x_c of each transition parameter as a family of curves with 95 % intervals.
// `wirepack analyze DIR DIR ... --out OUT` writes them (analyze.hpp).
#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/critical_table.hpp"

namespace wirepack::report {

// One sweep as the table reads it: its swept parameters, its points (CriticalPoint::params
// holding every transition parameter, swept or not) and the fit settings.
struct PhaseSource {
  std::string name;               // the sweep directory, as given
  std::string order_parameter;    // what D is in this sweep's fits ("D", "D_chord", ...)
  std::vector<std::string> axes;  // swept parameters (JSON pointers)
  std::vector<CriticalPoint> points;
  int resamples = 0;
  std::map<std::string, std::pair<double, double>> ranges;  // critical_ranges
};

// One critical point: x_c of `axis` where every other transition parameter has the value in
// `at`, and the swept parameters that are not transition parameters have `other`.
struct PhaseRow {
  std::string source;
  std::string order_parameter;
  std::string axis;                          // JSON pointer
  std::map<std::string, nlohmann::json> at;  // transition parameter -> value (not axis)
  std::vector<std::pair<std::string, nlohmann::json>> other;  // e.g. /shell_material
  CriticalSlice slice;                                        // the fit and its counts
};

// Every slice of every source, in source order.
std::vector<PhaseRow> phase_rows(const std::vector<PhaseSource>& sources);

// phase_diagram_4d.csv: one row per critical point: source, order_parameter, axis, one column
// per transition
// parameter (blank in the axis's own), other, status, model, x_c, x_c_lo, x_c_hi, points,
// values, note.
std::string phase_4d_csv(const std::vector<PhaseRow>& rows);

// One gnuplot script per transition parameter with at least two fitted points ("phase4d_<name>"):
// x_c against the other transition parameter that takes the most values among them (log scale
// where it spans a decade), one curve with the 95 % intervals as bars per combination of the rest
// (and per source, where the points come from several sweeps).
std::vector<std::pair<std::string, std::string>> phase_4d_plots(const std::vector<PhaseRow>& rows);

}  // namespace wirepack::report
