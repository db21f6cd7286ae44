#pragma once
// Twin runs (decorrelation diagnostic, docs/design.md §5): two runs of one scene whose initial
// perturbations differ by a tiny offset. Where their wires part by more than r, modulo a rotation
// about the feed axis (the scene's symmetry: a seed picks an azimuth), the dynamics have
// amplified the offset; runs that never part follow one trajectory. Pure functions.
#include <span>
#include <vector>

#include <Eigen/Core>

namespace wirepack::analysis {

struct TwinSeparation {
  double max = 0;  // largest node distance [m]
  double rms = 0;  // root mean square node distance [m]
};
// Node distances between centerlines a and b (nodes in order from the hole, the common
// n = min(|a|, |b|) first nodes compared) after rotating a about the z axis (the feed axis,
// through the origin) by the angle that minimises sum_i |R(phi) a_i - b_i|^2:
// phi = atan2(sum_i (a_i x b_i)_z, sum_i (a_ix b_ix + a_iy b_iy)). Zeros for n = 0. The largest
// distance sees a local departure (a stick-slip event at another moment), the rms one a
// different packing.
TwinSeparation twin_separation(std::span<const Eigen::Vector3d> a,
                               std::span<const Eigen::Vector3d> b);

// First l at which the separation exceeds `threshold` (l and separation of equal length, in
// order of l); NaN if it never does.
double twin_parting_l(std::span<const double> l, std::span<const double> separation,
                      double threshold);

}  // namespace wirepack::analysis
