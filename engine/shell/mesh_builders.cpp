#include "engine/shell/mesh_builders.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>

namespace wirepack {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Rest length of the relaxation springs over the mean edge: slightly above 1 the net is under
// a little pressure, which evens out the areas. Max/min face area at n = 12 / 48: 1.25 / 1.34
// (1.34 / 1.49 at 1.0; 1.80 / ~2 unrelaxed). At 1.15 the net folds for n = 48, so
// geodesic_sphere checks the angles and falls back to 1.0 should that ever happen.
constexpr double kSpringLength = 1.1;
// Sweeps of the global relaxation: the edge spread settles within a few hundred; full
// convergence would take ~20 n^2 sweeps (18 s at n = 48; 2 s with this cap).
constexpr int kRelaxSweeps = 2000;
// The hole's boundary circle is not drawn tighter than this many target edges.
constexpr double kMinHoleRadius = 0.6;

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

// Spring relaxation on the sphere of radius R: every edge is a spring of rest length L0 [m],
// each vertex moves by 1/2 of the mean spring force per neighbour and is projected back onto
// the sphere (Jacobi sweeps). mode[i]: 0 free on the sphere, 1 sliding on the circle of
// geodesic angle theta_c around the south pole, 2 fixed. Stops after max_iter sweeps or when
// no vertex moves by more than tol * L0.
void relax_on_sphere(ShellMesh& m, double R, double L0, const std::vector<char>& mode,
                     double theta_c, int max_iter, double tol) {
  const auto nb = neighbours(m);
  const int nv = m.num_vertices();
  Vec3List next = m.rest;
  for (int it = 0; it < max_iter; ++it) {
    double moved = 0.0;
    for (int i = 0; i < nv; ++i) {
      if (mode[i] == 2) continue;
      Vec3 d = Vec3::Zero();
      for (int j : nb[i]) {
        const Vec3 e = m.rest[j] - m.rest[i];
        const double len = e.norm();
        d += (len - L0) / len * e;
      }
      Vec3 y = m.rest[i] + 0.5 / static_cast<double>(nb[i].size()) * d;
      y = mode[i] == 1 ? on_circle(y, R, theta_c) : Vec3(R * y.normalized());
      moved = std::max(moved, (y - m.rest[i]).norm());
      next[i] = y;
    }
    m.rest.swap(next);
    next = m.rest;
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
    std::array<std::pair<int, int>, 3> w{{{abc[0], n - i - j}, {abc[1], i}, {abc[2], j}}};
    for (auto& p : w) {
      if (p.second == 0) p.first = -1;
    }
    std::sort(w.begin(), w.end());
    const auto key =
        std::make_tuple(w[0].first, w[0].second, w[1].first, w[1].second, w[2].first, w[2].second);
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
        const int p00 = vertex(abc, i, j), p10 = vertex(abc, i + 1, j), p01 = vertex(abc, i, j + 1);
        m.faces.push_back({p00, p10, p01});
        if (i + j + 1 < n) m.faces.push_back({p10, vertex(abc, i + 1, j + 1), p01});
      }
    }
  }
  m.clamped.assign(m.rest.size(), 0);
  m.build_topology();
  const ShellMesh projected = m;
  const std::vector<char> free(m.rest.size(), 0);
  relax_on_sphere(m, R, kSpringLength * mean_edge(m), free, 0.0, kRelaxSweeps, 1e-6);
  // The projected mesh has angles >= 54 deg; a relaxed one far below that has folded.
  if (mesh_quality(m).min_angle_deg < 45.0) {
    m = projected;
    relax_on_sphere(m, R, mean_edge(m), free, 0.0, kRelaxSweeps, 1e-6);
  }
  return m;
}

namespace {

// Cuts the hole of sphere_with_hole with removal radius rho [m] (faces whose centroid is
// within geodesic distance rho of the south pole, and the five at the pole), moves the
// boundary onto the circle of geodesic angle theta_h and relaxes the vertices within
// theta_h + 3 edges with springs of length L0. Returns false where the cut is not a disc.
bool cut_hole(ShellMesh& m, double R, double rho, double theta_h, double L0) {
  std::vector<char> keep(m.num_faces(), 1);
  for (int f = 0; f < m.num_faces(); ++f) {
    Vec3 c = Vec3::Zero();
    double at_pole = 0.0;
    for (int v : m.faces[f]) {
      c += m.rest[v];
      at_pole = std::max(at_pole, -m.rest[v].z() / R);
    }
    if (polar_from_south(c) * R < rho || at_pole > 1 - 1e-12) keep[f] = 0;
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
  // A disc was cut out: Euler characteristic 1 and every boundary vertex on two boundary edges
  // (one simple loop).
  std::vector<int> degree(m.num_vertices(), 0);
  for (size_t e = 0; e < m.edges.size(); ++e) {
    if (m.edge_faces[e][1] >= 0) continue;
    ++degree[m.edges[e][0]];
    ++degree[m.edges[e][1]];
  }
  if (m.num_vertices() - static_cast<int>(m.edges.size()) + m.num_faces() != 1) return false;
  std::vector<char> mode(m.num_vertices(), 2);
  for (int v = 0; v < m.num_vertices(); ++v) {
    if (degree[v] != 0 && degree[v] != 2) return false;
    if (degree[v] == 2) {
      mode[v] = 1;
      m.rest[v] = on_circle(m.rest[v], R, theta_h);
    } else if (polar_from_south(m.rest[v]) < theta_h + 3 * L0 / R) {
      mode[v] = 0;
    }
  }
  relax_on_sphere(m, R, L0, mode, theta_h, 2000, 1e-9);
  return true;
}

// Smallest interior angle of the faces with a vertex within geodesic angle theta of the south
// pole [rad].
double min_angle_near_pole(const ShellMesh& m, double theta) {
  double worst = kPi;
  for (const auto& f : m.faces) {
    bool near = false;
    for (int v : f) near = near || polar_from_south(m.rest[v]) < theta;
    if (!near) continue;
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = m.rest[f[(k + 1) % 3]] - m.rest[f[k]];
      const Vec3 b = m.rest[f[(k + 2) % 3]] - m.rest[f[k]];
      worst = std::min(worst, std::atan2(a.cross(b).norm(), a.dot(b)));
    }
  }
  return worst;
}

}  // namespace

double sphere_hole_radius(double target_edge, double hole_radius) {
  return hole_radius > 0 ? std::max(hole_radius, kMinHoleRadius * target_edge) : 0.0;
}

ShellMesh sphere_with_hole(double R, double target_edge, double hole_radius, double clamp_width) {
  ShellMesh sphere = geodesic_sphere(R, target_edge);
  if (!(hole_radius > 0)) return sphere;
  const double edge = mean_edge(sphere);
  const double theta_h = sphere_hole_radius(target_edge, hole_radius) / R;
  if (!(theta_h < kPi / 2)) throw std::invalid_argument("sphere_with_hole: hole too large");
  // The faces removed decide how many vertices the boundary circle gets (ideally its length
  // over one edge): try removal radii around the hole radius and keep the cut whose faces near
  // the hole have the largest smallest angle (ties: the removal radius closest to the hole's).
  ShellMesh best;
  double best_angle = -1.0;
  for (int k : {0, -1, 1, -2, 2, -3, 3, -4, 4, -5, 5}) {
    const double rho = theta_h * R + 0.1 * k * edge;
    if (rho < 0) continue;
    ShellMesh m = sphere;
    if (!cut_hole(m, R, rho, theta_h, kSpringLength * edge)) continue;
    const double angle = min_angle_near_pole(m, theta_h + 4 * edge / R);
    if (angle > best_angle + 1e-3) best = std::move(m), best_angle = angle;
  }
  if (best_angle < 0) throw std::runtime_error("sphere_with_hole: no clean cut found");
  const double theta_c = (hole_radius + clamp_width) / R, tol = 1e-9;
  for (int v = 0; v < best.num_vertices(); ++v) {
    best.clamped[v] = polar_from_south(best.rest[v]) <= std::max(theta_c, theta_h) + tol ? 1 : 0;
  }
  return best;
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
