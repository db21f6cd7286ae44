// Shell fields of the run file (issue 18): the area stretch of a uniformly inflated shell is
// uniform and known; a short elastic run records every field with the right shapes and values.
#include "sweep/runfile/shell_fields.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "engine/shell/mesh_builders.hpp"
#include "sweep/running/run.hpp"
#include "sweep/temp_dir.hpp"

namespace wirepack::sweep {
namespace {

using wirepack::testing::TempDir;

Points points(const Vec3List& x) {
  Points out;
  for (const Vec3& p : x) out.push_back({p.x(), p.y(), p.z()});
  return out;
}

// The paper's sphere with a hole, inflated uniformly by a factor s about its centre: every
// face's area grows by s^2 (and a rigid motion changes nothing).
TEST(ShellFields, UniformlyInflatedShellHasUniformAreaStretch) {
  const ShellMesh mesh = sphere_with_hole(10e-3, 1e-3, 1.2e-3, 1e-3);
  const Points rest = points(mesh.rest);
  for (double s : {1.0, 1.05, 1.3, 0.9}) {
    Points now = rest;
    for (auto& p : now)
      for (int c = 0; c < 3; ++c) p[c] = s * p[c] + (c == 0 ? 2e-3 : 0.0);  // + a shift
    const std::vector<double> stretch = face_area_stretch(rest, now, mesh.faces);
    ASSERT_EQ(stretch.size(), mesh.faces.size());
    for (double a : stretch) ASSERT_NEAR(a, s * s, 1e-12) << s;
  }
  // Stretched along z only by s: a face's area grows by between 1 and s (its normal's tilt).
  Points now = rest;
  for (auto& p : now) p[2] *= 1.2;
  for (double a : face_area_stretch(rest, now, mesh.faces)) {
    EXPECT_GE(a, 1.0 - 1e-12);
    EXPECT_LE(a, 1.2 + 1e-12);
  }
  EXPECT_THROW(face_area_stretch(rest, Points(3), mesh.faces), std::invalid_argument);
}

// A short elastic run through the run loop: the tip reaches the shell (l ~ 2 at rho = 10).
// Snapshot 0 is the rest state (stretch exactly 1, contact only at the hole); the rim flag is the
// vertices that never move; the contact force pushes the shell outwards at the end; the
// per-node contact counts sum to twice N (the series).
TEST(ShellFields, ElasticRunRecordsTheFields) {
  TempDir dir;
  const Scene scene =
      parse_scene({{"rho", 10},
                   {"xi", 10},
                   {"eps", 1000},
                   {"mu_s", 0},
                   {"shell", "elastic"},
                   {"l_max", 2.6},
                   {"numerics", {{"element_length", 1e-3}, {"shell_mesh_size", 1e-3}}},
                   {"output", {{"every_l", 0.1}, {"snapshots_every_l", 1.0}}}},
                  "short_elastic.json");
  const RunOutcome out = run_scene(scene, dir / "run.h5", nullptr);
  ASSERT_EQ(out.status, RunStatus::Complete) << out.failure;
  const RunRecord r = read_run_file(dir / "run.h5");
  ASSERT_GE(r.snapshots.size(), 3u);
  const Snapshot& first = r.snapshots.front();
  const Snapshot& last = r.snapshots.back();
  for (const Snapshot* s : {&first, &last}) {
    EXPECT_EQ(s->wire_contacts.size(), s->wire.size());
    EXPECT_EQ(s->shell_area_stretch.size(), s->shell_triangles.size());
    EXPECT_EQ(s->shell_contact_force.size(), s->shell_vertices.size());
    EXPECT_EQ(s->shell_clamped.size(), s->shell_vertices.size());
  }
  for (double a : first.shell_area_stretch) EXPECT_EQ(a, 1.0);
  // At l = 0 the wire only passes the hole: a force, if any, on the rim's vertices only (the
  // rim's edges are chords, a little inside the hole's circle).
  const double R = 10 * 0.5e-3;
  for (std::size_t v = 0; v < first.shell_vertices.size(); ++v)
    if (first.shell_contact_force[v] != std::array<double, 3>{0, 0, 0}) {
      EXPECT_LT(first.shell_vertices[v][2], -0.9 * R) << v;
    }
  EXPECT_EQ(first.shell_clamped, last.shell_clamped);
  int clamped = 0;
  for (std::size_t v = 0; v < last.shell_vertices.size(); ++v) {
    const bool held = last.shell_vertices[v] == first.shell_vertices[v];
    EXPECT_EQ(held, last.shell_clamped[v] == 1) << v;
    clamped += last.shell_clamped[v];
  }
  EXPECT_GT(clamped, 3);
  // The pushed shell: stretched somewhere, pushed outwards in all (sum of F . x / |x|).
  double max_stretch = 0;
  for (double a : last.shell_area_stretch) max_stretch = std::max(max_stretch, a);
  EXPECT_GT(max_stretch, 1.0);
  double outward = 0;
  for (std::size_t v = 0; v < last.shell_vertices.size(); ++v) {
    const auto& x = last.shell_vertices[v];
    const auto& f = last.shell_contact_force[v];
    outward += (f[0] * x[0] + f[1] * x[1] + f[2] * x[2]) /
               std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
  }
  EXPECT_GT(outward, 0.0);
  const double N = r.find_series("N")->values.back();
  EXPECT_EQ(std::accumulate(last.wire_contacts.begin(), last.wire_contacts.end(), 0), 2 * N);
}

}  // namespace
}  // namespace wirepack::sweep
