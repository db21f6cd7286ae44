#pragma once
// Where along the wire it turns, and in which sense (docs/design.md §5.3): the entry chord, the
// order parameter without it, and a per-node table of a snapshot counted from the hole, for
// `wirepack export --profile` and the recorder.
#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "analysis/observables.hpp"
#include "engine/params.hpp"

namespace wirepack::sweep {

// Distance of a point inside the cavity to the shell's inner surface [m]: R - |p| for the rigid
// sphere (centred at the origin; `vertices` empty), else the distance to the nearest triangle of
// the deformed mid-surface minus half the thickness h.
double distance_to_shell(const analysis::Vec3& p, double R, double h,
                         std::span<const analysis::Vec3> vertices,
                         std::span<const std::array<int, 3>> triangles);

// The entry chord's geometric definition (analysis::entry_chord_start): a node touches when its
// centreline is within r + slack of the shell's surface, or within 2 r + slack of a node at least
// an arc of exclude_arc (in r) away along the wire; nodes within hole_zone of the hole are on the
// hole's rim and not tested.
struct EntryChordSettings {
  double slack_r = 0.25;       // slack over r: the contacts' skin [-]
  double exclude_arc_r = 6.3;  // 2 pi: closer along the wire, two nodes are neighbours [-]
  double hole_zone_r = 4.0;    // [-]
};

// Inside wire (tip first, the hole last) of a scene: the index k where the entry chord starts
// (nodes k..n-1 are the chord; k = 0: the wire touches nothing).
std::size_t entry_chord_start(analysis::Centerline x, const SceneParams& p,
                              std::span<const analysis::Vec3> shell_vertices,
                              std::span<const std::array<int, 3>> shell_triangles,
                              const EntryChordSettings& settings = {});

// The order parameters of one configuration: the paper's S, D (all inside nodes), the same
// without the entry chord, and the curvature-weighted S_kappa.
struct OrderVariants {
  double S = 0, D = 1;              // paper, literal
  double S_chord = 0, D_chord = 1;  // without the entry chord (its own coil normal)
  double S_kappa = 0, D_kappa = 1;  // curvature-weighted
  std::size_t chord_start = 0;      // entry_chord_start: nodes chord_start..n-1 are the chord
  double chord_length_R =
      0;  // arc length of the entry chord (node chord_start to the hole) over R [-]
  // Sense blocks of the wire without the entry chord about D_chord's axis (analysis::sense_blocks),
  // blocks shorter than kMinSenseBlock_R merged: a coil has none, a coil wound one way and then
  // the other one, a disordered packing one per loop or so.
  std::size_t reversals = 0;
  double order_length_R = 0;  // their length-weighted mean length over R [-]
};
// The shortest sense block resolved, over R: the sign changes of kappa_n over shorter stretches
// are not a loop turned the other way (the loops of the packings are longer: Fig. 6, Lambda of
// 1.5-3 R at rho = 20), e.g. the entry chord's own S-bend (0.35 R) [-].
inline constexpr double kMinSenseBlock_R = 1.0;
OrderVariants order_variants(analysis::Centerline x, const SceneParams& p,
                             std::span<const analysis::Vec3> shell_vertices,
                             std::span<const std::array<int, 3>> shell_triangles);

// One row per inside node, counted from the hole (row 0 = the node at the hole).
struct ProfileRow {
  int from_hole = 0;       // nodes from the hole [-]
  double s_R = 0;          // arc length from the hole over R [-]
  double kappa_R = 0;      // curvature times R [-]
  double kappa_n_R = 0;    // signed curvature about the coil normal (the axis of D) times R [-]
  double shell_gap_r = 0;  // distance_to_shell over r, minus 1: < slack where it touches [-]
  int self_contacts = 0;   // the snapshot's wire_contacts at this node (0 if not recorded)
  bool in_chord = false;   // part of the entry chord
};
struct WireProfile {
  double l = 0;
  OrderVariants order;
  std::vector<ProfileRow> rows;
};

// `wirepack export RUN --profile CSV --snapshot K`: snapshot K's profile as CSV, commented
// header lines (`# l = ...`, the three D) then a header row and one row per node. Written to a
// temporary name and renamed. Throws RunFileError (unreadable run file, no snapshot K) or
// InputError.
void export_profile(const std::string& run_file, long snapshot, const std::string& csv_path);

}  // namespace wirepack::sweep
