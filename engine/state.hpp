#pragma once
// Mutable state of one run: the discrete elastic rod (Bergou et al. 2008/2010 style) and,
// for an elastic shell (Engine III), the shell's vertices.
// Nodes are stored tip first: node 0 is the free tip, the highest indices are the kinematic
// guide outside the hole. Edge j joins nodes j and j+1.
#include <vector>

#include "engine/types.hpp"

namespace wirepack {

struct State {
  Vec3List x;                       // node positions (n) [m]
  Vec3List v;                       // node velocities (n) [m/s]
  std::vector<double> rest_length;  // edge rest lengths (n-1) [m]
  int n_free = 0;                   // nodes [0, n_free) are dynamic, the rest are the guide

  // Twist degrees of freedom (empty when the scene has no twist effect).
  std::vector<double> theta;      // material angle of edge j about its reference frame (n-1) [rad]
  std::vector<double> omega;      // d theta / dt (n-1) [rad/s]
  Vec3List ref1;                  // reference director of edge j, unit, normal to the edge (n-1)
  Vec3List ref_tangent;           // unit tangent at which ref1 was last transported (n-1)
  std::vector<double> ref_twist;  // reference twist at node i (n; 0 at the two ends) [rad]

  // Elastic shell (empty for a rigid sphere): mid-surface vertices of the mesh.
  Vec3List shell_x;  // vertex positions (nv) [m]
  Vec3List shell_v;  // vertex velocities (nv) [m/s]

  int num_nodes() const { return static_cast<int>(x.size()); }
  int num_edges() const { return static_cast<int>(x.size()) - 1; }
  bool has_twist() const { return !theta.empty(); }
  // Edge j is dynamic (its theta integrates) iff both its nodes are dynamic.
  bool edge_free(int j) const { return j + 1 < n_free; }
};

// Generalised forces: -dU/dx per node (n) [N], -dU/dtheta per edge (n-1) [N m] and -dU/dx
// per shell vertex (nv) [N]; plus the edge geometry of the state they are evaluated at, computed
// once by reset() and read by every rod term, the damping and the reference frames (each used
// to recompute the same square roots and divisions).
struct Forces {
  Vec3List f;
  std::vector<double> torque;
  Vec3List shell_f;
  std::vector<double> edge_len;  // |x_{j+1} - x_j| (n-1) [m]
  Vec3List edge_t;               // unit tangent (x_{j+1} - x_j) / edge_len (n-1)
  std::vector<double> node_cos;  // t_{i-1} . t_i at interior node i (n; 0 at the ends)
  Vec3List node_cross;           // t_{i-1} x t_i (n; zero at the ends; only with twist DOFs)
  double min_rest_length = 0;    // smallest rest length (inf for a single node) [m]
  std::vector<double> scratch;   // work space (update_reference_frames), no meaning outside

  // Zeroes the forces and computes the geometry of s; every accumulate() needs it for the same s.
  void reset(const State& s);
};

}  // namespace wirepack
