#include "sweep/runfile/wire_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "engine/contact/triangle_distance.hpp"
#include "sweep/atomic_file.hpp"
#include "sweep/config/scene_config.hpp"
#include "sweep/format.hpp"
#include "sweep/runfile/export.hpp"
#include "sweep/runfile/run_file.hpp"

namespace wirepack::sweep {

using analysis::Vec3;

double distance_to_shell(const Vec3& p, double R, double h, std::span<const Vec3> vertices,
                         std::span<const std::array<int, 3>> triangles) {
  if (vertices.empty()) return R - p.norm();
  double d2 = std::numeric_limits<double>::infinity();
  for (const auto& t : triangles)
    d2 = std::min(d2,
                  point_triangle_closest(p, vertices[t[0]], vertices[t[1]], vertices[t[2]]).dist2);
  return std::sqrt(d2) - h;
}

std::size_t entry_chord_start(analysis::Centerline x, const SceneParams& p,
                              std::span<const Vec3> shell_vertices,
                              std::span<const std::array<int, 3>> shell_triangles,
                              const EntryChordSettings& s) {
  const double r = p.wire.radius;
  const double h = p.shell == ShellKind::Rigid ? 0.0 : 0.5 * p.R() / p.xi;
  const double ell = p.numerics.element_length;
  const auto exclude = static_cast<std::size_t>(std::ceil(s.exclude_arc_r * r / ell));
  return analysis::entry_chord_start(
      x, r, s.slack_r * r, exclude, s.hole_zone_r * r, [&](const Vec3& q) {
        return distance_to_shell(q, p.R(), h, shell_vertices, shell_triangles);
      });
}

OrderVariants order_variants(analysis::Centerline x, const SceneParams& p,
                             std::span<const Vec3> shell_vertices,
                             std::span<const std::array<int, 3>> shell_triangles) {
  OrderVariants o;
  const analysis::Order literal = analysis::order_parameter(x);
  o.S = literal.S;
  o.D = literal.D;
  const analysis::Order weighted = analysis::curvature_weighted_order(x);
  o.S_kappa = weighted.S;
  o.D_kappa = weighted.D;
  const std::size_t k = entry_chord_start(x, p, shell_vertices, shell_triangles);
  // Without a contact (k = 0) the whole wire is the chord: S = 0, D = 1 as for no turning.
  const analysis::Order body = analysis::order_parameter(x.first(k));
  o.S_chord = body.S;
  o.D_chord = body.D;
  o.chord_start = k;
  const analysis::SenseBlocks blocks =
      analysis::sense_blocks(x.first(k), body.n, kMinSenseBlock_R * p.R());
  o.reversals = blocks.reversals;
  o.order_length_R = blocks.order_length / p.R();
  double chord = 0;
  for (std::size_t i = k; i + 1 < x.size(); ++i) chord += (x[i + 1] - x[i]).norm();
  o.chord_length_R = chord / p.R();
  return o;
}

void export_profile(const std::string& run_file, long snapshot, const std::string& csv_path) {
  const RunRecord rec = read_run_for_export(run_file);
  if (snapshot < 0 || snapshot >= static_cast<long>(rec.snapshots.size()))
    throw RunFileError(run_file + ": no snapshot " + std::to_string(snapshot) + " (it has " +
                       std::to_string(rec.snapshots.size()) + ", numbered from 0)");
  const Scene scene = parse_scene(rec.config, run_file + " (config)");
  const SceneParams& p = scene.engine;
  const Snapshot& snap = rec.snapshots[static_cast<std::size_t>(snapshot)];
  std::vector<Vec3> x, sv;
  for (const auto& q : snap.wire) x.emplace_back(q[0], q[1], q[2]);
  for (const auto& q : snap.shell_vertices) sv.emplace_back(q[0], q[1], q[2]);
  const OrderVariants o = order_variants(x, p, sv, snap.shell_triangles);
  const std::size_t k = o.chord_start;
  const double r = p.wire.radius, R = p.R();
  const double h = p.shell == ShellKind::Rigid ? 0.0 : 0.5 * R / p.xi;
  const auto kappa = analysis::curvatures(x);
  const auto ell = analysis::voronoi_lengths(x);
  const auto turn = analysis::signed_turning(x, analysis::coil_normal(x));
  std::ostringstream out;
  out << "# " << run_file << ", snapshot " << snapshot << ", l = " << format_number(snap.l)
      << "\n# D = " << format_number(o.D) << ", D_chord = " << format_number(o.D_chord)
      << ", D_kappa = " << format_number(o.D_kappa)
      << ", entry chord = " << format_number(o.chord_length_R)
      << " R\n# reversals = " << o.reversals
      << ", order length = " << format_number(o.order_length_R) << " R\n";
  out << "from_hole,s_R,kappa_R,kappa_n_R,shell_gap_r,self_contacts,in_chord\n";
  double s = 0;
  const std::size_t n = x.size();
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t i = n - 1 - j;  // the hole is the last node
    if (j > 0) s += (x[i + 1] - x[i]).norm();
    const double kn = ell[i] > 0 ? turn[i] / ell[i] : 0.0;
    const double gap = distance_to_shell(x[i], R, h, sv, snap.shell_triangles) / r - 1;
    const int contacts = i < snap.wire_contacts.size() ? snap.wire_contacts[i] : 0;
    out << j << ',' << format_number(s / R) << ',' << format_number(kappa[i] * R) << ','
        << format_number(kn * R) << ',' << format_number(gap) << ',' << contacts << ','
        << (i >= k ? 1 : 0) << '\n';
  }
  write_file_atomic(csv_path, out.str());
}

}  // namespace wirepack::sweep
