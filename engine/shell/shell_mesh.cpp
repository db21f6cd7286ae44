#include <algorithm>
#include <stdexcept>
#include <string>
#include <tuple>

#include "engine/shell/shell_term.hpp"

namespace wirepack {

// Edges are numbered in lexicographic order of (v0, v1), v0 < v1. edge_faces[e][0] is the face
// that traverses the edge as v0 -> v1 (counter-clockwise order) and [1] the one that traverses
// it as v1 -> v0; on a boundary edge the only face is in [0] and [1] is -1. Throws on an edge
// with more than two faces or with two faces of the same direction (inconsistent orientation).
void ShellMesh::build_topology() {
  struct HalfEdge {
    int a, b;      // sorted vertex pair
    int face, k;   // face and the local index of the opposite vertex
    bool forward;  // the face traverses a -> b
  };
  std::vector<HalfEdge> he;
  he.reserve(3 * faces.size());
  for (int f = 0; f < num_faces(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int p = faces[f][(k + 1) % 3], q = faces[f][(k + 2) % 3];
      he.push_back({std::min(p, q), std::max(p, q), f, k, p < q});
    }
  }
  std::sort(he.begin(), he.end(), [](const HalfEdge& l, const HalfEdge& r) {
    return std::tie(l.a, l.b, l.face) < std::tie(r.a, r.b, r.face);
  });
  edges.clear();
  edge_faces.clear();
  face_edges.assign(faces.size(), {-1, -1, -1});
  for (size_t i = 0; i < he.size();) {
    size_t j = i;
    while (j < he.size() && he[j].a == he[i].a && he[j].b == he[i].b) ++j;
    const std::string where =
        "ShellMesh: edge (" + std::to_string(he[i].a) + ", " + std::to_string(he[i].b) + ")";
    if (j - i > 2) throw std::invalid_argument(where + " has more than two faces");
    const int e = static_cast<int>(edges.size());
    edges.push_back({he[i].a, he[i].b});
    std::array<int, 2> ef{-1, -1};
    if (j - i == 1) {
      ef[0] = he[i].face;
    } else {
      if (he[i].forward == he[i + 1].forward) {
        throw std::invalid_argument(where + ": inconsistent face orientation");
      }
      ef[0] = he[i].forward ? he[i].face : he[i + 1].face;
      ef[1] = he[i].forward ? he[i + 1].face : he[i].face;
    }
    edge_faces.push_back(ef);
    for (size_t m = i; m < j; ++m) face_edges[he[m].face][he[m].k] = e;
    i = j;
  }
}

}  // namespace wirepack
