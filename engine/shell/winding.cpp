#include "engine/shell/winding.hpp"

#include <cmath>
#include <set>
#include <utility>

namespace wirepack {

ShellWinding::ShellWinding(const ShellMesh& mesh) : mesh_(mesh) {
  std::set<std::pair<int, int>> directed;
  for (const auto& f : mesh.faces) {
    for (int k = 0; k < 3; ++k) directed.emplace(f[k], f[(k + 1) % 3]);
  }
  for (const auto& [a, b] : directed) {
    if (!directed.count({b, a})) rim_.push_back({a, b});
  }
}

namespace {

// Signed solid angle of triangle (a, b, c) seen from p (Van Oosterom & Strackee 1983) [sr].
double solid_angle(const Vec3& p, const Vec3& a0, const Vec3& b0, const Vec3& c0) {
  const Vec3 a = a0 - p, b = b0 - p, c = c0 - p;
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double num = a.dot(b.cross(c));
  const double den = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
  return 2.0 * std::atan2(num, den);
}

}  // namespace

double ShellWinding::operator()(const Vec3& p, const Vec3List& x) const {
  double omega = 0.0;
  for (const auto& f : mesh_.faces) omega += solid_angle(p, x[f[0]], x[f[1]], x[f[2]]);
  if (!rim_.empty()) {
    // Close the hole with a fan to the centroid of its rim, traversing each rim edge backwards.
    Vec3 c = Vec3::Zero();
    for (const auto& e : rim_) c += x[e[0]];
    c /= static_cast<double>(rim_.size());
    for (const auto& e : rim_) omega += solid_angle(p, x[e[1]], x[e[0]], c);
  }
  // Faces counter-clockwise seen from outside subtend a positive solid angle from inside.
  return omega / (4.0 * M_PI);
}

}  // namespace wirepack
