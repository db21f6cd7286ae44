#pragma once
// Fields of the shell recorded in the run file's snapshots (docs/design.md §4.3).
#include <array>
#include <vector>

namespace wirepack::sweep {

using Points = std::vector<std::array<double, 3>>;
using Triangles = std::vector<std::array<int, 3>>;

// Area stretch per face, current area / rest area (f) [-]: 1 at rest, s^2 for a shell scaled
// by s. `rest` and `current` are the vertices (m x 3) [m] of the same mesh.
std::vector<double> face_area_stretch(const Points& rest, const Points& current,
                                      const Triangles& faces);

}  // namespace wirepack::sweep
