#pragma once
// Builders of shell meshes: the paper's sphere with a clamped hole at the south pole (an
// icosahedral geodesic mesh, spring-relaxed to near-uniform triangles), a closed sphere, a
// flat clamped square for plate tests; and mesh quality figures (docs/design.md §2.4, issue 4).
#include "engine/shell/shell_term.hpp"

namespace wirepack {

// Closed sphere of radius R [m] centred at the origin, edges ~ target_edge [m]: every face of
// an icosahedron with a vertex at each pole (0, 0, +-R) is split into n^2 triangles
// (frequency n = sphere_frequency(R, target_edge)), the vertices are projected to the sphere
// and then relaxed as a net of equal, slightly compressed springs on the sphere (the 12
// five-valent vertices stay put by symmetry). Reached for n = 12 .. 48: angles 52.9 .. 72 deg,
// edge cv 0.042, max/min edge 1.21 .. 1.26, max/min area 1.25 .. 1.35 (unrelaxed: 1.41,
// 1.8 .. 1.9). Nothing is clamped; topology is built.
ShellMesh geodesic_sphere(double R, double target_edge);

// The frequency n used by geodesic_sphere: the n whose 20 n^2 equilateral triangles of edge
// target_edge have the area of the sphere, n >= 1. The mesh has 10 n^2 + 2 vertices.
int sphere_frequency(double R, double target_edge);

// geodesic_sphere with a hole of radius hole_radius [m] (geodesic, on the sphere) around the
// south pole (0, 0, -R): the faces whose centroid lies in a cap around the pole are removed
// (always the five faces at the pole vertex, then any face with two edges on the hole), the
// hole's boundary vertices are moved along their meridians onto the circle of geodesic
// radius r_h = max(hole_radius, 0.6 target_edge) (see sphere_hole_radius) and the vertices
// within 3 edges of it are relaxed again, the boundary sliding on that circle. The cap's
// radius is chosen among hole_radius +- 0.5 edge for the best smallest angle near the hole
// (it sets how many vertices the circle gets). Vertices within geodesic distance
// max(hole_radius + clamp_width, r_h) of the pole are clamped. At R = 10 mm, edge 1 mm and
// holes of 0.1 .. 3.3 mm: angles >= 40.8 deg. hole_radius <= 0: the closed sphere, unclamped.
ShellMesh sphere_with_hole(double R, double target_edge, double hole_radius, double clamp_width);

// Geodesic radius r_h [m] of the hole that sphere_with_hole cuts (0 for hole_radius <= 0).
double sphere_hole_radius(double target_edge, double hole_radius);

// Square [-L/2, L/2]^2 in the plane z = 0 [m], n x n cells, each split into two triangles
// with diagonals alternating in a checkerboard pattern; normal +z (counter-clockwise seen from
// +z); the boundary vertices are clamped. Vertex (i, j) at x = -L/2 + i L/n, y = -L/2 + j L/n
// has index j (n + 1) + i.
ShellMesh flat_square(double L, int n);

struct MeshQuality {
  double min_angle_deg = 0, max_angle_deg = 0;       // extreme interior angles of the faces [deg]
  double edge_min = 0, edge_max = 0, edge_mean = 0;  // edge lengths [m]
  double edge_cv = 0;  // coefficient of variation of the edge lengths (std / mean) [-]
  double area_min = 0, area_max = 0;  // face areas [m^2]
  int vertices = 0, faces = 0;
};

// Quality of the rest mesh (needs the topology, i.e. build_topology() done).
MeshQuality mesh_quality(const ShellMesh& mesh);

}  // namespace wirepack
