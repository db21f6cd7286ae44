// Shell meshes: topology (Euler characteristic, orientation, edge/face tables), the sphere
// with its clamped hole, the flat square, and the quality figures we reach (docs/design.md §2.4).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

#include "engine/shell/mesh_builders.hpp"

namespace wirepack {
namespace {

int euler_characteristic(const ShellMesh& m) {
  return m.num_vertices() - static_cast<int>(m.edges.size()) + m.num_faces();
}

bool traverses(const std::array<int, 3>& f, int a, int b) {
  for (int k = 0; k < 3; ++k) {
    if (f[k] == a && f[(k + 1) % 3] == b) return true;
  }
  return false;
}

// Each undirected edge is traversed once in each direction by its two faces (once on a
// boundary), and the edge / face tables agree with the faces.
void expect_consistent_tables(const ShellMesh& m) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& f : m.faces) {
    for (int k = 0; k < 3; ++k) ++directed[{f[k], f[(k + 1) % 3]}];
  }
  for (const auto& [e, count] : directed) EXPECT_EQ(count, 1) << e.first << "->" << e.second;
  ASSERT_EQ(m.edges.size(), m.edge_faces.size());
  for (size_t e = 0; e < m.edges.size(); ++e) {
    const int a = m.edges[e][0], b = m.edges[e][1];
    EXPECT_LT(a, b);
    const int f0 = m.edge_faces[e][0], f1 = m.edge_faces[e][1];
    ASSERT_GE(f0, 0);
    // Interior edge: face [0] traverses a -> b, face [1] b -> a; boundary: the one face in [0].
    if (f1 >= 0) {
      EXPECT_TRUE(traverses(m.faces[f0], a, b));
      EXPECT_TRUE(traverses(m.faces[f1], b, a));
    } else {
      EXPECT_TRUE(traverses(m.faces[f0], a, b) || traverses(m.faces[f0], b, a));
    }
    for (int f : {f0, f1}) {
      if (f < 0) continue;
      // face_edges: edge k of the face is opposite its vertex k.
      int k = 0;
      while (k < 3 && m.face_edges[f][k] != static_cast<int>(e)) ++k;
      ASSERT_LT(k, 3);
      EXPECT_NE(m.faces[f][k], a);
      EXPECT_NE(m.faces[f][k], b);
    }
  }
}

void print_quality(const char* what, const MeshQuality& q) {
  std::printf(
      "  %s: V=%d F=%d angles %.1f..%.1f deg, edge %.3g..%.3g (mean %.3g, cv %.3f, max/min "
      "%.3f), area max/min %.3f\n",
      what, q.vertices, q.faces, q.min_angle_deg, q.max_angle_deg, q.edge_min, q.edge_max,
      q.edge_mean, q.edge_cv, q.edge_max / q.edge_min, q.area_max / q.area_min);
}

// Geodesic angle of a point from the south pole [rad].
double from_south(const Vec3& x) {
  return std::atan2(std::hypot(x.x(), x.y()), -x.z());
}

TEST(ShellMesh, TopologyOfTwoTriangles) {
  ShellMesh m;
  m.rest = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  m.faces = {{0, 1, 2}, {0, 2, 3}};
  m.clamped.assign(4, 0);
  m.build_topology();
  ASSERT_EQ(m.edges.size(), 5u);
  EXPECT_EQ(euler_characteristic(m), 1);
  expect_consistent_tables(m);
  // The diagonal (0, 2) is interior: face 1 traverses it 0 -> 2 (slot 0), face 0 2 -> 0.
  for (size_t e = 0; e < m.edges.size(); ++e) {
    if (m.edges[e] == std::array<int, 2>{0, 2}) {
      EXPECT_EQ(m.edge_faces[e][0], 1);
      EXPECT_EQ(m.edge_faces[e][1], 0);
    } else {
      EXPECT_EQ(m.edge_faces[e][1], -1);
    }
  }
  // Inconsistent orientation and non-manifold edges are refused.
  ShellMesh bad = m;
  bad.faces = {{0, 1, 2}, {0, 3, 2}};
  EXPECT_THROW(bad.build_topology(), std::invalid_argument);
  bad.rest.push_back(Vec3(1, 0, 1));
  bad.faces = {{0, 1, 2}, {0, 2, 3}, {2, 0, 4}};
  EXPECT_THROW(bad.build_topology(), std::invalid_argument);
}

// Closed geodesic spheres at three sizes: a closed, consistently and outward oriented surface
// on the sphere; quality reached with the spring relaxation (n = 3, 6, 12): min angle > 53 deg,
// edge cv < 0.06, max/min edge < 1.25 (1.21 at n = 12), max/min area < 1.3 (1.25), mean edge
// within 5 % of target.
TEST(ShellMesh, ClosedSphereTopologyAndQuality) {
  const double R = 1.0;
  for (double target : {0.4, 0.2, 0.1}) {
    const ShellMesh m = geodesic_sphere(R, target);
    const int n = sphere_frequency(R, target);
    EXPECT_EQ(m.num_vertices(), 10 * n * n + 2);
    EXPECT_EQ(m.num_faces(), 20 * n * n);
    EXPECT_EQ(euler_characteristic(m), 2);
    expect_consistent_tables(m);
    for (const auto& ef : m.edge_faces) EXPECT_GE(ef[1], 0);  // no boundary
    for (const Vec3& x : m.rest) EXPECT_NEAR(x.norm(), R, 1e-12 * R);
    for (const auto& f : m.faces) {
      const Vec3 nrm = (m.rest[f[1]] - m.rest[f[0]]).cross(m.rest[f[2]] - m.rest[f[0]]);
      EXPECT_GT(nrm.dot(m.rest[f[0]] + m.rest[f[1]] + m.rest[f[2]]), 0.0);  // outward
    }
    // The poles are vertices (the hole is centred on one).
    int poles = 0;
    for (const Vec3& x : m.rest) poles += std::abs(std::abs(x.z()) - R) < 1e-12 ? 1 : 0;
    EXPECT_EQ(poles, 2);
    const MeshQuality q = mesh_quality(m);
    print_quality(("sphere, target " + std::to_string(target)).c_str(), q);
    EXPECT_GT(q.min_angle_deg, 53.0);
    EXPECT_LT(q.edge_cv, 0.06);
    EXPECT_LT(q.edge_max / q.edge_min, 1.25);
    EXPECT_LT(q.area_max / q.area_min, 1.3);
    EXPECT_NEAR(q.edge_mean / target, 1.0, 0.05);
  }
}

// The paper's shell (R = 10 mm, mesh size 1 mm) with holes from below one edge to a third of
// R: a disc removed (chi = 1, one boundary loop), the boundary on the circle of geodesic
// radius max(hole_radius, 0.6 edges), no vertex and no face centroid in the hole, exactly the
// vertices within hole_radius + clamp_width clamped; min angle > 35 deg (we reach >= 40.8).
TEST(ShellMesh, SphereWithClampedHole) {
  const double R = 10e-3, edge = 1e-3, clamp = 0.5e-3;
  for (double hole : {0.1e-3, 0.75e-3, 1e-3, 2e-3, 3.3e-3}) {
    const ShellMesh m = sphere_with_hole(R, edge, hole, clamp);
    EXPECT_EQ(euler_characteristic(m), 1);
    expect_consistent_tables(m);
    const MeshQuality q = mesh_quality(m);
    const double realised = sphere_hole_radius(edge, hole);
    EXPECT_EQ(realised, std::max(hole, 0.6 * edge));
    int boundary_edges = 0;
    std::vector<int> degree(m.num_vertices(), 0);
    for (size_t e = 0; e < m.edges.size(); ++e) {
      if (m.edge_faces[e][1] >= 0) continue;
      ++boundary_edges;
      for (int v : m.edges[e]) ++degree[v];
    }
    EXPECT_GE(boundary_edges, 5);
    for (int v = 0; v < m.num_vertices(); ++v) {
      const double s = R * from_south(m.rest[v]);  // geodesic distance from the pole [m]
      EXPECT_NEAR(m.rest[v].norm(), R, 1e-12 * R);
      EXPECT_TRUE(degree[v] == 0 || degree[v] == 2);  // one simple loop (with chi = 1)
      if (degree[v] == 2) {
        EXPECT_NEAR(s, realised, 1e-9 * R);
        EXPECT_EQ(m.clamped[v], 1);
      }
      EXPECT_GE(s, realised - 1e-9 * R);
      EXPECT_EQ(m.clamped[v], s <= std::max(hole + clamp, realised) + 1e-9 * R ? 1 : 0);
    }
    for (const auto& f : m.faces) {
      EXPECT_GE(R * from_south(m.rest[f[0]] + m.rest[f[1]] + m.rest[f[2]]), hole);
    }
    char what[64];
    std::snprintf(what, sizeof what, "hole %.2g mm (realised %.3g mm)", hole * 1e3, realised * 1e3);
    print_quality(what, q);
    EXPECT_GT(q.min_angle_deg, 35.0);
    EXPECT_LT(q.max_angle_deg, 100.0);
    EXPECT_LT(q.edge_cv, 0.06);
  }
}

TEST(ShellMesh, HoleRadiusZeroGivesTheClosedSphere) {
  const ShellMesh m = sphere_with_hole(1.0, 0.3, 0.0, 0.1);
  EXPECT_EQ(euler_characteristic(m), 2);
  for (char c : m.clamped) EXPECT_EQ(c, 0);
}

TEST(ShellMesh, FlatSquareTopology) {
  const double L = 2.0;
  const int n = 4;
  const ShellMesh m = flat_square(L, n);
  EXPECT_EQ(m.num_vertices(), (n + 1) * (n + 1));
  EXPECT_EQ(m.num_faces(), 2 * n * n);
  EXPECT_EQ(static_cast<int>(m.edges.size()), 2 * n * (n + 1) + n * n);
  EXPECT_EQ(euler_characteristic(m), 1);
  expect_consistent_tables(m);
  int boundary_edges = 0, clamped = 0;
  for (const auto& ef : m.edge_faces) boundary_edges += ef[1] < 0 ? 1 : 0;
  for (char c : m.clamped) clamped += c;
  EXPECT_EQ(boundary_edges, 4 * n);
  EXPECT_EQ(clamped, 4 * n);
  double area = 0.0;
  for (const auto& f : m.faces) {
    const Vec3 nrm = (m.rest[f[1]] - m.rest[f[0]]).cross(m.rest[f[2]] - m.rest[f[0]]);
    EXPECT_GT(nrm.z(), 0.0);  // counter-clockwise seen from +z
    area += 0.5 * nrm.norm();
  }
  EXPECT_NEAR(area, L * L, 1e-12);
  // Vertex (i, j) at index j (n + 1) + i; the centre is a vertex for even n.
  EXPECT_TRUE(m.rest[(n / 2) * (n + 1) + n / 2].isZero(1e-15));
  EXPECT_TRUE(m.rest[0].isApprox(Vec3(-L / 2, -L / 2, 0)));
  // Alternating diagonals: each interior vertex of even i + j has valence 8 and odd has 4.
  std::vector<int> valence(m.num_vertices(), 0);
  for (const auto& e : m.edges) ++valence[e[0]], ++valence[e[1]];
  for (int j = 1; j < n; ++j) {
    for (int i = 1; i < n; ++i) EXPECT_EQ(valence[j * (n + 1) + i], (i + j) % 2 == 0 ? 8 : 4);
  }
  const MeshQuality q = mesh_quality(m);
  EXPECT_NEAR(q.min_angle_deg, 45.0, 1e-9);
  EXPECT_NEAR(q.max_angle_deg, 90.0, 1e-9);
}

}  // namespace
}  // namespace wirepack
