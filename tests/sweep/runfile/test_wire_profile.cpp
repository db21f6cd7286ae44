// Tests for sweep/wire_profile: the distance to the shell (rigid sphere and a triangle), the
// entry chord and the order-parameter variants on a synthetic packing with a known chord (an
// arc lying on the rigid wall, joined to the hole by a straight chord), and the profile export
// of a run file (rows from the hole, chord flags, a missing snapshot refused).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "sweep/config/scene_config.hpp"
#include "sweep/runfile/run_file.hpp"
#include "sweep/runfile/wire_profile.hpp"
#include "sweep/temp_dir.hpp"

namespace wirepack::sweep {
namespace {

using analysis::Vec3;
using testing::TempDir;
constexpr double pi = std::numbers::pi;

SceneParams rigid_scene() {
  return parse_scene(default_scene_json(), "default").engine;
}

TEST(DistanceToShell, RigidSphereAndATriangle) {
  // Rigid: R - |p|.
  EXPECT_DOUBLE_EQ(distance_to_shell(Vec3(0, 0.003, 0.004), 0.01, 0, {}, {}), 0.005);
  // Elastic: nearest point of the triangle minus h; above its interior, and beyond a vertex.
  const std::vector<Vec3> v{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<std::array<int, 3>> t{{0, 1, 2}};
  EXPECT_NEAR(distance_to_shell(Vec3(0.2, 0.2, 0.5), 1, 0.1, v, t), 0.4, 1e-15);
  EXPECT_NEAR(distance_to_shell(Vec3(-3, -4, 0), 1, 0.1, v, t), 4.9, 1e-12);
}

// The default rigid scene (R = 20 r, r = element length): an arc of 0.9 turn about +z in the
// plane z = 0 on the wall (radius R - r: it touches), counter-clockwise, ending at P = (a, 0, 0);
// then a straight chord from P down to the hole H = (0, 0, -(R - r)), nodes r apart; H last.
struct Packing {
  std::vector<Vec3> x;
  std::size_t p_index = 0;  // index of P
  double chord_length = 0;  // |H - P| [m]
};
Packing arc_and_chord(const SceneParams& s) {
  const double r = s.wire.radius, a = s.R() - r;
  Packing k;
  const int m = static_cast<int>(std::round(0.9 * 2 * pi * a / r));
  for (int j = 0; j <= m; ++j) {
    const double t = -0.9 * 2 * pi * (1.0 - static_cast<double>(j) / m);
    k.x.emplace_back(a * std::cos(t), a * std::sin(t), 0);
  }
  k.p_index = k.x.size() - 1;
  const Vec3 P = k.x.back(), H(0, 0, -a);
  k.chord_length = (H - P).norm();
  const int c = static_cast<int>(std::round(k.chord_length / r));
  for (int j = 1; j <= c; ++j) k.x.push_back(P + (H - P) * (static_cast<double>(j) / c));
  return k;
}

TEST(EntryChord, StartsAfterTheLastNodeOnTheWall) {
  const SceneParams s = rigid_scene();
  ASSERT_EQ(s.shell, ShellKind::Rigid);
  ASSERT_DOUBLE_EQ(s.numerics.element_length, s.wire.radius);
  const Packing k = arc_and_chord(s);
  // P lies on the wall (gap 0 < slack); the chord's first node past it is 0.68 r off the wall
  // (moving r along a chord at 45 degrees to the radius: 0.707 r minus the curvature term), so
  // the chord is every node after P.
  EXPECT_EQ(entry_chord_start(k.x, s, {}, {}), k.p_index + 1);
  // Without the arc nothing touches but the hole's rim: the whole wire is the chord.
  const std::vector<Vec3> chord_only(k.x.begin() + static_cast<long>(k.p_index) + 1, k.x.end());
  EXPECT_EQ(entry_chord_start(chord_only, s, {}, {}), 0u);
}

TEST(EntryChord, OrderVariantsDropTheChord) {
  const SceneParams s = rigid_scene();
  const Packing k = arc_and_chord(s);
  const OrderVariants o = order_variants(k.x, s, {}, {});
  // The literal D counts the straight chord's length with sign 0: D = 1 - |S| is about the
  // chord's share of the interior length (the chord's nodes and the kink at P; one node of
  // slack each way).
  double total = 0;
  for (std::size_t i = 0; i + 1 < k.x.size(); ++i) total += (k.x[i + 1] - k.x[i]).norm();
  const double r = s.wire.radius;
  EXPECT_NEAR(o.D, k.chord_length / total, 2 * r / total);
  // Without the chord the arc turns one way only: D = 0. Weighted by curvature the straight
  // chord weighs nothing and the kink at P turns the same way as the arc: D_kappa = 0.
  EXPECT_NEAR(o.D_chord, 0.0, 1e-12);
  EXPECT_NEAR(o.D_kappa, 0.0, 1e-12);
  EXPECT_EQ(o.chord_start, k.p_index + 1);
  // The arc is one sense block: no reversal, the block as long as the arc's interior nodes.
  EXPECT_EQ(o.reversals, 0u);
  const auto ell = analysis::voronoi_lengths(std::span(k.x).first(o.chord_start));
  double arc = 0;
  for (std::size_t i = 1; i + 1 < ell.size(); ++i) arc += ell[i];
  EXPECT_NEAR(o.order_length_R, arc / s.R(), 1e-12);
  EXPECT_NEAR(o.chord_length_R,
              (k.chord_length - k.chord_length / std::round(k.chord_length / r)) / s.R(), 1e-12);
}

TEST(ExportProfile, RowsFromTheHoleWithTheChordFlagged) {
  const SceneParams s = rigid_scene();
  const Packing k = arc_and_chord(s);
  RunRecord rec;
  rec.config = parse_scene(default_scene_json(), "default").resolved;
  rec.status = RunStatus::Complete;
  rec.series = {{"l", {0.0, 1.0}}};
  Snapshot snap;
  snap.l = 1.0;
  for (const Vec3& p : k.x) snap.wire.push_back({p.x(), p.y(), p.z()});
  snap.curvature.assign(k.x.size(), 0.0);
  rec.snapshots.push_back(snap);
  TempDir dir;
  write_run_file(rec, dir / "run.h5");
  export_profile(dir / "run.h5", 0, dir / "profile.csv");
  std::ifstream in(dir / "profile.csv");
  std::string line;
  std::vector<std::string> rows;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') rows.push_back(line);
  ASSERT_EQ(rows.size(), k.x.size() + 1);
  EXPECT_EQ(rows[0], "from_hole,s_R,kappa_R,kappa_n_R,shell_gap_r,self_contacts,in_chord");
  // Row 1 is the hole (in the chord), the last row the tip (on the wall, not in it); the chord
  // has x.size() - (p_index + 1) nodes.
  const std::size_t chord_nodes = k.x.size() - k.p_index - 1;
  for (std::size_t j = 0; j < k.x.size(); ++j) {
    const std::string& row = rows[j + 1];
    const char flag = row.back();
    EXPECT_EQ(flag, j < chord_nodes ? '1' : '0') << "row " << j << ": " << row;
    EXPECT_EQ(row.substr(0, row.find(',')), std::to_string(j));
  }
  EXPECT_THROW(export_profile(dir / "run.h5", 1, dir / "p2.csv"), RunFileError);
  EXPECT_FALSE(std::ifstream(dir / "p2.csv").good());
}

}  // namespace
}  // namespace wirepack::sweep
