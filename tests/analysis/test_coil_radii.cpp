// Tests for coil_radii (docs/design.md §5.4, paper Fig. 1f): synthetic toroidal bundles
// of known material radii R_t, R_x, R_y, hexagonally packed with node noise, at nine shapes;
// a hexagonal lattice clipped at random offsets (its envelope lies inside the nominal one by the
// lattice gaps); invariance under a rigid motion; wires that are not coils.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <ostream>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "analysis/observables.hpp"

namespace wirepack::analysis {
namespace {

using std::numbers::pi;
using Vec2 = Eigen::Vector2d;  // cross-section point (y radial, a axial) [m]

// Material radii of a bundle [m].
struct Radii {
  double R_t, R_x, R_y;
};

// True iff a wire disk of radius r centred at p = (y, a) lies inside the material half-ellipse
// {y >= R_t, ((y - R_t) / R_y)^2 + (a / R_x)^2 <= 1}: y >= R_t + r and 720 points of the disk's
// rim inside the ellipse (the rim may poke out by r (1 - cos(pi / 720)) < 1e-5 r).
bool disk_inside(const Radii& b, double r, const Vec2& p) {
  if (p[0] < b.R_t + r * (1 - 1e-9)) return false;
  for (int k = 0; k < 720; ++k) {
    const double t = 2 * pi * k / 720;
    const double u = (p[0] + r * std::cos(t) - b.R_t) / b.R_y, v = (p[1] + r * std::sin(t)) / b.R_x;
    if (u * u + v * v > 1 + 1e-9) return false;
  }
  return true;
}

// Outer layer of turns pressed against the envelope: sites at least 2 r apart along the inner
// parallel curve (distance r) of the ellipse, q(t) = e(t) - r nu(t) with e(t) = (R_t + R_y cos t,
// R_x sin t) and outward normal nu ~ (R_x cos t, R_y sin t), for y >= R_t + r; the two end sites
// sit in the corners of the flat inner face.
std::vector<Vec2> rim_layer(const Radii& b, double r) {
  auto q = [&](double t) {
    const double c = std::cos(t), s = std::sin(t), N = std::hypot(b.R_x * c, b.R_y * s);
    return Vec2(b.R_t + b.R_y * c - r * b.R_x * c / N, b.R_x * s - r * b.R_y * s / N);
  };
  double lo = 0, hi = pi / 2;  // q_y(t_c) = R_t + r by bisection (q_y decreases on [0, pi/2])
  for (int it = 0; it < 100; ++it)
    ((q(0.5 * (lo + hi))[0] > b.R_t + r) ? lo : hi) = 0.5 * (lo + hi);
  const double tc = 0.5 * (lo + hi);
  constexpr int kSamples = 20000;
  std::vector<double> s(kSamples + 1, 0.0);  // arclength of q from -tc
  for (int k = 1; k <= kSamples; ++k) {
    s[k] =
        s[k - 1] + (q(-tc + 2 * tc * k / kSamples) - q(-tc + 2 * tc * (k - 1) / kSamples)).norm();
  }
  const int m = std::max(1, static_cast<int>(std::floor(s.back() / (2 * r))));  // gaps >= 2 r
  std::vector<Vec2> sites;
  for (int j = 0, k = 0; j <= m; ++j) {  // equal arclength steps, k: sample interval
    const double target = s.back() * j / m;
    while (k + 1 < kSamples && s[k + 1] < target) ++k;
    const double f = (k + (target - s[k]) / (s[k + 1] - s[k])) / kSamples;  // s increases
    sites.push_back(q(-tc + 2 * tc * std::min(1.0, f)));
  }
  return sites;
}

// Turn centres of a hexagonal packing of spacing 2 r: rows of constant y, sqrt(3) r apart, the
// first row wound on the inner face y = R_t + r, axial lattice offset a_shift; a site is kept
// where its wire disk fits inside the material half-ellipse and it is >= 2 r from every site of
// `avoid`. Rows are visited in a snake so that consecutive sites are neighbours.
std::vector<Vec2> lattice_sites(const Radii& b, double r, double a_shift,
                                const std::vector<Vec2>& avoid) {
  std::vector<Vec2> sites;
  const int rows = static_cast<int>(std::floor((b.R_y - 2 * r) / (std::sqrt(3.0) * r))) + 1;
  const int kmax = static_cast<int>(std::ceil(b.R_x / (2 * r))) + 1;
  for (int j = 0; j < rows; ++j) {
    std::vector<Vec2> row;
    for (int k = -kmax; k <= kmax; ++k) {
      const Vec2 p(b.R_t + r + j * std::sqrt(3.0) * r, a_shift + (j % 2 ? r : 0.0) + 2 * r * k);
      bool free = disk_inside(b, r, p);
      for (const Vec2& o : avoid) free = free && (p - o).norm() >= 2 * r * (1 - 1e-9);
      if (free) row.push_back(p);
    }
    if (j % 2) std::reverse(row.begin(), row.end());
    sites.insert(sites.end(), row.begin(), row.end());
  }
  return sites;
}

// Wire about the z axis winding 1.38 turns at each site (y, a) in order, the last 15 % of each
// visit moving on to the next site (a smoothstep in y and a, inside the convex cross-section).
// Nodes ~ds apart, each displaced by isotropic Gaussian noise of standard deviation `noise`
// (n x 3) [m].
std::vector<Vec3> wind(const std::vector<Vec2>& sites, double ds, double noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0.0, noise);
  std::vector<Vec3> x;
  constexpr double kMove = 0.15;
  // 1 + 1 / phi^2 turns per site (phi the golden ratio): the moves between sites, and with them
  // the slight lean they give a turn, are spread evenly in azimuth as in a real winding.
  const double span = 2 * pi * (1 + 2 / (3 + std::sqrt(5.0)));
  double theta = 0;
  for (std::size_t s = 0; s < sites.size(); ++s) {
    const Vec2 p0 = sites[s], p1 = sites[std::min(s + 1, sites.size() - 1)];
    const int nt = std::max(12, static_cast<int>(std::ceil(span * p0[0] / ds)));
    for (int j = 0; j < nt; ++j) {
      const double f = double(j) / nt, th = theta + span * f;
      const double g = std::clamp((f - (1 - kMove)) / kMove, 0.0, 1.0);
      const Vec2 p = p0 + g * g * (3 - 2 * g) * (p1 - p0);
      x.emplace_back(p[0] * std::cos(th) + gauss(rng), p[0] * std::sin(th) + gauss(rng),
                     p[1] + gauss(rng));
    }
    theta += span;
  }
  return x;
}

constexpr double kR = 1e-3;       // wire radius [m]
constexpr double kR_y = 32 * kR;  // R_y / r = 32: >= 200 turns at the slimmest shape
constexpr double kNoise = 0.05;   // node noise / r
constexpr double kDs = kR;        // node spacing [m]

// Dense bundle whose envelope is the half-ellipse: outer layer pressed against it, first row on
// the inner face, hexagonal packing inside (n_turns: number of turns).
std::vector<Vec3> dense_bundle(const Radii& b, double a_shift, unsigned seed, int* n_turns) {
  const std::vector<Vec2> rim = rim_layer(b, kR);
  std::vector<Vec2> sites = lattice_sites(b, kR, a_shift, rim);
  for (const Vec2& p : rim) EXPECT_TRUE(disk_inside(b, kR, p));
  sites.insert(sites.end(), rim.begin(), rim.end());
  *n_turns = static_cast<int>(sites.size());
  return wind(sites, kDs, kNoise * kR, seed);
}

struct Shape {
  double t_over_y, x_over_y;  // R_t / R_y, R_x / R_y
};
void PrintTo(const Shape& s, std::ostream* os) {
  *os << "R_t/R_y=" << s.t_over_y << " R_x/R_y=" << s.x_over_y;
}

class DenseBundle : public ::testing::TestWithParam<Shape> {};

TEST_P(DenseBundle, RecoversMaterialRadiiWithin3Percent) {
  // Here the envelope touches M all round, so only the estimator's own errors remain: trimmed node
  // noise after the running mean (~0.03 r) and the outer layer's sagitta between sites (< 0.1 r);
  // observed < 0.6 % on every radius, against the required 3 %. Two lattice offsets and noise
  // seeds per shape.
  const Radii b{GetParam().t_over_y * kR_y, GetParam().x_over_y * kR_y, kR_y};
  for (int rep = 0; rep < 2; ++rep) {
    int turns = 0;
    const auto x = dense_bundle(b, (0.37 + 0.81 * rep) * kR, 11 + rep, &turns);
    const CoilRadii c = coil_radii(x, kR);
    ASSERT_TRUE(c.ok);
    EXPECT_GE(turns, 200);
    EXPECT_NEAR(c.R_t / b.R_t, 1, 0.03);
    EXPECT_NEAR(c.R_x / b.R_x, 1, 0.03);
    EXPECT_NEAR(c.R_y / b.R_y, 1, 0.03);
    RecordProperty("rel_err_" + std::to_string(rep), std::to_string(c.R_t / b.R_t - 1) + " " +
                                                         std::to_string(c.R_x / b.R_x - 1) + " " +
                                                         std::to_string(c.R_y / b.R_y - 1));
  }
}

INSTANTIATE_TEST_SUITE_P(NineShapes, DenseBundle,
                         ::testing::Values(Shape{0.3, 0.5}, Shape{0.3, 1}, Shape{0.3, 2},
                                           Shape{1, 0.5}, Shape{1, 1}, Shape{1, 2}, Shape{3, 0.5},
                                           Shape{3, 1}, Shape{3, 2}));

TEST(CoilRadii, ClippedLatticeEnvelopeLiesWithinOneLatticeGap) {
  // A lattice merely clipped to the eroded half-ellipse (no layer pressed against the rim): its
  // outer turns miss the nominal envelope by the lattice gap, up to r across lattice columns
  // (a faces) and sqrt(3) r across rows (outer rim). The fit reports the wires' own envelope, so
  // the nominal R_x, R_y are approached from below, by 0.1 r to 0.7 r here (least squares
  // averages the gaps over directions); R_t, set by the first row on the inner face, is not
  // affected. With R_y = 48 r (>= 500 turns) this stays inside 3 % even at R_x = 24 r.
  const double R_y = 48 * kR;
  for (const Shape& sh : {Shape{0.3, 0.5}, Shape{1, 1}, Shape{0.3, 2}}) {
    const Radii b{sh.t_over_y * R_y, sh.x_over_y * R_y, R_y};
    for (double a_shift : {0.0, 0.6, 1.2}) {
      const auto x = wind(lattice_sites(b, kR, a_shift * kR, {}), 2 * kDs, kNoise * kR, 3);
      const CoilRadii c = coil_radii(x, kR);
      ASSERT_TRUE(c.ok);
      EXPECT_NEAR(c.R_t, b.R_t, 0.2 * kR);
      EXPECT_LT(c.R_x, b.R_x + 0.1 * kR);
      EXPECT_GT(c.R_x, b.R_x - kR);
      EXPECT_LT(c.R_y, b.R_y + 0.1 * kR);
      EXPECT_GT(c.R_y, b.R_y - kR);
      EXPECT_NEAR(c.R_t / b.R_t, 1, 0.03);
      EXPECT_NEAR(c.R_x / b.R_x, 1, 0.03);
      EXPECT_NEAR(c.R_y / b.R_y, 1, 0.03);
    }
  }
}

TEST(CoilRadii, StraightEnteringWireIsIgnored) {
  // The wire still on its way in: a straight stretch three outer turns long leaving the last
  // turn along its tangent (reaching y ~ 19 R_y). Its curvature radius is infinite, not ~y, so it
  // is left out of the outline and the radii stay within 3 %.
  const Radii b{1.0 * kR_y, 1.0 * kR_y, kR_y};
  int turns = 0;
  auto x = dense_bundle(b, 0.37 * kR, 9, &turns);
  const Vec3 t = (x.back() - x[x.size() - 2]).normalized();
  const double tail = 3 * 2 * pi * (b.R_t + b.R_y);
  const Vec3 end = x.back();
  for (double s = kDs; s <= tail; s += kDs) x.push_back(end + s * t);
  const CoilRadii c = coil_radii(x, kR);
  ASSERT_TRUE(c.ok);
  EXPECT_NEAR(c.R_t / b.R_t, 1, 0.03);
  EXPECT_NEAR(c.R_x / b.R_x, 1, 0.03);
  EXPECT_NEAR(c.R_y / b.R_y, 1, 0.03);
}

TEST(CoilRadii, InvariantUnderRigidMotion) {
  // Rotation + translation change nothing but round-off (axis, centroid and cylindrical
  // coordinates are covariant): radii agree to 1e-9 relative.
  const Radii b{1.0 * kR_y, 2.0 * kR_y, kR_y};  // taller than wide: needs the turning axis
  int turns = 0;
  const auto x = dense_bundle(b, 0.37 * kR, 5, &turns);
  const Eigen::Matrix3d Q =
      Eigen::AngleAxisd(2.1, Vec3(0.3, -1, 0.6).normalized()).toRotationMatrix();
  const Vec3 shift(0.25, -1.5, 3.0);
  std::vector<Vec3> y;
  for (const Vec3& p : x) y.push_back(Q * p + shift);
  const CoilRadii c = coil_radii(x, kR), d = coil_radii(y, kR);
  ASSERT_TRUE(c.ok);
  ASSERT_TRUE(d.ok);
  EXPECT_NEAR(d.R_t, c.R_t, 1e-9 * c.R_t);
  EXPECT_NEAR(d.R_x, c.R_x, 1e-9 * c.R_x);
  EXPECT_NEAR(d.R_y, c.R_y, 1e-9 * c.R_y);
  EXPECT_NEAR(d.R_x / b.R_x, 1, 0.03);
}

TEST(CoilRadii, WiresThatAreNotCoilsAreNotOk) {
  // Documented behaviour: fewer than one net turn about the turning axis gives ok = false.
  std::vector<Vec3> line, arc;
  for (int j = 0; j < 100; ++j) {
    line.push_back(j * Vec3(1e-3, 2e-3, -1e-3));
    const double t = 1.8 * pi * j / 99;  // 0.9 turn
    arc.emplace_back(0.05 * std::cos(t), 0.05 * std::sin(t), 0);
  }
  EXPECT_FALSE(coil_radii(line, kR).ok);
  EXPECT_FALSE(coil_radii(arc, kR).ok);
  EXPECT_FALSE(coil_radii(line, -1.0).ok);  // invalid wire radius
}

}  // namespace
}  // namespace wirepack::analysis
