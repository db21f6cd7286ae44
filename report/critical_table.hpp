#pragma once
// Critical points in `wirepack analyze` and `wirepack refine` (issue 16): the per-point D of a
// sweep cut into slices (one swept transition parameter x, the other swept parameters fixed),
// each fitted by analysis::fit_critical; critical.csv, phase_diagram.csv and the phase-diagram
// plots. docs/reference.md, section "Critical points", documents every column.
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/critical.hpp"

namespace wirepack::report {

// One grid point as the critical-point fits see it.
struct CriticalPoint {
  std::map<std::string, nlohmann::json> params;  // swept parameter (JSON pointer) -> value
  std::vector<double> D;                         // D of each complete run (NaN: none)
  std::size_t failed = 0;                        // failed runs
  std::size_t missing = 0;                       // runs neither complete nor failed
};

// One fit: parameter `axis` over the points whose other swept parameters equal `at`.
struct CriticalSlice {
  std::string axis;                                        // JSON pointer, e.g. "/mu_s"
  std::vector<std::pair<std::string, nlohmann::json>> at;  // the other swept parameters
  std::vector<std::size_t> points;                         // indices of its points
  std::size_t failed = 0, missing = 0;                     // runs over its points
  analysis::CriticalOptions options;                       // log_x for eps
  std::optional<std::pair<double, double>> range;          // [x_min, x_max] fitted, if set
  analysis::CriticalResult fit;
};

// Parameters with a coiling-to-crumpling transition: /mu_s, /eps, /xi, /rho.
bool is_transition_axis(const std::string& pointer);
// eps is fitted in log10(eps) (its values span decades); the others linearly.
bool fitted_in_log(const std::string& pointer);

// The per-seed D of a slice's points (x: the axis value; non-numeric values and values outside
// the slice's range are left out).
std::vector<analysis::CriticalSample> slice_samples(const CriticalSlice& slice,
                                                    const std::vector<CriticalPoint>& points);

// Every slice of every swept transition parameter among `axes` (the swept parameters in
// analysis order), or of `only` alone when it is not empty; slices in order of first appearance
// of their `at` values in `points`. Each is fitted with `resamples` bootstrap resamples, on the
// grid values inside ranges[axis] where given.
std::vector<CriticalSlice> critical_slices(
    const std::vector<std::string>& axes, const std::vector<CriticalPoint>& points, int resamples,
    const std::string& only = "",
    const std::map<std::string, std::pair<double, double>>& ranges = {});

// critical.csv: one row per slice (header only when there is none).
std::string critical_csv(const std::vector<std::string>& axes,
                         const std::vector<CriticalSlice>& slices);

// With exactly two swept parameters of which at least one is a transition parameter:
// phase_diagram.csv (x_c of each transition parameter against the other parameter) and one
// gnuplot script per transition parameter ("phase_<name>", D of every point as a coloured square
// over the plane, the critical line and its 95 % band). Otherwise "" and no scripts.
bool has_phase_diagram(const std::vector<std::string>& axes);
std::string phase_diagram_csv(const std::vector<std::string>& axes,
                              const std::vector<CriticalSlice>& slices);
std::vector<std::pair<std::string, std::string>> phase_diagram_plots(
    const std::vector<std::string>& axes, const std::vector<CriticalPoint>& points,
    const std::vector<CriticalSlice>& slices);

}  // namespace wirepack::report
