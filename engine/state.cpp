#include "engine/state.hpp"

#include <algorithm>
#include <limits>

namespace wirepack {

void Forces::reset(const State& s) {
  f.assign(s.x.size(), Vec3::Zero());
  torque.assign(s.theta.size(), 0.0);
  shell_f.assign(s.shell_x.size(), Vec3::Zero());
  const int ne = s.num_edges();
  edge_len.resize(std::max(ne, 0));
  edge_t.resize(std::max(ne, 0));
  double min_rest = std::numeric_limits<double>::infinity();
  for (int j = 0; j < ne; ++j) {
    const Vec3 e = s.x[j + 1] - s.x[j];
    const double len = e.norm();
    edge_len[j] = len;
    edge_t[j] = e / len;  // same rounding as e.normalized()
    min_rest = std::min(min_rest, s.rest_length[j]);
  }
  min_rest_length = min_rest;
  // Turning of the tangent at each interior node: bend, twist and the reference frames use it.
  const int n = s.num_nodes();
  node_cos.assign(std::max(n, 0), 0.0);
  for (int i = 1; i + 1 < n; ++i) node_cos[i] = edge_t[i - 1].dot(edge_t[i]);
  if (s.has_twist()) {
    node_cross.assign(std::max(n, 0), Vec3::Zero());
    for (int i = 1; i + 1 < n; ++i) node_cross[i] = edge_t[i - 1].cross(edge_t[i]);
  } else {
    node_cross.clear();
  }
}

}  // namespace wirepack
