#pragma once
// Observables of a wire configuration (docs/design.md §5). Pure functions of the centerline: nodes
// in order along the wire [m], any number n >= 0 (degenerate inputs give documented zeros).
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include <Eigen/Core>

namespace wirepack::analysis {

using Vec3 = Eigen::Vector3d;
using Centerline = std::span<const Vec3>;

// Voronoi length of node i: half the sum of its adjacent edge lengths (n) [m].
std::vector<double> voronoi_lengths(Centerline x);
// Discrete curvature kappa_i = 2 tan(phi_i / 2) / ell_i at interior nodes (phi_i turning angle,
// ell_i Voronoi length); 0 at the two end nodes (n) [1/m].
std::vector<double> curvatures(Centerline x);
// Total curvature K = sum_i kappa_i ell_i [-].
double total_curvature(Centerline x);
// Coil normal: eigenvector of the length-weighted gyration tensor
// sum ell_i (x_i - xbar)(x_i - xbar)^T with the smallest eigenvalue (unit).
// Sign: the component of largest magnitude is positive (S keeps its sign as a sense of rotation).
Vec3 coil_normal(Centerline x);
// Turning axis: eigenvector of sum_i |b_i| bhat_i bhat_i^T with the largest eigenvalue (unit,
// sign as coil_normal), b_i = u_{i-k,i} x u_{i,i+k} over unit chords u spanning k = stride edges:
// the common binormal of a coil's turns, whatever the bundle's aspect ratio (the coil normal tips
// into the plane of a coil taller than wide). A stride of ~1/8 turn averages out node noise.
Vec3 turning_axis(Centerline x, std::size_t stride = 1);
struct Order {
  double S = 0;            // (1/L) sum ell_i sgn(n . (t_{i-1} x t_i)) [-]
  double D = 1;            // 1 - |S|
  Vec3 n = Vec3::UnitZ();  // axis used
};
// Order parameter of paper section "Order-disorder transition" with the coil-normal axis, sums
// over interior nodes. No turning (n <= 2 nodes, a straight wire) gives S = 0, D = 1.
Order order_parameter(Centerline x);
// Curvature-weighted order parameter S_kappa = int kappa_n ds / int |kappa_n| ds, kappa_n the
// component along the axis n of order_parameter of the curvature binormal kappa b; discretely
// kappa_n,i ell_i = n . 2 (t_{i-1} x t_i) / (1 + t_{i-1} . t_i) (the signed turning, independent
// of the Voronoi lengths). Unlike the paper's S, which counts every unit of length alike, a
// straight stretch (the entry chord from the hole) weighs nothing and a tight loop much. Same
// axis and degenerate cases as order_parameter (no turning: S = 0, D = 1).
Order curvature_weighted_order(Centerline x);
// The signed turning kappa_n,i ell_i = n . 2 (t_{i-1} x t_i) / (1 + t_{i-1} . t_i) of every node
// about the axis n (unit) (n values; 0 at the two ends, at a zero-length edge and at a complete
// fold-back) [-]: positive where the wire turns counter-clockwise about n.
std::vector<double> signed_turning(Centerline x, const Vec3& n);
// Sense blocks (docs/design.md §5.3): the wire cut where the sign of its turning about the axis
// n changes, blocks shorter than min_block merged into their neighbours (the shortest first, the
// first of equal ones first: merging a block joins it and its two neighbours, which turn alike).
// D = 1 - |S| cannot tell one coil wound one way and then the other (a reversal: D up to 1) from
// loops turning every way; the blocks can: a coil is one block, a reversed coil two or three long
// ones, a disordered packing many of about a loop's length. Interior nodes, each weighing its
// Voronoi length, signs as order_parameter (a node that does not turn joins the block before it,
// leading ones the first block).
struct SenseBlocks {
  std::size_t reversals = 0;  // number of blocks - 1 [-]
  double order_length = 0;    // length-weighted mean block length sum b^2 / sum b [m]
  double length = 0;          // sum b: the interior nodes' Voronoi lengths [m]
};
// The core on a sequence: node weights ell (n) [m] and turning signs (n, each -1, 0 or 1).
SenseBlocks sense_blocks(std::span<const double> ell, std::span<const int> sign, double min_block);
// A centerline's blocks about the axis n (unit); min_block [m].
SenseBlocks sense_blocks(Centerline x, const Vec3& n, double min_block);
// The entry chord: the wire from the hole (the last node of the inside wire) back to its first
// contact with the shell or with another part of the wire. Walking back from the last node,
// node i is in contact when distance_to_shell(x_i) < r + slack (distance of the centreline point
// to the shell's surface on the inside [m]) or when a node j at least `exclude` nodes away along
// the wire is closer than 2 r + slack; nodes within hole_zone of the last node (the wire passing
// through the hole lies on the shell) are not tested. Returns k, the number of nodes before the
// chord: the wire without its entry chord is x.first(k), its order parameter the variant that
// does not count the chord. k = 0 when nothing touches.
std::size_t entry_chord_start(Centerline x, double r, double slack, std::size_t exclude,
                              double hole_zone,
                              const std::function<double(const Vec3&)>& distance_to_shell);
// Paper: U_b_hat = U_b r^2 / (R E_w I).
double bending_energy_hat(double U_b, double r, double R, double E_w);

// Coil cross-section (docs/design.md §5.4): in cylindrical coordinates about the turning axis
// (through the turning-weighted centroid), the bundle is fitted by two half-ellipses y >= R_t with
// semi-axes R_x (axial) and R_y (radial). The radii describe the material envelope (the wire's
// surface: centerline extremes + wire_radius), R_t being the innermost wire surface. Radii in
// metres; ok = false when the wire makes less than one net turn about the axis or the fit
// degenerates (see coil_radii.cpp).
struct CoilRadii {
  double R_t = 0, R_x = 0, R_y = 0;
  bool ok = false;
};
CoilRadii coil_radii(Centerline x, double wire_radius);

}  // namespace wirepack::analysis
