#include "sweep/runfile/shell_fields.hpp"

#include <cmath>
#include <stdexcept>

namespace wirepack::sweep {

namespace {

double triangle_area(const Points& x, const std::array<int, 3>& t) {
  const auto& a = x[static_cast<std::size_t>(t[0])];
  const auto& b = x[static_cast<std::size_t>(t[1])];
  const auto& c = x[static_cast<std::size_t>(t[2])];
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                       u[0] * v[1] - u[1] * v[0]};
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

void check_indices(const Points& x, const Triangles& faces) {
  for (const auto& t : faces)
    for (int v : t)
      if (v < 0 || static_cast<std::size_t>(v) >= x.size())
        throw std::invalid_argument("triangle vertex index out of range");
}

}  // namespace

std::vector<double> face_area_stretch(const Points& rest, const Points& current,
                                      const Triangles& faces) {
  if (rest.size() != current.size())
    throw std::invalid_argument("rest and current shells differ in vertex count");
  check_indices(rest, faces);
  std::vector<double> out;
  out.reserve(faces.size());
  for (const auto& t : faces) out.push_back(triangle_area(current, t) / triangle_area(rest, t));
  return out;
}

}  // namespace wirepack::sweep
