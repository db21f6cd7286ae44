#pragma once
// Builders of shell meshes: the paper's sphere with a clamped hole at the south pole (an
// icosahedral geodesic mesh, spring-relaxed to near-uniform triangles), a closed sphere, a
// flat clamped square for plate tests; and mesh quality figures (DESIGN §3, issue 4).
#include "engine/shell/shell_term.hpp"

namespace wirepack {

// Closed sphere of radius R [m] centred at the origin, edges ~ target_edge [m]: every face of
// an icosahedron with a vertex at each pole (0, 0, +-R) is split into n^2 triangles
// (frequency n = sphere_frequency(R, target_edge)), the vertices are projected to the sphere
// and then relaxed as a net of equal springs on the sphere (lengths equalised; the 12
// five-valent vertices stay put by symmetry). Nothing is clamped; topology is built.
ShellMesh geodesic_sphere(double R, double target_edge);

// The frequency n used by geodesic_sphere: the n whose 20 n^2 equilateral triangles of edge
// target_edge have the area of the sphere, n >= 1. The mesh has 10 n^2 + 2 vertices.
int sphere_frequency(double R, double target_edge);

// geodesic_sphere with a hole of radius hole_radius [m] (geodesic, on the sphere) around the
// south pole (0, 0, -R): the faces whose centroid lies in the cap are removed (at least the
// five faces at the pole, so the hole is never smaller than ~ one edge when hole_radius is
// tiny), the hole's boundary vertices are moved along their meridians onto the circle of
// geodesic radius hole_radius and the rest is relaxed again with the boundary sliding on that
// circle. Vertices within geodesic distance hole_radius + clamp_width of the pole are clamped.
// hole_radius <= 0 gives the closed sphere with nothing clamped.
ShellMesh sphere_with_hole(double R, double target_edge, double hole_radius, double clamp_width);

// Square [-L/2, L/2]^2 in the plane z = 0 [m], n x n cells, each split into two triangles
// with diagonals alternating in a checkerboard pattern; normal +z (counter-clockwise seen from
// +z); the boundary vertices are clamped. Vertex (i, j) at x = -L/2 + i L/n, y = -L/2 + j L/n
// has index j (n + 1) + i.
ShellMesh flat_square(double L, int n);

struct MeshQuality {
  double min_angle_deg = 0, max_angle_deg = 0;  // extreme interior angles of the faces [deg]
  double edge_min = 0, edge_max = 0, edge_mean = 0;  // edge lengths [m]
  double edge_cv = 0;  // coefficient of variation of the edge lengths (std / mean) [-]
  double area_min = 0, area_max = 0;  // face areas [m^2]
  int vertices = 0, faces = 0;
};

// Quality of the rest mesh (needs the topology, i.e. build_topology() done).
MeshQuality mesh_quality(const ShellMesh& mesh);

}  // namespace wirepack
