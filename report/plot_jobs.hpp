#pragma once
// The gnuplot scripts of `wirepack analyze` (docs/design.md §4.6): one job per plot, its data
// inline (report/plots.hpp writes the script).
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "report/critical_table.hpp"
#include "report/reductions.hpp"

namespace wirepack::report {

struct PlotJob {
  std::string name;    // file stem in plots/
  std::string script;  // gnuplot script text
};

// The order parameter (settings.order_parameter; the literal D beside it when that is another)
// against a swept parameter, one curve per combination of the others; none when the parameter
// is not numeric. With no other swept parameter and a transition fitted along it (the slice of
// `slices` for this axis): the fitted model, x_c with its interval, and an inset magnified
// about x_c (paper Fig. 5b).
std::optional<PlotJob> view_plot(const Analysis& a, const View& v,
                                 const std::vector<CriticalSlice>& slices = {});
// The six scaling laws of point i with their fits.
PlotJob scaling_plot(const Analysis& a, std::size_t i, const MeanSeries& m,
                     const std::vector<ExponentFit>& fits);
// The two distributions of point i with their lognormal fits.
PlotJob distribution_plot(const Analysis& a, std::size_t i, const std::array<Distribution, 2>& ds);
// The packing of point i at the distribution l (first run with a snapshot there): the wire seen
// from the pole and from the side, over the shell; none without a snapshot.
std::optional<PlotJob> packing_plot(const Analysis& a, std::size_t i, const Samples& s);

}  // namespace wirepack::report
