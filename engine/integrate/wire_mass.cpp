#include "engine/integrate/wire_mass.hpp"

#include <cmath>
#include <stdexcept>
#include <type_traits>

namespace wirepack {

WireMass::WireMass(double m_p, double beta) : m_(m_p), beta_(beta), inv_m_(1.0 / m_p) {
  if (!(m_p > 0.0) || !(beta >= 0.0) || !std::isfinite(beta)) {
    throw std::invalid_argument("WireMass: need m_p > 0 and a finite beta >= 0");
  }
  // Tip of a semi-infinite chain: 1 / (M^-1)_00 = e_0 = m + beta - beta^2 / e*, with e* the
  // fixed point of the backward pivots e = m + 2 beta - beta^2 / e.
  const double s = m_ + 2.0 * beta_;
  const double e_star = 0.5 * (s + std::sqrt(m_ * m_ + 4.0 * m_ * beta_));
  point_mass_ = beta_ == 0.0 ? m_ : m_ + beta_ - beta_ * beta_ / e_star;
}

void WireMass::factorise(int n_free, bool joined_to_guide) {
  n_ = n_free;
  if (uniform()) return;
  inv_pivot_.resize(n_free);
  // Diagonal of M: m + beta * degree (the tip has one neighbour; the last free node two when it
  // is joined to the guide). Off-diagonal -beta. Forward pivots d_i = a_i - beta^2 / d_{i-1}.
  double d_prev = 0.0;
  for (int i = 0; i < n_free; ++i) {
    int degree = (i > 0 ? 1 : 0) + (i + 1 < n_free || joined_to_guide ? 1 : 0);
    const double diag = m_ + beta_ * degree;
    const double d = i == 0 ? diag : diag - beta_ * beta_ / d_prev;
    inv_pivot_[i] = 1.0 / d;
    d_prev = d;
  }
}

namespace {
double squared(const Vec3& x) {
  return x.squaredNorm();
}
double squared(double x) {
  return x * x;
}
template <class T>
T zero() {
  if constexpr (std::is_same_v<T, double>) {
    return 0.0;
  } else {
    return T::Zero();
  }
}
}  // namespace

template <class T>
void WireMass::solve_impl(const std::vector<T>& f, std::vector<T>& a) const {
  const int n = static_cast<int>(f.size());
  a.resize(n);
  if (uniform()) {
    for (int i = 0; i < n; ++i) a[i] = i < n_ ? T(inv_m_ * f[i]) : zero<T>();
    return;
  }
  // Thomas algorithm, off-diagonal -beta: g_i = f_i + beta g_{i-1} / d_{i-1}, then
  // a_i = (g_i + beta a_{i+1}) / d_i.
  for (int i = 0; i < n_; ++i) {
    a[i] = i == 0 ? f[0] : T(f[i] + (beta_ * inv_pivot_[i - 1]) * a[i - 1]);
  }
  for (int i = n_ - 1; i >= 0; --i) {
    a[i] = i == n_ - 1 ? T(inv_pivot_[i] * a[i]) : T(inv_pivot_[i] * (a[i] + beta_ * a[i + 1]));
  }
  for (int i = n_; i < n; ++i) a[i] = zero<T>();
}

void WireMass::solve(const Vec3List& f, Vec3List& a) const {
  solve_impl(f, a);
}
void WireMass::solve(const std::vector<double>& f, std::vector<double>& a) const {
  solve_impl(f, a);
}

template <class T>
double WireMass::kinetic_impl(const std::vector<T>& v, int n_free, bool joined_to_guide) const {
  double k = 0.0;
  for (int i = 0; i < n_free; ++i) k += squared(v[i]);
  double e = 0.5 * m_ * k;
  if (uniform()) return e;
  const int n = static_cast<int>(v.size());
  double rel = 0.0;
  const int last = joined_to_guide ? n_free : n_free - 1;  // edges (j, j+1) with j < last
  for (int j = 0; j < last && j + 1 < n; ++j) rel += squared(T(v[j + 1] - v[j]));
  return e + 0.5 * beta_ * rel;
}

double WireMass::kinetic_energy(const Vec3List& v, int n_free, bool joined_to_guide) const {
  return kinetic_impl(v, n_free, joined_to_guide);
}
double WireMass::kinetic_energy(const std::vector<double>& v, int n_free,
                                bool joined_to_guide) const {
  return kinetic_impl(v, n_free, joined_to_guide);
}

Vec3 WireMass::momentum(const Vec3List& v, int n_free) const {
  Vec3 p = Vec3::Zero();
  for (int i = 0; i < n_free; ++i) p += m_ * v[i];
  if (uniform()) return p;
  // Rows of beta L over the free nodes sum to beta (v_last - v_guide) (the interior edges
  // cancel pairwise); the guide's own row is not a free DOF.
  const int n = static_cast<int>(v.size());
  if (n_free > 0 && n_free < n) p += beta_ * (v[n_free - 1] - v[n_free]);
  return p;
}

}  // namespace wirepack
