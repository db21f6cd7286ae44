#pragma once
// Twin runs (decorrelation diagnostic): two run files of one scene whose perturbations differ by
// a tiny offset (scene key perturbation/offset), compared snapshot by snapshot: the largest and
// the rms node distance modulo a rotation about the feed axis (analysis/twin.hpp), in wire
// radii, and the first l where each exceeds the threshold (r by default).
#include <string>
#include <vector>

#include "sweep/runfile/run_file.hpp"

namespace wirepack::report {

struct TwinComparison {
  std::vector<double> l;             // l of the compared snapshots (run a's) [-]
  std::vector<double> separation_r;  // largest node distance modulo the rotation / r [-]
  std::vector<double> rms_r;         // rms node distance modulo the rotation / r [-]
  double parting_l = 0;              // first l with separation_r > threshold_r; NaN: never
  double parting_rms_l = 0;          // first l with rms_r > threshold_r; NaN: never
  double threshold_r = 1;            // [-]
};

// Snapshots are paired by index while their l agree within 0.05 (both runs record at the same
// l); the wire radius is run a's. Throws sweep::RunFileError if neither run has a snapshot.
TwinComparison compare_twins(const sweep::RunRecord& a, const sweep::RunRecord& b,
                             double threshold_r = 1.0);

// CSV: "l,separation_r,rms_r", one row per compared snapshot.
std::string twin_csv(const TwinComparison& c);

}  // namespace wirepack::report
