#pragma once
// The elastic shell (Engine III): a triangulated Kirchhoff-Love shell. Each shell energy
// (membrane, bending) is a ShellTerm over the vertex positions; the mesh (rest shape,
// topology, clamped vertices) is immutable and shared read-only.
#include <array>
#include <string>
#include <vector>

#include "engine/params.hpp"
#include "engine/term_type.hpp"
#include "engine/types.hpp"

namespace wirepack {

// Triangle mesh of the shell's mid-surface in its rest (stress-free) configuration.
struct ShellMesh {
  Vec3List rest;                          // vertex positions (nv) [m]
  std::vector<std::array<int, 3>> faces;  // counter-clockwise seen from outside (nf)
  std::vector<char> clamped;              // 1 for vertices held fixed (nv)
  // Unique edges (ne): vertex pair (v0 < v1) and the two adjacent faces (-1 on a boundary).
  std::vector<std::array<int, 2>> edges;
  std::vector<std::array<int, 2>> edge_faces;
  // For each face, its three edges, edge k opposite to vertex k (nf x 3).
  std::vector<std::array<int, 3>> face_edges;

  int num_vertices() const { return static_cast<int>(rest.size()); }
  int num_faces() const { return static_cast<int>(faces.size()); }
  // Fills edges, edge_faces and face_edges from faces.
  void build_topology();
};

struct ShellMaterial {
  ShellMaterialLaw law = ShellMaterialLaw::Linear;      // the membrane's (membrane.hpp)
  double E = 0;                                         // Young's modulus E_s [Pa]
  double nu = 0;                                        // Poisson ratio nu_s [-]
  double t = 0;                                         // thickness [m]
  double M() const { return E * t / (1.0 - nu * nu); }  // membrane rigidity (paper)
  double B() const { return M() * t * t / 12.0; }       // bending rigidity (paper)
};

class ShellTerm {
 public:
  virtual ~ShellTerm() = default;
  virtual std::string name() const = 0;
  virtual TermType type() const = 0;
  // Adds -dU/dx for every vertex into f (nv) and returns U [J].
  virtual double accumulate(const Vec3List& x, Vec3List& f) = 0;
  virtual double energy(const Vec3List& x) = 0;
  // Square of the highest angular frequency at lumped vertex mass m [kg] [1/s^2].
  virtual double omega_max_sq(double vertex_mass) const = 0;
};

}  // namespace wirepack
