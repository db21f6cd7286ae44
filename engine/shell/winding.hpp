#pragma once
// Inside/outside test against the deformed shell: the generalised winding number of a point
// with respect to the shell's triangles plus a fan that closes the entrance hole. It is 1
// inside and 0 outside for any closed surface, folded or self-touching ones included, so it
// detects a wire that has passed through the shell however distorted the mesh is.
#include <array>
#include <vector>

#include "engine/shell/shell_term.hpp"

namespace wirepack {

class ShellWinding {
 public:
  explicit ShellWinding(const ShellMesh& mesh);
  // Winding number of p with respect to the shell at vertex positions x (nv) [-].
  double operator()(const Vec3& p, const Vec3List& x) const;

 private:
  const ShellMesh& mesh_;
  std::vector<std::array<int, 2>> rim_;  // boundary edges, directed as in their face
};

}  // namespace wirepack
