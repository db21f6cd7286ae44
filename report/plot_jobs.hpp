#pragma once
// The gnuplot scripts of `wirepack analyze` (docs/design.md §4.6): one job per plot, its data
// inline (report/plots.hpp writes the script).
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "report/reductions.hpp"

namespace wirepack::report {

struct PlotJob {
  std::string name;    // file stem in plots/
  std::string script;  // gnuplot script text
};

// D against a swept parameter, one curve per combination of the others; none when the
// parameter is not numeric.
std::optional<PlotJob> view_plot(const Analysis& a, const View& v);
// The six scaling laws of point i with their fits.
PlotJob scaling_plot(const Analysis& a, std::size_t i, const MeanSeries& m,
                     const std::vector<ExponentFit>& fits);
// The two distributions of point i with their lognormal fits.
PlotJob distribution_plot(const Analysis& a, std::size_t i, const std::array<Distribution, 2>& ds);
// The packing of point i at the distribution l (first run with a snapshot there): the wire seen
// from the pole and from the side, over the shell; none without a snapshot.
std::optional<PlotJob> packing_plot(const Analysis& a, std::size_t i, const Samples& s);

}  // namespace wirepack::report
