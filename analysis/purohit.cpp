// Purohit-type coil model (paper Eqs. 4-7): closed forms and their quadrature counterparts.
#include "analysis/purohit.hpp"

#include <cmath>
#include <numbers>
#include <vector>

namespace wirepack::analysis {
namespace {

using std::numbers::pi;

bool positive_finite(double v) {
  return std::isfinite(v) && v > 0;
}

// Gauss-Legendre rule of order n on [-1, 1]: nodes are the roots of P_n, found by Newton from
// the Chebyshev guess cos(pi (k - 1/4) / (n + 1/2)); weights 2 / ((1 - x^2) P_n'(x)^2).
struct GaussLegendre {
  std::vector<double> x, w;
  explicit GaussLegendre(int n) : x(static_cast<std::size_t>(n)), w(static_cast<std::size_t>(n)) {
    for (int k = 1; k <= n; ++k) {
      double t = std::cos(pi * (k - 0.25) / (n + 0.5));
      double dp = 1;
      for (int it = 0; it < 100; ++it) {
        // P_n(t) and P_n'(t) by the three-term recurrence.
        double p0 = 1, p1 = t;
        for (int j = 2; j <= n; ++j) {
          const double p2 = ((2 * j - 1) * t * p1 - (j - 1) * p0) / j;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (t * p1 - p0) / (t * t - 1);
        const double step = p1 / dp;
        t -= step;
        if (std::abs(step) < 1e-16) break;
      }
      const auto i = static_cast<std::size_t>(k - 1);
      x[i] = t;
      w[i] = 2 / ((1 - t * t) * dp * dp);
    }
  }
};

// Composite Gauss-Legendre (20 points on each of `panels` equal panels) of f over
// theta in [0, pi/2]. The integrands below are smooth in theta; the only sharp feature is the
// 1/(p + sin theta) peak of width ~p at theta = 0 for small p, resolved by 200 panels down to
// p ~ 1e-3.
template <class F>
double integrate_quarter(F f, int panels = 200) {
  static const GaussLegendre gl(20);
  const double h = 0.5 * pi / panels;
  double sum = 0;
  for (int k = 0; k < panels; ++k) {
    const double mid = (k + 0.5) * h;
    for (std::size_t j = 0; j < gl.x.size(); ++j) sum += gl.w[j] * f(mid + 0.5 * h * gl.x[j]);
  }
  return 0.5 * h * sum;
}

// Common prefactor of Eqs. 4, 5, 7 after y = R_t + R_y sin(theta), w = 2 R_x cos(theta) / d,
// dy = R_y cos(theta) dtheta: 2/(sqrt(3) d) * 2 R_x / d * R_y.
double layer_prefactor(double d, double R_x, double R_y) {
  return 2 / (std::sqrt(3.0) * d) * 2 * R_x / d * R_y;
}

}  // namespace

double purohit_bending_integral(double p) {
  if (!(p > 0)) return NaN;
  if (std::isinf(p)) return 0;
  if (p < 1) {
    // ln((1 + q)/p) = atanh(q) since p^2 = (1 - q)(1 + q).
    const double q = std::sqrt((1 - p) * (1 + p));
    return q * std::atanh(q) + 0.5 * pi * p - 1;
  }
  if (p == 1) return 0.5 * pi - 1;
  // p > 1: q ln((1 + q)/p) = -s atan(s), s = sqrt(p^2 - 1) (see purohit.hpp). With
  // atan(s) = pi/2 - atan(1/s): I = pi / (2 (p + s)) + (s atan(1/s) - 1), the last bracket by its
  // series -1/(3 s^2) + 1/(5 s^4) - ... for large s (avoids cancelling two O(1) terms).
  const double s = std::sqrt((p - 1) * (p + 1));
  double tail = 0;
  if (s < 4) {
    tail = s * std::atan(1 / s) - 1;
  } else {
    const double z = 1 / (s * s);
    double zk = z;
    double sign = -1;
    for (int k = 1; k <= 30; ++k) {
      tail += sign * zk / (2 * k + 1);
      zk *= z;
      sign = -sign;
    }
  }
  return 0.5 * pi / (p + s) + tail;
}

PurohitPrediction purohit(double L, double R_t, double R_x, double R_y, double EI) {
  PurohitPrediction r;
  if (!positive_finite(L) || !positive_finite(R_t) || !positive_finite(R_x) ||
      !positive_finite(R_y) || !positive_finite(EI)) {
    return r;
  }
  r.p = R_t / R_y;
  r.c = 4.0 / 3.0 + pi * r.p;
  // paper Eq. (4): L = 2 pi c R_x R_y^2 / (sqrt(3) d^2), solved for d.
  r.d = std::sqrt(2 * pi * r.c * R_x * R_y * R_y / (std::sqrt(3.0) * L));
  // paper Eq. (6): Purohit bending energy with d eliminated.
  r.U_b = 2 * L * EI / (r.c * R_y * R_y) * purohit_bending_integral(r.p);
  // paper Eq. (7): total curvature.
  r.K = pi * L / (r.c * R_y);
  r.ok = std::isfinite(r.U_b) && std::isfinite(r.K) && std::isfinite(r.d);
  return r;
}

double purohit_length_quadrature(double d, double R_t, double R_x, double R_y) {
  // paper Eq. (4): L = 2/(sqrt(3) d) int 2 pi y w(y) dy.
  const double I = integrate_quarter([&](double th) {
    const double c = std::cos(th);
    return (R_t + R_y * std::sin(th)) * c * c;
  });
  return layer_prefactor(d, R_x, R_y) * 2 * pi * I;
}

double purohit_bending_quadrature(double d, double R_t, double R_x, double R_y, double EI) {
  // paper Eq. (5): U_b = 2/(sqrt(3) d) int pi EI / y w(y) dy (a winding of radius y stores
  // (1/2) EI y^-2 * 2 pi y).
  const double I = integrate_quarter([&](double th) {
    const double c = std::cos(th);
    return c * c / (R_t + R_y * std::sin(th));
  });
  return layer_prefactor(d, R_x, R_y) * pi * EI * I;
}

double purohit_curvature_quadrature(double d, [[maybe_unused]] double R_t, double R_x, double R_y) {
  // paper Eq. (7): K = 2/(sqrt(3) d) int 2 pi w(y) dy (each winding turns by 2 pi, whatever its
  // radius, so R_t only shifts the integration range).
  const double I = integrate_quarter([](double th) {
    const double c = std::cos(th);
    return c * c;
  });
  return layer_prefactor(d, R_x, R_y) * 2 * pi * I;
}

}  // namespace wirepack::analysis
