#include "engine/shell/mesh_builders.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>

namespace wirepack {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Icosahedron of unit circumradius with vertices at the poles: 0 = north, 1..5 upper ring at
// z = 1/sqrt(5) and longitudes 72 k deg, 6..10 lower ring at longitudes 36 + 72 k deg,
// 11 = south. Faces counter-clockwise seen from outside.
void icosahedron(Vec3List& v, std::vector<std::array<int, 3>>& f) {
  const double z = 1.0 / std::sqrt(5.0), r = 2.0 / std::sqrt(5.0);
  v.assign(12, Vec3::Zero());
  v[0] = Vec3(0, 0, 1);
  v[11] = Vec3(0, 0, -1);
  for (int k = 0; k < 5; ++k) {
    const double pu = 2 * kPi * k / 5, pl = pu + kPi / 5;
    v[1 + k] = Vec3(r * std::cos(pu), r * std::sin(pu), z);
    v[6 + k] = Vec3(r * std::cos(pl), r * std::sin(pl), -z);
  }
  f.clear();
  for (int k = 0; k < 5; ++k) {
    const int u0 = 1 + k, u1 = 1 + (k + 1) % 5, l0 = 6 + k, l1 = 6 + (k + 1) % 5;
    f.push_back({0, u0, u1});
    f.push_back({u0, l0, u1});
    f.push_back({u1, l0, l1});
    f.push_back({11, l1, l0});
  }
}

// Vertex neighbours (one-ring) from the edge list.
std::vector<std::vector<int>> neighbours(const ShellMesh& m) {
  std::vector<std::vector<int>> nb(m.num_vertices());
  for (const auto& e : m.edges) {
    nb[e[0]].push_back(e[1]);
    nb[e[1]].push_back(e[0]);
  }
  return nb;
}

// Geodesic angle from the south pole of a point on the sphere [rad].
double polar_from_south(const Vec3& x) {
  return std::atan2(std::hypot(x.x(), x.y()), -x.z());
}

// Point at geodesic angle theta from the south pole on the meridian of x, radius R.
Vec3 on_circle(const Vec3& x, double R, double theta) {
  const double phi = std::atan2(x.y(), x.x());
  return Vec3(R * std::sin(theta) * std::cos(phi), R * std::sin(theta) * std::sin(phi),
              -R * std::cos(theta));
}

// Mean edge length [m].
double mean_edge(const ShellMesh& m) {
  double s = 0.0;
  for (const auto& e : m.edges) s += (m.rest[e[1]] - m.rest[e[0]]).norm();
  return s / static_cast<double>(m.edges.size());
}

// Spring relaxation on the sphere of radius R: every edge is a spring of rest length L0 (the
// current mean edge), each vertex moves by 1/2 of the mean spring force per neighbour and is
// projected back onto the sphere (Jacobi sweeps). Vertices with circle[i] = 1 slide on the
// circle of geodesic angle theta_c around the south pole instead. Stops after max_iter sweeps
// or when no vertex moves by more than tol * L0.
void relax_on_sphere(ShellMesh& m, double R, const std::vector<char>& circle, double theta_c,
                     int max_iter, double tol) {
  const auto nb = neighbours(m);
  const int nv = m.num_vertices();
  Vec3List next(nv);
  for (int it = 0; it < max_iter; ++it) {
    const double L0 = mean_edge(m);
    double moved = 0.0;
    for (int i = 0; i < nv; ++i) {
      Vec3 d = Vec3::Zero();
      for (int j : nb[i]) {
        const Vec3 e = m.rest[j] - m.rest[i];
        const double len = e.norm();
        d += (len - L0) / len * e;
      }
      Vec3 y = m.rest[i] + 0.5 / static_cast<double>(nb[i].size()) * d;
      y = circle[i] ? on_circle(y, R, theta_c) : Vec3(R * y.normalized());
      moved = std::max(moved, (y - m.rest[i]).norm());
      next[i] = y;
    }
    m.rest.swap(next);
    if (moved < tol * L0) break;
  }
}

// Keeps only the faces with keep[f] = 1 and drops the vertices no face uses.
void keep_faces(ShellMesh& m, const std::vector<char>& keep) {
  std::vector<std::array<int, 3>> faces;
  std::vector<int> id(m.num_vertices(), -1);
  Vec3List rest;
  for (int f = 0; f < m.num_faces(); ++f) {
    if (!keep[f]) continue;
    std::array<int, 3> g;
    for (int k = 0; k < 3; ++k) {
      int& v = id[m.faces[f][k]];
      if (v < 0) {
        v = static_cast<int>(rest.size());
        rest.push_back(m.rest[m.faces[f][k]]);
      }
      g[k] = v;
    }
    faces.push_back(g);
  }
  m.rest = std::move(rest);
  m.faces = std::move(faces);
  m.clamped.assign(m.rest.size(), 0);
  m.build_topology();
}

}  // namespace

int sphere_frequency(double R, double target_edge) {
  if (!(R > 0) || !(target_edge > 0)) throw std::invalid_argument("sphere: R, edge must be > 0");
  // 20 n^2 (sqrt(3)/4) a^2 = 4 pi R^2
  const double n = std::sqrt(4 * kPi * R * R / (20 * std::sqrt(3.0) / 4)) / target_edge;
  return std::max(1, static_cast<int>(std::lround(n)));
}

ShellMesh geodesic_sphere(double R, double target_edge) {
  const int n = sphere_frequency(R, target_edge);
  Vec3List iv;
  std::vector<std::array<int, 3>> ifaces;
  icosahedron(iv, ifaces);
  // Points P(i, j) = A + (i (B - A) + j (C - A)) / n of each face; points on shared edges
  // and corners are merged by their integer coordinates in the icosahedron's vertex basis
  // (a point on an edge is a combination of its two end vertices only).
  ShellMesh m;
  std::map<std::tuple<int, int, int, int, int, int>, int> index;
  auto vertex = [&](const std::array<int, 3>& abc, int i, int j) {
    // Barycentric weights (n - i - j, i, j) on (A, B, C); key: sorted (vertex, weight) pairs
    // with zero weights dropped.
    std::array<std::pair<int, int>, 3> w{
        {{abc[0], n - i - j}, {abc[1], i}, {abc[2], j}}};
    for (auto& p : w) {
      if (p.second == 0) p.first = -1;
    }
    std::sort(w.begin(), w.end());
    const auto key = std::make_tuple(w[0].first, w[0].second, w[1].first, w[1].second,
                                     w[2].first, w[2].second);
    auto it = index.find(key);
    if (it != index.end()) return it->second;
    const Vec3 p = (n - i - j) * iv[abc[0]] + i * iv[abc[1]] + j * iv[abc[2]];
    const int id = static_cast<int>(m.rest.size());
    m.rest.push_back(R * p.normalized());
    index.emplace(key, id);
    return id;
  };
  for (const auto& abc : ifaces) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i + j < n; ++i) {
        const int p00 = vertex(abc, i, j), p10 = vertex(abc, i + 1, j),
                  p01 = vertex(abc, i, j + 1);
        m.faces.push_back({p00, p10, p01});
        if (i + j + 1 < n) m.faces.push_back({p10, vertex(abc, i + 1, j + 1), p01});
      }
    }
  }
  m.clamped.assign(m.rest.size(), 0);
  m.build_topology();
  relax_on_sphere(m, R, std::vector<char>(m.rest.size(), 0), 0.0, 20 * n * n + 100, 1e-9);
  return m;
}

ShellMesh sphere_with_hole(double R, double target_edge, double hole_radius,
                           double clamp_width) {
  ShellMesh m = geodesic_sphere(R, target_edge);
  if (!(hole_radius > 0)) return m;
  const double theta_c = (hole_radius + clamp_width) / R;
  // The boundary circle is not drawn tighter than half an edge (pentagon of ~0.6 edges).
  const double theta_h = std::max(hole_radius, 0.5 * mean_edge(m)) / R;
  if (!(theta_h < kPi / 2)) throw std::invalid_argument("sphere_with_hole: hole too large");
  // Faces whose centroid is in the cap, and always those at the pole vertex.
  std::vector<char> keep(m.num_faces(), 1);
  for (int f = 0; f < m.num_faces(); ++f) {
    Vec3 c = Vec3::Zero();
    double at_pole = 0.0;
    for (int v : m.faces[f]) {
      c += m.rest[v];
      at_pole = std::max(at_pole, -m.rest[v].z() / R);
    }
    if (polar_from_south(c) < theta_h || at_pole > 1 - 1e-12) keep[f] = 0;
  }
  keep_faces(m, keep);
  // Ears (faces with two edges on the hole) would fold over when their tip is moved onto the
  // circle: remove them too, until there are none.
  for (bool again = true; again;) {
    again = false;
    keep.assign(m.num_faces(), 1);
    for (int f = 0; f < m.num_faces(); ++f) {
      int on_boundary = 0;
      for (int e : m.face_edges[f]) on_boundary += m.edge_faces[e][1] < 0 ? 1 : 0;
      if (on_boundary >= 2) keep[f] = 0, again = true;
    }
    if (again) keep_faces(m, keep);
  }
  // The hole's boundary must be one simple loop (a disc was cut out).
  std::vector<int> boundary_degree(m.num_vertices(), 0);
  int boundary_edges = 0;
  for (size_t e = 0; e < m.edges.size(); ++e) {
    if (m.edge_faces[e][1] >= 0) continue;
    ++boundary_edges;
    ++boundary_degree[m.edges[e][0]];
    ++boundary_degree[m.edges[e][1]];
  }
  std::vector<char> on_hole(m.num_vertices(), 0);
  int boundary_vertices = 0;
  for (int v = 0; v < m.num_vertices(); ++v) {
    if (boundary_degree[v] == 0) continue;
    if (boundary_degree[v] != 2) throw std::runtime_error("sphere_with_hole: pinched hole");
    on_hole[v] = 1;
    ++boundary_vertices;
  }
  if (boundary_vertices != boundary_edges) {
    throw std::runtime_error("sphere_with_hole: hole boundary is not one loop");
  }
  // Boundary onto the circle of geodesic radius hole_radius, then relax again.
  for (int v = 0; v < m.num_vertices(); ++v) {
    if (on_hole[v]) m.rest[v] = on_circle(m.rest[v], R, theta_h);
  }
  const int n = sphere_frequency(R, target_edge);
  relax_on_sphere(m, R, on_hole, theta_h, 20 * n * n + 100, 1e-9);
  const double tol = 1e-9;
  for (int v = 0; v < m.num_vertices(); ++v) {
    m.clamped[v] = polar_from_south(m.rest[v]) <= theta_c + tol ? 1 : 0;
  }
  return m;
}

ShellMesh flat_square(double L, int n) {
  if (!(L > 0) || n < 1) throw std::invalid_argument("flat_square: L > 0, n >= 1");
  ShellMesh m;
  const double h = L / n;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      m.rest.emplace_back(-L / 2 + i * h, -L / 2 + j * h, 0.0);
      m.clamped.push_back(i == 0 || j == 0 || i == n || j == n ? 1 : 0);
    }
  }
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if ((i + j) % 2 == 0) {  // diagonal a-c
        m.faces.push_back({a, b, c});
        m.faces.push_back({a, c, d});
      } else {  // diagonal b-d
        m.faces.push_back({a, b, d});
        m.faces.push_back({b, c, d});
      }
    }
  }
  m.build_topology();
  return m;
}

MeshQuality mesh_quality(const ShellMesh& m) {
  MeshQuality q;
  q.vertices = m.num_vertices();
  q.faces = m.num_faces();
  q.min_angle_deg = 180.0;
  q.max_angle_deg = 0.0;
  q.area_min = HUGE_VAL;
  for (const auto& f : m.faces) {
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = m.rest[f[(k + 1) % 3]] - m.rest[f[k]];
      const Vec3 b = m.rest[f[(k + 2) % 3]] - m.rest[f[k]];
      const double ang = std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / kPi;
      q.min_angle_deg = std::min(q.min_angle_deg, ang);
      q.max_angle_deg = std::max(q.max_angle_deg, ang);
    }
    const double area =
        0.5 * (m.rest[f[1]] - m.rest[f[0]]).cross(m.rest[f[2]] - m.rest[f[0]]).norm();
    q.area_min = std::min(q.area_min, area);
    q.area_max = std::max(q.area_max, area);
  }
  double s = 0.0, s2 = 0.0;
  q.edge_min = HUGE_VAL;
  for (const auto& e : m.edges) {
    const double len = (m.rest[e[1]] - m.rest[e[0]]).norm();
    s += len;
    s2 += len * len;
    q.edge_min = std::min(q.edge_min, len);
    q.edge_max = std::max(q.edge_max, len);
  }
  const double ne = static_cast<double>(m.edges.size());
  q.edge_mean = s / ne;
  q.edge_cv = std::sqrt(std::max(0.0, s2 / ne - q.edge_mean * q.edge_mean)) / q.edge_mean;
  return q;
}

}  // namespace wirepack
