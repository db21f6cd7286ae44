// Twin-run comparison of two run files (see twin.hpp).
#include "report/twin.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "analysis/twin.hpp"
#include "sweep/format.hpp"

namespace wirepack::report {

namespace {

// A snapshot's inside wire from the hole (the file keeps it tip first) [m].
std::vector<Eigen::Vector3d> from_hole(const sweep::Snapshot& s) {
  std::vector<Eigen::Vector3d> x;
  x.reserve(s.wire.size());
  for (auto it = s.wire.rbegin(); it != s.wire.rend(); ++it)
    x.emplace_back((*it)[0], (*it)[1], (*it)[2]);
  return x;
}

}  // namespace

TwinComparison compare_twins(const sweep::RunRecord& a, const sweep::RunRecord& b,
                             double threshold_r) {
  if (a.snapshots.empty() || b.snapshots.empty())
    throw sweep::RunFileError("twin comparison: a run has no snapshot");
  const double r = a.config.at("wire").at("radius").get<double>();
  TwinComparison c;
  c.threshold_r = threshold_r;
  const std::size_t n = std::min(a.snapshots.size(), b.snapshots.size());
  for (std::size_t k = 0; k < n; ++k) {
    const sweep::Snapshot& sa = a.snapshots[k];
    const sweep::Snapshot& sb = b.snapshots[k];
    if (std::abs(sa.l - sb.l) > 0.05) break;
    const auto xa = from_hole(sa);
    const auto xb = from_hole(sb);
    const analysis::TwinSeparation d = analysis::twin_separation(xa, xb);
    c.l.push_back(sa.l);
    c.separation_r.push_back(d.max / r);
    c.rms_r.push_back(d.rms / r);
  }
  c.parting_l = analysis::twin_parting_l(c.l, c.separation_r, threshold_r);
  c.parting_rms_l = analysis::twin_parting_l(c.l, c.rms_r, threshold_r);
  return c;
}

std::string twin_csv(const TwinComparison& c) {
  std::ostringstream o;
  o << "l,separation_r,rms_r\n";
  for (std::size_t k = 0; k < c.l.size(); ++k)
    o << sweep::format_number(c.l[k]) << ',' << sweep::format_number(c.separation_r[k]) << ','
      << sweep::format_number(c.rms_r[k]) << '\n';
  return o.str();
}

}  // namespace wirepack::report
