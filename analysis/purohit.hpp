#pragma once
// Coil model after Purohit et al. (paper Eqs. 4-7, docs/design.md §5.5): the wire winds about the
// coil axis x with its binormal along x, filling a toroidal bundle whose cross-section is two
// half-ellipses y >= R_t (semi-axes R_x axial, R_y radial) with strands a distance d apart in a
// hexagonal lattice. At radius y the bundle holds w(y) = 2 R_x sqrt(1 - ((y - R_t)/R_y)^2) / d
// windings along x, and 2 / (sqrt(3) d) such layers per unit radius. Predicts the bending energy
// U_b(L) and total curvature K(L) from the measured radii. All lengths in metres.
#include "analysis/stats.hpp"

namespace wirepack::analysis {

struct PurohitPrediction {
  double c = NaN;    // c = 4/3 + pi p [-]
  double p = NaN;    // p = R_t / R_y [-]
  double d = NaN;    // mean strand separation d(L) [m], from paper Eq. (4)
  double U_b = NaN;  // bending energy, paper Eq. (6) [J]
  double K = NaN;    // total curvature, paper Eq. (7) [-]
  bool ok = false;   // false when L, EI, or a radius is <= 0 or not finite
};
// Closed forms for injected length L [m], radii R_t, R_x, R_y [m] and bending stiffness EI
// [N m^2]:
//   d   = sqrt(2 pi c R_x R_y^2 / (sqrt(3) L))                         (Eq. 4 solved for d)
//   U_b = 2 L EI / (c R_y^2) (q ln((1 + q)/p) + pi p / 2 - 1)          (Eq. 6), q = sqrt(1 - p^2)
//   K   = pi L / (c R_y)                                               (Eq. 7)
// For p > 1, q = i s with s = sqrt(p^2 - 1) and |1 + i s| = p, so q ln((1 + q)/p) =
// i s * i atan(s) = -s atan(s): real, as the paper notes; at p = 1 the term is 0.
PurohitPrediction purohit(double L, double R_t, double R_x, double R_y, double EI);

// The same integrals by quadrature at a given strand separation d [m] (for tests and as
// documentation of the model): y = R_t + R_y sin(theta), theta in [0, pi/2], removes the
// square-root endpoint singularity of w(y); Gauss-Legendre on the smooth integrand.
// L = 2/(sqrt(3) d) int 2 pi y w(y) dy [m]            (paper Eq. 4)
double purohit_length_quadrature(double d, double R_t, double R_x, double R_y);
// U_b = 2/(sqrt(3) d) int pi EI / y w(y) dy [J]       (paper Eq. 5)
double purohit_bending_quadrature(double d, double R_t, double R_x, double R_y, double EI);
// K = 2/(sqrt(3) d) int 2 pi w(y) dy [-]              (paper Eq. 7, integral form)
double purohit_curvature_quadrature(double d, double R_t, double R_x, double R_y);

// The dimensionless integral of Eq. (5): I(p) = int_0^1 sqrt(1 - u^2) / (p + u) du
// = q ln((1 + q)/p) + pi p / 2 - 1, evaluated without complex arithmetic for any p > 0.
double purohit_bending_integral(double p);

}  // namespace wirepack::analysis
