// Tests for sphtroch/core/curve.hpp (double): the rotation chain against the report's expanded
// equations (Eqs. 4, 5, 9, 28), the phase rotation (Eq. 8), the special points for n = 1
// (Eqs. 11, 12, 14, 15, 25) and n = 2 (Eqs. 32-35), and the velocity, acceleration and screw
// axis (Eq. 47a) against finite differences and the pitch-cone geometry.
//
// Every expected value below is computed here from the report's formulas, written out
// component by component, never taken from the library.
#include "catch2/catch.hpp"

#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/gear_train.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using sphtroch::A3Reference;
using sphtroch::GearTrain;
using sphtroch::Ratio;
using sphtroch::TracerCurve;
using V3 = Eigen::Vector3d;

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kEps = std::numeric_limits<double>::epsilon();  // 2.22e-16

/// Eq. 4, expanded (the second line of the report's Eq. 4), theta3 given.
V3 eq4(double a2, double a3, double t2, double t3) {
  const double c2 = std::cos(t2), s2 = std::sin(t2), c3 = std::cos(t3), s3 = std::sin(t3);
  const double ca2 = std::cos(a2), sa2 = std::sin(a2), ca3 = std::cos(a3), sa3 = std::sin(a3);
  return V3(c2 * s3 * sa3 + s2 * c3 * ca2 * sa3 + s2 * sa2 * ca3,   //
            s2 * s3 * sa3 - c2 * c3 * ca2 * sa3 - c2 * sa2 * ca3,   //
            -c3 * sa2 * sa3 + ca2 * ca3);
}

/// Eq. 5 (theta_p = 0), expanded, with n theta2 formed as p*theta2/q.
V3 eq5(double a2, double a3, const Ratio& n, double t2) {
  const double nt = static_cast<double>(n.p()) * t2 / static_cast<double>(n.q());
  const double c2 = std::cos(t2), s2 = std::sin(t2), cn = std::cos(nt), sn = std::sin(nt);
  const double ca2 = std::cos(a2), sa2 = std::sin(a2), ca3 = std::cos(a3), sa3 = std::sin(a3);
  return V3(c2 * sn * sa3 + s2 * cn * ca2 * sa3 + s2 * sa2 * ca3,  //
            s2 * sn * sa3 - c2 * cn * ca2 * sa3 - c2 * sa2 * ca3,  //
            -cn * sa2 * sa3 + ca2 * ca3);
}

/// Eq. 9 (n = 1), as printed.
V3 eq9(double a2, double a3, double t2) {
  const double c = std::cos(t2), s = std::sin(t2);
  const double ca2 = std::cos(a2), sa2 = std::sin(a2), ca3 = std::cos(a3), sa3 = std::sin(a3);
  return V3(c * s * sa3 * (1 + ca2) + s * sa2 * ca3,                      //
            (1 - c * c) * sa3 - c * c * ca2 * sa3 - c * sa2 * ca3,        //
            -c * sa2 * sa3 + ca2 * ca3);
}

/// Eq. 28 (n = 2), as printed.
V3 eq28(double a2, double a3, double t2) {
  const double c = std::cos(t2), s = std::sin(t2);
  const double ca2 = std::cos(a2), sa2 = std::sin(a2), ca3 = std::cos(a3), sa3 = std::sin(a3);
  return V3(s * (2 * (1 - s * s) * sa3 * (1 + ca2) + std::sin(a2 - a3)),  //
            c * (2 * (1 - c * c) * sa3 * (1 + ca2) - std::sin(a2 + a3)),  //
            -std::cos(2 * t2) * sa2 * sa3 + ca2 * ca3);
}

/// Eq. 47a: omega = Z1 + n Z2 per unit carrier rate.
V3 eq47a(double a2, double n, double t2) {
  return V3(n * std::sin(t2) * std::sin(a2), -n * std::cos(t2) * std::sin(a2), 1 + n * std::cos(a2));
}

/// The planet axis Z2 in the base frame: third column of the first matrix of Eq. 4.
V3 z2_axis(double a2, double t2) { return V3(std::sin(t2) * std::sin(a2), -std::cos(t2) * std::sin(a2), std::cos(a2)); }

double max_abs_diff(const V3& a, const V3& b) { return (a - b).cwiseAbs().maxCoeff(); }

const double kA2[] = {0.1, kPi / 3, kPi / 2, 2.0, 2 * kPi / 3, 3.0};
const double kA3[] = {0.05, kPi / 4, kPi / 2, 2.2, 3.1};
const Ratio kRatios[] = {Ratio(1),     Ratio(2),     Ratio(3),     Ratio(-1),   Ratio(-2),
                         Ratio(-3, 2), Ratio(5, 2),  Ratio(1, 3),  Ratio(2, 7), Ratio(-7, 4)};
const double kPhases[] = {0.0, 0.7, -kPi / 4};

std::vector<double> theta_grid() {
  std::vector<double> t;
  for (int k = -48; k <= 48; ++k) t.push_back(k * kPi / 12 + 0.01 * k);  // [-4 pi, 4 pi], not on multiples of pi only
  for (double big : {100.0, -250.5, 1000.25, 12345.678, 1e5 + 0.3}) t.push_back(big);
  return t;
}
}  // namespace

TEST_CASE("chain equals the expanded Eq. 4 component by component to 1e-15 over (a2, a3, n, phase, theta2)",
          "[curve][eq4]") {
  // Both sides evaluate sin/cos at the same double theta3 = n theta2 + theta_p (Eq. 3, with
  // n theta2 formed as p*theta2/q). That makes the check independent of |theta2|: what is left
  // is the rounding of the two matrix products, a few ulp of O(1) terms. How accurately theta3
  // itself is formed is checked separately below (it is the dominant error for large theta2).
  const auto grid = theta_grid();
  double worst = 0.0;
  for (double a2 : kA2)
    for (double a3 : kA3)
      for (const Ratio& n : kRatios)
        for (double phase : kPhases) {
          const TracerCurve<double> curve(GearTrain(a2, a3, n, phase));
          for (double t2 : grid) {
            const double t3 = static_cast<double>(n.p()) * t2 / static_cast<double>(n.q()) + phase;
            const V3 expected = eq4(a2, a3, t2, t3);
            const V3 p = curve.point(t2);
            const double err = max_abs_diff(p, expected);
            worst = std::max(worst, err);
            if (err > 1e-15) {
              INFO("a2 = " << a2 << " a3 = " << a3 << " n = " << n.str() << " phase = " << phase << " theta2 = " << t2);
              CHECK(err <= 1e-15);
            }
          }
        }
  INFO("worst absolute component error " << worst);
  CHECK(worst <= 1e-15);
}

TEST_CASE("theta3 = n theta2 + theta_p (Eq. 3) to its rounding bound, why large theta2 misses 1e-15 absolute",
          "[curve][eq3]") {
  // Reference in long double (64-bit significand): p * theta2 is exact there for |p| < 2^10 and
  // theta2 a double, so the reference carries one rounding of 2^-64 relative. The double value
  // p*theta2/q + theta_p carries up to three roundings of 2^-53 relative each: |error| <=
  // 1.5 eps (|n theta2| + |theta_p|) (+ a hair). For |theta2| ~ 1e5 that is ~1e-11 rad, and P
  // moves by up to |dP/dtheta3| <= 1 times that: any comparison of P at large theta2 against a
  // theta3 formed differently (e.g. as 0.2857142857142857 * theta2 for n = 2/7) differs by
  // |theta3| * eps, not by a few ulp — conditioning of sin/cos at a large argument, not a bug.
  for (const Ratio& n : kRatios)
    for (double phase : kPhases) {
      const TracerCurve<double> curve(GearTrain(1.0, 1.0, n, phase));
      for (double t2 : theta_grid()) {
        const long double exact = static_cast<long double>(n.p()) * t2 / static_cast<long double>(n.q()) + phase;
        const double got = curve.planet_angle(t2);
        const long double bound =
            1.5L * kEps * (std::fabs(static_cast<long double>(n.value()) * t2) + std::fabs(phase)) + 1e-300L;
        INFO("n = " << n.str() << " theta2 = " << t2);
        CHECK(std::fabs(static_cast<long double>(got) - exact) <= bound + 2 * std::numeric_limits<long double>::epsilon() * std::fabs(exact));
      }
    }
}

TEST_CASE("chain equals Eq. 4 evaluated in long double within the theta3 rounding bound", "[curve][eq4]") {
  // The same comparison against an independent long-double evaluation of Eq. 4 (theta3 exact
  // to 2^-64): the allowed error is the theta3 rounding of the test above (P moves by at most
  // |theta3 error|, |dP/dtheta3| <= 1) plus 1e-15 for the products.
  for (double a2 : kA2)
    for (double a3 : kA3)
      for (const Ratio& n : kRatios) {
        const double phase = 0.7;
        const TracerCurve<double> curve(GearTrain(a2, a3, n, phase));
        for (double t2 : theta_grid()) {
          using L = long double;
          const L t3 = static_cast<L>(n.p()) * t2 / static_cast<L>(n.q()) + phase;
          const L c2 = std::cos(static_cast<L>(t2)), s2 = std::sin(static_cast<L>(t2));
          const L c3 = std::cos(t3), s3 = std::sin(t3);
          const L ca2 = std::cos(static_cast<L>(a2)), sa2 = std::sin(static_cast<L>(a2));
          const L ca3 = std::cos(static_cast<L>(a3)), sa3 = std::sin(static_cast<L>(a3));
          const L ex = c2 * s3 * sa3 + s2 * c3 * ca2 * sa3 + s2 * sa2 * ca3;
          const L ey = s2 * s3 * sa3 - c2 * c3 * ca2 * sa3 - c2 * sa2 * ca3;
          const L ez = -c3 * sa2 * sa3 + ca2 * ca3;
          const V3 p = curve.point(t2);
          const L tol = 1.5L * kEps * std::fabs(t3) + 1e-15L;
          INFO("a2 = " << a2 << " a3 = " << a3 << " n = " << n.str() << " theta2 = " << t2);
          CHECK(std::fabs(p.x() - ex) <= tol);
          CHECK(std::fabs(p.y() - ey) <= tol);
          CHECK(std::fabs(p.z() - ez) <= tol);
        }
      }
}

TEST_CASE("chain equals the expanded Eq. 5 (theta_p = 0) to 1e-15", "[curve][eq5]") {
  for (double a2 : kA2)
    for (double a3 : kA3)
      for (const Ratio& n : kRatios) {
        const TracerCurve<double> curve(GearTrain(a2, a3, n));
        for (double t2 : theta_grid()) {
          INFO("a2 = " << a2 << " a3 = " << a3 << " n = " << n.str() << " theta2 = " << t2);
          CHECK(max_abs_diff(curve.point(t2), eq5(a2, a3, n, t2)) <= 1e-15);
        }
      }
}

TEST_CASE("n = 1: chain equals Eq. 9 as printed", "[curve][eq9][n1]") {
  // Eq. 9 regroups Eq. 5; its intermediate terms are bounded by 2 (sa3 (1 + ca2) <= 2), so the
  // rounding stays within 1e-15 for |theta2| where sin/cos are well conditioned ([-4 pi, 4 pi]).
  for (double a2 : kA2)
    for (double a3 : kA3) {
      const TracerCurve<double> curve(GearTrain(a2, a3, Ratio(1)));
      for (int k = -48; k <= 48; ++k) {
        const double t2 = k * kPi / 12 + 0.01 * k;
        INFO("a2 = " << a2 << " a3 = " << a3 << " theta2 = " << t2);
        CHECK(max_abs_diff(curve.point(t2), eq9(a2, a3, t2)) <= 1e-15);
      }
    }
}

TEST_CASE("n = 2: chain equals Eq. 28 as printed", "[curve][eq28][n2]") {
  // Eq. 28 forms sin(a2 -+ a3) and cos(2 theta2) directly and carries terms up to 4 in size
  // (2 sa3 (1 + ca2)), i.e. up to ~6 roundings of quantities <= 4: bound 8 * 4 * eps/2.
  const double tol = 16 * kEps;
  for (double a2 : kA2)
    for (double a3 : kA3) {
      const TracerCurve<double> curve(GearTrain(a2, a3, Ratio(2)));
      for (int k = -48; k <= 48; ++k) {
        const double t2 = k * kPi / 12 + 0.01 * k;
        INFO("a2 = " << a2 << " a3 = " << a3 << " theta2 = " << t2);
        CHECK(max_abs_diff(curve.point(t2), eq28(a2, a3, t2)) <= tol);
      }
    }
}

TEST_CASE("P is a unit vector (sum of squares of Eq. 5 is 1, Sec. 4.1)", "[curve][unit]") {
  for (double a2 : kA2)
    for (double a3 : kA3)
      for (const Ratio& n : kRatios) {
        const TracerCurve<double> curve(GearTrain(a2, a3, n, 0.3));
        for (double t2 : theta_grid()) CHECK(std::abs(curve.point(t2).norm() - 1.0) <= 4 * kEps);
      }
}

TEST_CASE("closure: P(theta2 + 2 pi q) = P(theta2) within the argument rounding", "[curve][closure]") {
  // theta2 + T (T = 2 pi q) is rounded (|theta2| + T) eps/2; T itself carries q * 2 pi * eps/2;
  // theta3 = p (theta2 + T)/q + theta_p then has (|n| + 1)... roundings of its own size. P moves by
  // at most |dP/dtheta2| <= 1 + |n| per radian of theta2 error and 1 per radian of theta3 error:
  // bound = 2 eps (1 + |n|) (|theta2| + T) + 2 eps |theta3| + a few ulp of the products.
  for (double a2 : {0.4, kPi / 2, 2.5})
    for (double a3 : {0.3, kPi / 2, 2.9})
      for (const Ratio& n : kRatios) {
        const TracerCurve<double> curve(GearTrain(a2, a3, n, -0.4));
        const double period = curve.period();
        CHECK(period == 2 * kPi * static_cast<double>(n.q()));
        for (double t2 : {-7.0, -1.0, 0.0, 0.5, 3.0, 11.0, 123.0})
          for (int q : {1, 2, -1, 5}) {
            const double shifted = t2 + q * period;
            const double t3 = std::abs(n.value() * shifted) + 0.4;
            const double tol = 2 * kEps * (1 + std::abs(n.value())) * (std::abs(t2) + std::abs(q) * period) +
                               2 * kEps * t3 + 8 * kEps;
            INFO("a2 = " << a2 << " a3 = " << a3 << " n = " << n.str() << " theta2 = " << t2 << " periods " << q);
            CHECK(max_abs_diff(curve.point(shifted), curve.point(t2)) <= tol);
          }
        // And the period is the smallest: for q > 1 the curve has not closed after 2 pi.
        if (n.q() > 1) CHECK(max_abs_diff(curve.point(0.5 + 2 * kPi), curve.point(0.5)) > 1e-3);
      }
}

TEST_CASE("Eq. 8: a phase theta_p rotates the theta_p = 0 curve about Z1 by -theta_p/n", "[curve][eq8][phase]") {
  // Eqs. 6-8: P'(theta2) = R(-theta_p/n, Z1) P(theta2 + theta_p/n), where P' has theta3 =
  // n theta2 + theta_p and P has theta3 = n theta2. R is the report's matrix
  // [[c, s, 0], [-s, c, 0], [0, 0, 1]] with c = cos(theta_p/n), s = sin(theta_p/n).
  for (double a2 : kA2)
    for (double a3 : kA3)
      for (const Ratio& n : kRatios)
        for (double phase : {0.7, -kPi / 4, 2.0}) {
          const TracerCurve<double> with_phase(GearTrain(a2, a3, n, phase));
          const TracerCurve<double> zero_phase(GearTrain(a2, a3, n, 0.0));
          const double shift = phase / n.value();
          const double c = std::cos(shift), s = std::sin(shift);
          for (double t2 : {-5.0, -1.25, 0.0, 0.3, 1.0, 2.5, 6.0}) {
            const V3 p = zero_phase.point(t2 + shift);
            const V3 rotated(c * p.x() + s * p.y(), -s * p.x() + c * p.y(), p.z());
            // Error: rounding of t2 + shift and of n (t2 + shift) vs n t2 + theta_p, each of
            // relative eps, moving P by (1 + |n|) per radian.
            const double tol = 4 * kEps * (1 + std::abs(n.value())) * (1 + std::abs(t2) + std::abs(shift)) *
                               (1 + std::abs(n.value()));
            INFO("a2 = " << a2 << " a3 = " << a3 << " n = " << n.str() << " phase = " << phase << " theta2 = " << t2);
            CHECK(max_abs_diff(with_phase.point(t2), rotated) <= tol);
          }
        }
}

TEST_CASE("n = 1: z extremes at theta2 = pi and 0 (Eqs. 13-15)", "[curve][n1][eq14][eq15]") {
  for (double a2 : kA2)
    for (double a3 : kA3) {
      const TracerCurve<double> curve(GearTrain(a2, a3, Ratio(1)));
      const V3 zmax(0, std::sin(a2 - a3), std::cos(a2 - a3));   // Eq. 14
      const V3 zmin(0, -std::sin(a2 + a3), std::cos(a2 + a3));  // Eq. 15
      INFO("a2 = " << a2 << " a3 = " << a3);
      // double(pi) differs from pi by 1.2e-16; P moves by <= 2 per radian: 8 eps covers it.
      CHECK(max_abs_diff(curve.point(kPi), zmax) <= 8 * kEps);
      CHECK(max_abs_diff(curve.point(-kPi), zmax) <= 8 * kEps);
      CHECK(max_abs_diff(curve.point(0.0), zmin) <= 8 * kEps);
      // They are the extremes of z (Eq. 13: dz/dtheta2 = s theta2 sa2 sa3).
      for (int k = 0; k < 720; ++k) {
        const double z = curve.point(k * kPi / 360).z();
        CHECK(z <= zmax.z() + 4 * kEps);
        CHECK(z >= zmin.z() - 4 * kEps);
      }
    }
}

TEST_CASE("n = 1: the node (0, sin a3, cos a3) of Eq. 25 is reached at both theta2 = +-acos(Eq. 22b)",
          "[curve][n1][eq25][node]") {
  int cases = 0;
  for (double a2 : {kPi / 2, kPi / 3, 2 * kPi / 3, 1.0, 2.5})
    for (double a3 : {kPi / 2, kPi / 3, 2 * kPi / 3, kPi / 4, 1.2, 2.0}) {
      const double c = -std::sin(a2) * std::cos(a3) / (std::sin(a3) * (1 + std::cos(a2)));  // Eq. 22b
      // Eq. 24 (two real solutions); stay away from |c| = 1 where acos is ill-conditioned.
      if (!(a2 / 2 < a3 && a3 < kPi - a2 / 2) || std::abs(c) > 0.95) continue;
      ++cases;
      const V3 node(0, std::sin(a3), std::cos(a3));  // Eq. 25
      const TracerCurve<double> curve(GearTrain(a2, a3, Ratio(1)));
      const double t = std::acos(c);
      // acos(c) has error ~ eps / sqrt(1 - c^2) (<= 3.2 eps here); c itself ~4 eps; P moves by <= 2.
      const double tol = 2 * (4 * kEps / std::sqrt(1 - c * c) + 2 * kEps) + 4 * kEps;
      INFO("a2 = " << a2 << " a3 = " << a3 << " theta2 = +-" << t);
      CHECK(max_abs_diff(curve.point(t), node) <= tol);
      CHECK(max_abs_diff(curve.point(-t), node) <= tol);
      // The two branches are distinct parameter values (a true double point, t != 0, pi).
      CHECK(t > 1e-3);
      CHECK(t < kPi - 1e-3);
    }
  CHECK(cases >= 10);
  // Report Fig. 3 (a2 = a3 = pi/2): c = 0, node (0, 1, 0) at theta2 = +-pi/2.
  const TracerCurve<double> fig3(GearTrain(kPi / 2, kPi / 2, Ratio(1)));
  CHECK(max_abs_diff(fig3.point(kPi / 2), V3(0, 1, 0)) <= 8 * kEps);
  CHECK(max_abs_diff(fig3.point(-kPi / 2), V3(0, 1, 0)) <= 8 * kEps);
}

TEST_CASE("n = 1: the apex y and z of Eqs. 11/12 at theta2 from Eq. 27b", "[curve][n1][eq11][eq12]") {
  int cases = 0;
  for (double a2 : {kPi / 2, kPi / 3, 2 * kPi / 3, 1.0, 2.5})
    for (double a3 : {kPi / 2, kPi / 3, 2 * kPi / 3, kPi / 4, 1.2, 2.0, 0.4}) {
      const double ca2 = std::cos(a2), sa2 = std::sin(a2), ca3 = std::cos(a3), sa3 = std::sin(a3);
      const double c = -sa2 * ca3 / (2 * sa3 * (1 + ca2));  // Eq. 27b
      if (std::abs(c) > 0.95) continue;
      ++cases;
      const double za = 0.5 * ca3 * (1 + ca2);                    // Eq. 11
      const double ya = sa3 + ca3 * ca3 * (1 - ca2) / (4 * sa3);  // Eq. 12
      const TracerCurve<double> curve(GearTrain(a2, a3, Ratio(1)));
      const double t = std::acos(c);
      const double tol = 2 * (4 * kEps / std::sqrt(1 - c * c) + 2 * kEps) + 8 * kEps;
      INFO("a2 = " << a2 << " a3 = " << a3 << " theta2 = +-" << t);
      for (double s : {t, -t}) {
        const V3 p = curve.point(s);
        CHECK(std::abs(p.y() - ya) <= tol);
        CHECK(std::abs(p.z() - za) <= tol);
      }
      // The two apex points differ only in the sign of x (symmetry about the Y-Z plane).
      CHECK(std::abs(curve.point(t).x() + curve.point(-t).x()) <= tol);
      // y_a is the maximum of y (Eq. 12: "the maximum y-coordinate of the cylinder").
      for (int k = 0; k < 720; ++k) CHECK(curve.point(k * kPi / 360).y() <= ya + tol);
    }
  CHECK(cases >= 10);
}

TEST_CASE("n = 2: z extremes of Eqs. 32-35 at theta2 = -pi/2, pi/2, 0, pi", "[curve][n2][eq32][eq35]") {
  for (double a2 : kA2)
    for (double a3 : kA3) {
      const TracerCurve<double> curve(GearTrain(a2, a3, Ratio(2)));
      const double sm = std::sin(a2 - a3), cm = std::cos(a2 - a3), sp = std::sin(a2 + a3), cp = std::cos(a2 + a3);
      INFO("a2 = " << a2 << " a3 = " << a3);
      // double(pi/2) is off by 6e-17 and P moves by <= 3 per radian: 8 eps covers it.
      CHECK(max_abs_diff(curve.point(-kPi / 2), V3(-sm, 0, cm)) <= 8 * kEps);  // Eq. 32
      CHECK(max_abs_diff(curve.point(kPi / 2), V3(sm, 0, cm)) <= 8 * kEps);    // Eq. 33
      CHECK(max_abs_diff(curve.point(0.0), V3(0, -sp, cp)) <= 8 * kEps);       // Eq. 34
      CHECK(max_abs_diff(curve.point(kPi), V3(0, sp, cp)) <= 8 * kEps);        // Eq. 35
      for (int k = 0; k < 720; ++k) {
        const double z = curve.point(k * kPi / 360).z();
        CHECK(z <= cm + 4 * kEps);
        CHECK(z >= cp - 4 * kEps);
      }
    }
}

namespace {
/// Finite-difference set-up. h = 2^-17 (~7.6e-6) and theta2 on a dyadic grid, so theta2 +- h are
/// exact and the step is exactly 2h. Central-difference truncation error is h^2/6 |f'''|; each
/// component of P is a trig polynomial with coefficient sum <= 3 and frequencies <= 1 + |n|
/// (theta2, theta3, theta2 +- theta3), so |P'''| <= 3 (1 + |n|)^3 and |P''''| <= 3 (1 + |n|)^4.
/// Rounding: each P carries <= 4 eps from the products plus the theta3 rounding (<= 1.5 eps
/// |theta3|, Eq. 3 test), so the difference quotient carries <= 2 (4 + 1.5 |theta3|) eps / (2h).
/// With |theta2| <= 8 and |n| <= 3 that is ~1e-9 against a truncation of <= 2e-9: well below any
/// error a wrong formula would show (O(1)).
constexpr double kH = 1.0 / 131072.0;
double fd_tol(double nabs, double t3abs, int order) {
  const double deriv_bound = 3 * std::pow(1 + nabs, 2 + order);  // order 1: P''', order 2: (P')'''
  const double trunc = kH * kH / 6 * deriv_bound;
  const double round = std::pow(1 + nabs, order - 1) * (4 + 1.5 * t3abs) * kEps / kH;
  return 2 * (trunc + round);
}
}  // namespace

TEST_CASE("velocity equals a central difference of P and is omega x P (Eq. 47a)", "[curve][velocity]") {
  for (double a2 : kA2)
    for (double a3 : kA3)
      for (const Ratio& n : kRatios) {
        const TracerCurve<double> curve(GearTrain(a2, a3, n, 0.25));
        for (int k = -64; k <= 64; k += 3) {
          const double t2 = k / 8.0;
          const V3 fd = (curve.point(t2 + kH) - curve.point(t2 - kH)) / (2 * kH);
          const double t3 = std::abs(n.value() * t2) + 0.25;
          const V3 v = curve.velocity(t2);
          INFO("a2 = " << a2 << " a3 = " << a3 << " n = " << n.str() << " theta2 = " << t2);
          CHECK(max_abs_diff(v, fd) <= fd_tol(std::abs(n.value()), t3, 1));
          // omega x P with omega from Eq. 47a and P from Eq. 4, both computed here.
          const double t3s = static_cast<double>(n.p()) * t2 / static_cast<double>(n.q()) + 0.25;
          const V3 expected = eq47a(a2, n.value(), t2).cross(eq4(a2, a3, t2, t3s));
          CHECK(max_abs_diff(v, expected) <= 16 * kEps * (1 + std::abs(n.value())));
          // Tangent to the sphere.
          CHECK(std::abs(v.dot(curve.point(t2))) <= 8 * kEps * (1 + std::abs(n.value())));
        }
      }
}

TEST_CASE("acceleration equals a central difference of the velocity", "[curve][acceleration]") {
  for (double a2 : kA2)
    for (double a3 : kA3)
      for (const Ratio& n : kRatios) {
        const TracerCurve<double> curve(GearTrain(a2, a3, n, -0.5));
        for (int k = -64; k <= 64; k += 5) {
          const double t2 = k / 8.0;
          const V3 fd = (curve.velocity(t2 + kH) - curve.velocity(t2 - kH)) / (2 * kH);
          const double t3 = std::abs(n.value() * t2) + 0.5;
          INFO("a2 = " << a2 << " a3 = " << a3 << " n = " << n.str() << " theta2 = " << t2);
          CHECK(max_abs_diff(curve.acceleration(t2), fd) <= fd_tol(std::abs(n.value()), t3, 2));
          // d/dtheta2 (P . P) = 0 twice: P . A = -|V|^2.
          const V3 v = curve.velocity(t2);
          CHECK(std::abs(curve.point(t2).dot(curve.acceleration(t2)) + v.squaredNorm()) <=
                32 * kEps * std::pow(1 + std::abs(n.value()), 2));
        }
      }
}

TEST_CASE("screw axis omega = Z1 + n Z2 (Eq. 47a) keeps the angle a_s from Z1 and a_p from Z2",
          "[curve][screw_axis]") {
  for (double a2 : kA2)
    for (const Ratio& n : kRatios) {
      const GearTrain train(a2, 1.0, n);
      const TracerCurve<double> curve(train);
      const double as = train.sun_cone(), ap = train.planet_cone(), nv = n.value();
      INFO("a2 = " << a2 << " n = " << n.str() << " a_s = " << as << " a_p = " << ap);
      for (int k = -20; k <= 20; ++k) {
        const double t2 = k * 0.37;
        const V3 omega = curve.screw_axis(t2);
        CHECK(max_abs_diff(omega, eq47a(a2, nv, t2)) <= 4 * kEps * (1 + std::abs(nv)));
        // |omega| = sqrt(1 + n^2 + 2 n cos a2) (Sec. 6).
        const double mag = std::sqrt(1 + nv * nv + 2 * nv * std::cos(a2));
        CHECK(std::abs(omega.norm() - mag) <= 8 * kEps * (1 + std::abs(nv)));
        const V3 w = omega / omega.norm();
        const V3 z1 = V3::UnitZ();
        const V3 z2 = z2_axis(a2, t2);
        // The fixed axode: the sun's pitch cone, half-angle |a_s| about Z1 (a_s < 0 is internal gearing).
        // Both cosine and sine, so the check is well conditioned at every angle; 1/|omega| amplifies rounding.
        const double tol = 16 * kEps * (1 + std::abs(nv)) / mag;
        CHECK(std::abs(w.dot(z1) - std::cos(as)) <= tol);
        CHECK(std::abs(w.cross(z1).norm() - std::abs(std::sin(as))) <= tol);
        // The moving axode: the planet's pitch cone, half-angle a_p about Z2.
        CHECK(std::abs(w.dot(z2) - std::cos(ap)) <= tol);
        CHECK(std::abs(w.cross(z2).norm() - std::sin(ap)) <= tol);
      }
    }
}

TEST_CASE("tracer on the pitch cone: the speed vanishes exactly at theta3 = pi (mod 2 pi)", "[curve][cusp]") {
  // Derivation: in carrier coordinates omega = (0, sin a2, cos a2 + n) (Eq. 47b), whose angle from
  // Z2 is a_p, so omega = |omega| (0, sin a_p, cos a_p). The tracer in carrier coordinates is
  // (s3 sa3, -c3 sa3, ca3) (Eq. 4, right factor). With a3 = a_p and theta3 = pi it is
  // (0, sin a_p, cos a_p), parallel to omega, so dP/dtheta2 = omega x P = 0. With a3 = pi - a_p
  // the same happens at theta3 = 0 (P = -omega/|omega|). Elsewhere the angle between P and omega
  // is nonzero and |v| = |omega| sin(angle); at theta3 = 0 on the pitch cone the angle is 2 a_p.
  for (double a2 : {0.3, kPi / 3, kPi / 2, 2.0, 2.8})
    for (const Ratio& n : kRatios)
      for (double phase : {0.0, 0.6}) {
        const GearTrain on = GearTrain::on_cone(a2, A3Reference::pitch_cone, 0.0, n, phase);
        const GearTrain mirror = GearTrain::on_cone(a2, A3Reference::mirror_pitch_cone, 0.0, n, phase);
        const TracerCurve<double> c_on(on), c_mirror(mirror);
        const double nv = n.value(), ap = on.planet_cone();
        const double mag = std::sqrt(1 + nv * nv + 2 * nv * std::cos(a2));
        INFO("a2 = " << a2 << " n = " << n.str() << " phase = " << phase);
        for (int k = -3; k <= 3; ++k) {
          // theta3 = n theta2 + theta_p = (2k + 1) pi  =>  theta2 = ((2k + 1) pi - theta_p) / n.
          const double t_cusp = ((2 * k + 1) * kPi - phase) / nv;
          const double t_mirror_cusp = (2 * k * kPi - phase) / nv;
          // theta2 is rounded (|theta2| eps) and theta3 again (|theta3| eps); |dv/dtheta| <= |omega|
          // (|omega| + 1) per radian: tol = 4 eps (1 + |n|)^2 (1 + |theta2| + |theta3|).
          const double tol = 4 * kEps * std::pow(1 + std::abs(nv), 2) * (1 + std::abs(t_cusp) * (1 + std::abs(nv)));
          CHECK(c_on.velocity(t_cusp).norm() <= tol);
          CHECK(c_mirror.velocity(t_mirror_cusp).norm() <= tol);
          // Half a planet turn away the speed is |omega| sin(2 a_p), far from zero.
          const double t_far = (2 * k * kPi - phase) / nv;
          CHECK(std::abs(c_on.velocity(t_far).norm() - mag * std::abs(std::sin(2 * ap))) <= 1e-12);
        }
      }
}
