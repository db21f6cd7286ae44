// Twin-run separation modulo the rotation about the feed axis (see twin.hpp).
#include "analysis/twin.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wirepack::analysis {

TwinSeparation twin_separation(std::span<const Eigen::Vector3d> a,
                               std::span<const Eigen::Vector3d> b) {
  const std::size_t n = std::min(a.size(), b.size());
  if (n == 0) return {};
  // Best rotation about z: maximise sum_i b_i . R(phi) a_i = C cos(phi) + S sin(phi).
  double c = 0, s = 0;
  for (std::size_t i = 0; i < n; ++i) {
    c += a[i].x() * b[i].x() + a[i].y() * b[i].y();
    s += a[i].x() * b[i].y() - a[i].y() * b[i].x();
  }
  const double phi = std::atan2(s, c);
  const double cp = std::cos(phi), sp = std::sin(phi);
  TwinSeparation out;
  double sum2 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d ra(cp * a[i].x() - sp * a[i].y(), sp * a[i].x() + cp * a[i].y(),
                             a[i].z());
    const double d2 = (ra - b[i]).squaredNorm();
    out.max = std::max(out.max, std::sqrt(d2));
    sum2 += d2;
  }
  out.rms = std::sqrt(sum2 / static_cast<double>(n));
  return out;
}

double twin_parting_l(std::span<const double> l, std::span<const double> separation,
                      double threshold) {
  const std::size_t n = std::min(l.size(), separation.size());
  for (std::size_t i = 0; i < n; ++i)
    if (separation[i] > threshold) return l[i];
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace wirepack::analysis
