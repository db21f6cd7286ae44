// Point-loaded closed sphere (membrane + bending, linear): Reissner's stiffness of a thin
// spherical shell under a point load, F / delta = 4 E t^2 / (R sqrt(3 (1 - nu^2))) (Reissner
// 1946, shallow-shell theory), delta the deflection under the load relative to the centre.
// The load acts over the bending length ell = sqrt(R t) / (3 (1 - nu^2))^{1/4} (0.078 R at
// R/t = 100), so the mesh must resolve ell at the pole but may be coarse elsewhere: the sphere
// here is two mirrored hemispheres, each a three-direction (valence-6) lattice graded from
// spacing a at the pole to h_e at the equator.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

#include "engine/shell/bending.hpp"
#include "engine/shell/membrane.hpp"
#include "engine/shell/mesh_builders.hpp"
#include "engine/shell/static_solve.hpp"

namespace wirepack {
namespace {

struct PolarSphere {
  ShellMesh mesh;
  int north = -1, south = -1;  // the pole vertices (0, 0, +-R)
};

// Closed sphere of radius R [m] with spacing ~a [m] at both poles and ~h_e [m] at the equator.
// The north hemisphere is the unit triangular lattice (points i (1, 0) + j (1/2, sqrt(3)/2))
// inside the disk rho <= rho_m, each point moved to geodesic distance g(rho) = a rho + b rho^2
// from the pole along its azimuth (g' = a at the pole, h_e at rho_m, g(rho_m) = pi R / 2). The
// hemisphere's boundary vertices are put on the equator and the south hemisphere is the mirror
// image z -> -z sharing them. The lattice is three-direction (valence 6) everywhere inside: the
// midedge-average operator is consistent on it (test_bending.cpp: QuadraticModes).
PolarSphere graded_sphere(double R, double a, double h_e) {
  const double r_max = 0.5 * M_PI * R;
  const double rho_m = 2.0 * r_max / (a + h_e);
  const double b = (h_e - a) / (2.0 * rho_m);
  const double s3 = std::sqrt(3.0) / 2.0;
  auto lattice = [s3](int i, int j) { return Eigen::Vector2d(i + 0.5 * j, s3 * j); };
  const int n = static_cast<int>(std::ceil(rho_m / s3)) + 1;

  // Lattice triangles (counter-clockwise) inside the disk.
  std::vector<std::array<std::pair<int, int>, 3>> tri;
  auto inside = [&](int i, int j) { return lattice(i, j).norm() <= rho_m; };
  for (int j = -n; j <= n; ++j) {
    for (int i = -2 * n; i <= 2 * n; ++i) {
      if (inside(i, j) && inside(i + 1, j) && inside(i, j + 1)) {
        tri.push_back({{{i, j}, {i + 1, j}, {i, j + 1}}});
      }
      if (inside(i + 1, j) && inside(i + 1, j + 1) && inside(i, j + 1)) {
        tri.push_back({{{i + 1, j}, {i + 1, j + 1}, {i, j + 1}}});
      }
    }
  }
  // The disk's staircase boundary can pinch (an interior edge between two boundary vertices,
  // or a vertex on two boundary loops); such edges would be shared by four faces after
  // mirroring. Drop the outermost face at each pinch until there is none.
  ShellMesh hemi;
  std::map<std::pair<int, int>, int> id;
  std::vector<Eigen::Vector2d> pts;
  std::vector<char> on_boundary;
  for (;;) {
    id.clear();
    pts.clear();
    hemi = ShellMesh();
    for (const auto& t : tri) {
      std::array<int, 3> f;
      for (int k = 0; k < 3; ++k) {
        auto it = id.find(t[k]);
        if (it == id.end()) {
          it = id.emplace(t[k], static_cast<int>(pts.size())).first;
          pts.push_back(lattice(t[k].first, t[k].second));
        }
        f[k] = it->second;
      }
      hemi.faces.push_back(f);
    }
    hemi.rest.assign(pts.size(), Vec3::Zero());
    hemi.build_topology();
    on_boundary.assign(pts.size(), 0);
    std::vector<int> boundary_degree(pts.size(), 0);
    for (size_t e = 0; e < hemi.edges.size(); ++e) {
      if (hemi.edge_faces[e][1] >= 0) continue;
      for (int v : hemi.edges[e]) on_boundary[v] = 1, ++boundary_degree[v];
    }
    std::vector<char> drop(tri.size(), 0);
    bool pinched = false;
    auto centroid_rho = [&](int f) {
      const auto& v = hemi.faces[f];
      return ((pts[v[0]] + pts[v[1]] + pts[v[2]]) / 3.0).norm();
    };
    for (size_t e = 0; e < hemi.edges.size(); ++e) {
      const auto& ef = hemi.edge_faces[e];
      const bool pinch_edge =
          ef[1] >= 0 && on_boundary[hemi.edges[e][0]] && on_boundary[hemi.edges[e][1]];
      const bool pinch_vertex = ef[1] < 0 && (boundary_degree[hemi.edges[e][0]] > 2 ||
                                              boundary_degree[hemi.edges[e][1]] > 2);
      if (!pinch_edge && !pinch_vertex) continue;
      pinched = true;
      drop[ef[1] < 0 || centroid_rho(ef[0]) > centroid_rho(ef[1]) ? ef[0] : ef[1]] = 1;
    }
    if (!pinched) break;
    std::vector<std::array<std::pair<int, int>, 3>> kept;
    for (size_t f = 0; f < tri.size(); ++f) {
      if (!drop[f]) kept.push_back(tri[f]);
    }
    tri = std::move(kept);
  }

  PolarSphere s;
  ShellMesh& m = s.mesh;
  const int nh = static_cast<int>(pts.size());
  for (int i = 0; i < nh; ++i) {
    const double rho = pts[i].norm();
    const double g = on_boundary[i] ? r_max : a * rho + b * rho * rho;  // geodesic distance
    const double phi = std::atan2(pts[i].y(), pts[i].x());
    m.rest.emplace_back(R * std::sin(g / R) * std::cos(phi), R * std::sin(g / R) * std::sin(phi),
                        on_boundary[i] ? 0.0 : R * std::cos(g / R));
  }
  std::vector<int> mirror(nh);
  for (int i = 0; i < nh; ++i) {
    if (on_boundary[i]) {
      mirror[i] = i;
    } else {
      mirror[i] = static_cast<int>(m.rest.size());
      m.rest.emplace_back(m.rest[i].x(), m.rest[i].y(), -m.rest[i].z());
    }
  }
  m.faces = hemi.faces;
  for (const auto& f : hemi.faces) m.faces.push_back({mirror[f[0]], mirror[f[2]], mirror[f[1]]});
  m.clamped.assign(m.rest.size(), 0);
  m.build_topology();
  s.north = id.at({0, 0});
  s.south = mirror[s.north];
  return s;
}

struct ReissnerResult {
  double ratio;  // (F / delta) / Reissner's stiffness
  int vertices;
  double min_angle_deg;
};

// Load F at the north pole towards the centre; the south pole is pinned, which is the same
// force system as equal and opposite pole loads (the reaction there is -F). Rigid rotations are
// removed by holding x, y of the north pole and y of the equator vertex nearest (R, 0, 0); these
// carry no reaction. delta = half the change of the pole-to-pole distance.
ReissnerResult reissner(double a_over_ell, double h_e_over_R) {
  const double R = 1.0;
  ShellMaterial mat;
  mat.E = 1.0e7;  // [Pa]
  mat.nu = 0.3;
  mat.t = 0.01 * R;  // R / t = 100
  const double ell = std::sqrt(R * mat.t) / std::pow(3.0 * (1.0 - mat.nu * mat.nu), 0.25);
  const PolarSphere s = graded_sphere(R, a_over_ell * ell, h_e_over_R * R);
  const ShellMesh& mesh = s.mesh;
  int eq = -1;
  for (int i = 0; i < mesh.num_vertices(); ++i) {
    if (mesh.rest[i].z() == 0.0 && (eq < 0 || mesh.rest[i].x() > mesh.rest[eq].x())) eq = i;
  }
  MembraneTerm membrane(mesh, mat);
  BendingTerm bending(mesh, mat);
  std::vector<char> fixed(3 * mesh.rest.size(), 0);
  for (int k = 0; k < 3; ++k) fixed[3 * s.south + k] = 1;
  fixed[3 * s.north + 0] = fixed[3 * s.north + 1] = 1;
  fixed[3 * eq + 1] = 1;
  const double F = 1.0;  // [N]
  Vec3List load(mesh.rest.size(), Vec3::Zero());
  load[s.north] = Vec3(0.0, 0.0, -F);
  const Vec3List u = testing::solve_linear({&membrane, &bending}, mesh, fixed, load);
  const double delta = -0.5 * (u[s.north].z() - u[s.south].z());
  const double k_reissner =
      4.0 * mat.E * mat.t * mat.t / (R * std::sqrt(3.0 * (1.0 - mat.nu * mat.nu)));
  return {F / delta / k_reissner, mesh.num_vertices(), mesh_quality(mesh).min_angle_deg};
}

TEST(Reissner, GradedSphereMeshIsClosedAndOriented) {
  const PolarSphere s = graded_sphere(1.0, 0.01, 0.2);
  const ShellMesh& m = s.mesh;
  for (const auto& ef : m.edge_faces) EXPECT_GE(ef[1], 0);                            // closed
  EXPECT_EQ(m.num_vertices() - static_cast<int>(m.edges.size()) + m.num_faces(), 2);  // Euler
  for (const auto& f : m.faces) {  // outward normals, no inverted face
    const Vec3 c = (m.rest[f[0]] + m.rest[f[1]] + m.rest[f[2]]) / 3.0;
    EXPECT_GT((m.rest[f[1]] - m.rest[f[0]]).cross(m.rest[f[2]] - m.rest[f[0]]).dot(c), 0.0);
  }
  EXPECT_NEAR(m.rest[s.north].z(), 1.0, 1e-12);
  EXPECT_NEAR(m.rest[s.south].z(), -1.0, 1e-12);
}

TEST(Reissner, PointLoadedSphereStiffness) {
  // Pole spacing ell/4 .. ell/32, equator spacing 0.2 R (R/t = 100, nu = 0.3).
  const double fractions[4] = {0.25, 0.125, 0.0625, 0.03125};
  double r[4];
  for (int k = 0; k < 4; ++k) {
    const auto res = reissner(fractions[k], 0.2);
    r[k] = res.ratio;
    std::printf(
        "  pole spacing ell/%-3.0f: %5d vertices (min angle %.1f deg), "
        "(F/delta) / Reissner = %.4f\n",
        1.0 / fractions[k], res.vertices, res.min_angle_deg, r[k]);
  }
  // Measured 0.918, 0.960, 0.979, 0.989: the discrete point load is too soft by ~ a / ell and
  // converges at first order (the gaps halve: 0.042, 0.019, 0.010); the Richardson value
  // 2 r_32 - r_16 = 0.999. The equator spacing hardly matters (the response decays over a few
  // ell): at ell/16, h_e = 0.1 R and 0.06 R gave 0.9794 and 0.9794 (4 and 19 s, not run here).
  // Bounds: monotone, 5 % at ell/16 and ell/32 (issue 4), 1 % for the extrapolation.
  for (int k = 0; k < 3; ++k) EXPECT_LT(r[k], r[k + 1]);
  EXPECT_NEAR(r[2], 1.0, 0.05);
  EXPECT_NEAR(r[3], 1.0, 0.05);
  const double extrapolated = 2.0 * r[3] - r[2];
  std::printf("  Richardson (first order): %.4f\n", extrapolated);
  EXPECT_NEAR(extrapolated, 1.0, 0.01);
}

}  // namespace
}  // namespace wirepack
