#pragma once
// `wirepack accuracy DIR...` (issue 7): the accuracy-vs-time study. Reads the complete runs of
// one or more sweep directories (a run found in several is read once) and measures, for every
// setting of the four resolution knobs (element_length, shell_mesh_size, quasistatic_ratio,
// tolerance), what it costs (wall time, steps) and how far U_b_hat(l), K(l), N(l) and D_max
// are from the finest setting of its ladder.
//
// Families and ladders: a run's scene is its resolved config without the four knobs and without
// its output settings; runs of one scene and one seed form a family. The family's centre is the
// run whose knobs each take the most frequent value among the scene's runs (all seeds; in
// one-knob-at-a-time ladders: the default setting, which every ladder shares). The ladder of knob k
// is the centre and every run that differs from it in k alone; its reference is the run with the
// smallest k (the finest). Runs in no ladder (several knobs off the centre, e.g. the presets of a
// sweep over /numerics/preset) are compared with the family's run that is finest in every knob,
// when there is one (knob "combined", value nan). The chaos floor: centres of one scene with
// different seeds are compared with the smallest seed's (knob "seed"), the error no numerics can
// beat for one trajectory.
//
// Outputs, in OUT (default: the first DIR/accuracy), written to a temporary name and renamed:
//   accuracy.csv    one row per (scene, seed, knob, value); columns in docs/reference.md
//   pareto.gp/.png  err_UK (the larger relative error of U_b_hat and K) against wall time per
//                   scene, one point set per knob, the seed floor as a line (gnuplot, if present)
#include <cstddef>
#include <string>
#include <vector>

#include "report/settings.hpp"

namespace wirepack::report {

// The knobs of the study, in column order: "element_length", "shell_mesh_size",
// "quasistatic_ratio", "tolerance" (scene keys under /numerics).
const std::vector<std::string>& accuracy_knobs();

// Columns of accuracy.csv, in order. err_N compares N ell / r (contacting element pairs times
// the element length over r), so that element lengths can be compared.
const std::vector<std::string>& accuracy_columns();

struct AccuracyOptions {
  std::vector<std::string> dirs;    // sweep directories (DIR/runs/*.h5)
  std::string out;                  // "" = dirs[0]/accuracy
  LWindow window;                   // l window of the series errors and of D_max (default [5, 50])
  std::string gnuplot = "gnuplot";  // "" = write the script only
};

struct AccuracyResult {
  std::string out;          // output directory
  std::string csv;          // path of accuracy.csv
  std::string plot;         // path of pareto.png ("" when not drawn)
  std::string plot_notice;  // why there is no plot
  std::size_t runs = 0;     // complete runs read
  std::size_t rows = 0;     // rows of accuracy.csv
  std::size_t ladders = 0;  // (family, knob) ladders with at least two settings
};

// Relative RMS difference of y against y_ref on the rows with l in [lo, hi] of the run:
// sqrt(sum (y - y_ref(l))^2 / sum y_ref(l)^2), y_ref linearly interpolated at the run's l.
// NaN when no row is in the window or the reference is zero there.
double relative_rms_error(const std::vector<double>& l, const std::vector<double>& y,
                          const std::vector<double>& l_ref, const std::vector<double>& y_ref,
                          double lo, double hi);

// Reads, compares, writes. Throws InputError (exit 2) when a DIR is not a directory with run
// files or OUT cannot be created; nothing is written then.
AccuracyResult accuracy_study(const AccuracyOptions& options);

}  // namespace wirepack::report
