#pragma once
// The CSV tables of `wirepack analyze` (docs/design.md §4.6; columns in docs/reference.md, section
// "Analysis"): text of each file from an Analysis and its reductions.
#include <string>
#include <vector>

#include "report/reductions.hpp"

namespace wirepack::report {

std::string runs_csv(const Analysis& a);
std::string curves_csv(const Analysis& a);
// D against one swept parameter.
std::string view_csv(const Analysis& a, const View& v);
std::string exponents_csv(const Analysis& a, const Fits& fits);
std::string series_csv(const Analysis& a, const std::vector<MeanSeries>& ms);
std::string distributions_csv(const Analysis& a, const std::vector<Samples>& samples,
                              const Distributions& ds);
// loop_sensitivity.csv: per point, the loop parameters over the loop detector's settings.
std::string loop_sensitivity_csv(const Analysis& a, const std::vector<Samples>& samples);
// morphology.csv: per run with a snapshot at the distributions' l, its order parameters there
// (the paper's D, D_chord, D_kappa, the entry chord) and its sense blocks (reversals, order
// length): a coil, a coil wound one way and then the other, or a disordered packing.
std::string morphology_csv(const Analysis& a, const std::vector<Samples>& samples);

}  // namespace wirepack::report
