// sphtroch/exact/precision_points.hpp — every gear train of ratio n whose tracer passes through
// three given points (fixed frame: the sun axis is Z of the points' frame), certified.
//
//   const sphtroch::TracerCurve<double> curve(sphtroch::GearTrain(1.0, 2.0, sphtroch::Ratio(1, 2), 0.3));
//   std::vector<sphtroch::Vector3d> pts = {curve.point(0.5), curve.point(2.0), curve.point(7.0)};
//   sphtroch::PrecisionPoints r = sphtroch::precision_points(pts, sphtroch::Ratio(1, 2));
//   r.certified;               // true: r.solutions are all the trains, each isolated (see below)
//   r.solutions[0].train;      // a2, a3, n, phase in [0, 2 pi / q)
//   r.solutions[0].params;     // theta2 at each point, in input order, in [0, 2 pi q)
//
// Unknowns (derivation ours, from Eqs. 3 and 4). In the carrier frame the tracer is
// Q(theta2) = Rx(-a2) Rz(-theta2) P = Rz(theta3) Rx(a3) z: the planet's point turned by
// theta3 = n theta2 + theta_p. So with theta_1 the carrier angle at point 1 and
// Delta_i = theta_i - theta_1, the train passes through P_1, P_2, P_3 exactly when
//     Q(a2, theta_1 + Delta_i; P_i) = Rz(n Delta_i) Q(a2, theta_1; P_1)     (i = 2, 3);
// a3 = acos(Q_1z) and theta_p = atan2(Q_1x, -Q_1y) - n theta_1 follow. Both sides are unit
// vectors, so each i gives two equations: f = Q_iz - W_z = 0 and g = (Q_i x W)_z = 0, with W
// the right side, plus the sign condition Q_i . W > 0. Four regular equations in the four
// unknowns x = (a2, theta_1, Delta_2, Delta_3) in [1e-6, pi - 1e-6] x [0, 2 pi] x [0, 2 pi q]^2
// (theta_1's domain overlapping itself a little at both ends, so no root sits on its edge):
// no arccos of z, so nothing folds at the z-extremes. The curve is the same set for theta_p and
// theta_p + 2 pi / q; shifting every theta_i by 2 pi k is that change, hence theta_1 in [0, 2 pi]
// (searched over [-1/16, 2 pi + 1/16], boxes wholly outside [0, 2 pi] dropped: no root on an edge).
//
// Certificate. Branch and bound over boxes of x in interval arithmetic (CGAL::Interval_nt; sin
// and cos from interval_trig.hpp). A box is discarded when f, g or the sign condition excludes
// zero on it (point 2 and point 3 are pruned separately over their own Delta). A small box is
// given to the Krawczyk operator K(X) = y - Y F(y) + (I - Y J(X)) (X - y): K(X) inside X proves
// exactly one root in X (it is then polished by Newton); K(X) disjoint from X proves none.
// `certified` means every box ended one of these ways: the solutions are ALL the trains through
// the points with a2, a3 in [1e-6, pi - 1e-6], none twice. Otherwise (a box below kMinBoxWidth
// still undecided — a singular root, e.g. a point exactly at a cusp — or more than max_boxes
// boxes) the solutions found are returned with certified = false and the count of undecided boxes.
// Cost: grows with q (Delta spans 2 pi q); measured in bench/ and the README.
#pragma once

#if !defined(SPHTROCH_HAVE_EXACT)
#error "sphtroch/exact/precision_points.hpp needs CGAL: link the CMake target sphtroch::exact"
#endif

#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/core/types.hpp"
#include "sphtroch/exact/interval_trig.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <string>
#include <vector>

namespace sphtroch {

/// Input points must be unit vectors to this, and no two closer than kDistinctPoints (chord).
constexpr double kPrecisionUnitTolerance = 1e-6;
constexpr double kDistinctPoints = 1e-9;
/// A box narrower than this (radians, Delta scaled by 1 + |n|) that is still undecided is
/// reported as such: the result is then not certified.
constexpr double kMinBoxWidth = 1e-11;
/// A train from an undecided box is listed (isolated = false) only if it passes the points to this.
constexpr double kUnisolatedResidual = 1e-12;

struct PrecisionPointsOptions {
  std::size_t max_boxes = 4000000;  // work bound: beyond it the result is returned uncertified
};

struct PrecisionSolution {
  GearTrain train;               // phase reduced to [0, 2 pi / q)
  std::vector<double> params;    // theta2 at each point (input order), in [0, 2 pi q)
  double residual = 0.0;         // max |P(params[i]) - points[i]| (chord), measured in double
  /// false: Newton's limit in a box the certificate could not decide (a near-singular root, e.g.
  /// two roots closer than the arithmetic resolves); it passes the points (residual <= 1e-12)
  /// but is not proven to be a single root, and the list is then not certified.
  bool isolated = true;
};

struct PrecisionPoints {
  std::vector<PrecisionSolution> solutions;  // by a2, then a3
  bool certified = true;         // every box was excluded or isolated one root (see header)
  std::size_t undecided = 0;     // boxes left undecided (0 when certified)
  std::size_t boxes = 0;         // boxes examined (the work)
};

/// All trains of ratio n through the three points (fixed frame). Throws InvalidInput (field
/// "points") for a count other than 3, non-finite or non-unit points, or two points closer than
/// kDistinctPoints.
inline PrecisionPoints precision_points(const std::vector<Vector3d>& points, const Ratio& n,
                                        const PrecisionPointsOptions& options = {});

namespace precision_detail {

using Box = std::array<Interval, 4>;  // a2, theta_1, Delta_2, Delta_3

/// Q = Rx(-a2) Rz(-theta) P and its derivatives by theta and by a2.
template <typename T>
struct CarrierView {
  T q[3];
  T d_theta[3];  // (r2, -cos a2 r1, sin a2 r1)
  T d_a2[3];     // (0, q_z, -q_y)
};

/// {sin, cos} of one angle (interval_trig.hpp).
template <typename T>
using SinCos = std::pair<T, T>;

template <typename T>
CarrierView<T> carrier_view(const T& ca, const T& sa, const SinCos<T>& theta, const Vector3d& p) {
  const T &s = theta.first, &c = theta.second;
  const T r1 = c * p.x() + s * p.y();
  const T r2 = c * p.y() - s * p.x();
  CarrierView<T> v{{r1, ca * r2 + sa * p.z(), ca * p.z() - sa * r2},
                   {r2, -(ca * r1), sa * r1},
                   {T(0.0), T(0.0), T(0.0)}};
  v.d_a2[1] = v.q[2];
  v.d_a2[2] = -v.q[1];
  return v;
}

/// f, g and the sign condition of one point (see header), with their derivatives by
/// (a2, theta_1, Delta) when `jacobian` is set.
template <typename T>
struct PointEquations {
  T f, g, dot;
  T df[3], dg[3];
};

/// theta_i = theta_1 + Delta and n Delta enter through their sines and cosines.
template <typename T>
PointEquations<T> point_equations(const T& ca, const T& sa, const CarrierView<T>& q1, const SinCos<T>& theta_i,
                                  const SinCos<T>& n_delta, const T& n, const Vector3d& p, bool jacobian) {
  const CarrierView<T> qi = carrier_view(ca, sa, theta_i, p);
  const T &s = n_delta.first, &c = n_delta.second;
  const T wx = c * q1.q[0] - s * q1.q[1], wy = s * q1.q[0] + c * q1.q[1];
  PointEquations<T> e;
  e.f = qi.q[2] - q1.q[2];
  e.g = qi.q[0] * wy - qi.q[1] * wx;
  e.dot = qi.q[0] * wx + qi.q[1] * wy;
  if (!jacobian) return e;
  const T dwx[3] = {-(s * q1.q[2]), c * q1.d_theta[0] - s * q1.d_theta[1], -(n * wy)};
  const T dwy[3] = {c * q1.q[2], s * q1.d_theta[0] + c * q1.d_theta[1], n * wx};
  const T dqx[3] = {T(0.0), qi.d_theta[0], qi.d_theta[0]};
  const T dqy[3] = {qi.q[2], qi.d_theta[1], qi.d_theta[1]};
  e.df[0] = qi.d_a2[2] - q1.d_a2[2];
  e.df[1] = qi.d_theta[2] - q1.d_theta[2];
  e.df[2] = qi.d_theta[2];
  for (int k = 0; k < 3; ++k) e.dg[k] = dqx[k] * wy + qi.q[0] * dwy[k] - dqy[k] * wx - qi.q[1] * dwx[k];
  return e;
}

/// The problem: three points and the ratio, with the interval and double forms of n.
struct Problem {
  Vector3d p[3];
  Ratio ratio;
  Interval n_interval;
  double n_value;
  double delta_scale;  // 1 + |n|: Delta's widths are compared after this factor
  double delta_max;    // 2 pi q
};

inline bool may_vanish(const Interval& x) { return x.inf() <= 0.0 && x.sup() >= 0.0; }

inline Interval centre_of(const Interval& x) { return Interval(0.5 * (x.inf() + x.sup())); }

/// Point 1 seen from the carrier over a box of (a2, theta_1) and at its centre: what every Delta
/// interval of the box shares (computed once per box).
struct BoxView {
  Interval a2, theta1, ca, sa;
  CarrierView<Interval> q1;
  Interval a2_centre, theta1_centre, ca_centre, sa_centre;
  CarrierView<Interval> q1_centre;
};

inline BoxView box_view(const Problem& pr, const Interval& a2, const Interval& theta1) {
  const Interval a2c = centre_of(a2), t1c = centre_of(theta1);
  const auto trig = interval_sincos_all<4>({a2, theta1, a2c, t1c});
  const Interval &sa = trig[0].first, &ca = trig[0].second, &sac = trig[2].first, &cac = trig[2].second;
  return {a2, theta1, ca, sa, carrier_view(ca, sa, trig[1], pr.p[0]),
          a2c, t1c, cac, sac, carrier_view(cac, sac, trig[3], pr.p[0])};
}

/// Whether point i (1 or 2) may satisfy its equations on (a2, theta_1) x delta.
inline bool point_may_hold(const Problem& pr, const BoxView& v, const Interval& delta, int i) {
  const Interval dc = centre_of(delta);
  const auto trig = interval_sincos_all<4>({v.theta1 + delta, pr.n_interval * delta, v.theta1_centre + dc,
                                            pr.n_interval * dc});
  const auto e = point_equations(v.ca, v.sa, v.q1, trig[0], trig[1], pr.n_interval, pr.p[i], true);
  if (!(may_vanish(e.f) && may_vanish(e.g) && e.dot.sup() > 0.0)) return false;
  // Mean-value form F(X) in F(c) + J(X) (X - c): much tighter than the plain one on small boxes.
  const auto ec = point_equations(v.ca_centre, v.sa_centre, v.q1_centre, trig[2], trig[3], pr.n_interval, pr.p[i], false);
  const Interval dx[3] = {v.a2 - v.a2_centre, v.theta1 - v.theta1_centre, delta - dc};
  Interval f = ec.f, g = ec.g;
  for (int k = 0; k < 3; ++k) {
    f += e.df[k] * dx[k];
    g += e.dg[k] * dx[k];
  }
  return may_vanish(f) && may_vanish(g);
}

/// F(x) and J(x) in type T (double at the centre, Interval over a box).
template <typename T>
void equations(const Problem& pr, const std::array<T, 4>& x, const T& n, std::array<T, 4>& f,
               std::array<std::array<T, 4>, 4>& jac, bool jacobian) {
  const auto trig = interval_sincos_all(std::array<T, 6>{x[0], x[1], T(x[1] + x[2]), T(n * x[2]), T(x[1] + x[3]), T(n * x[3])});
  const T &sa = trig[0].first, &ca = trig[0].second;
  const CarrierView<T> q1 = carrier_view(ca, sa, trig[1], pr.p[0]);
  for (int i = 0; i < 2; ++i) {
    const auto e = point_equations(ca, sa, q1, trig[2 + 2 * i], trig[3 + 2 * i], n, pr.p[1 + i], jacobian);
    f[2 * i] = e.f;
    f[2 * i + 1] = e.g;
    if (!jacobian) continue;
    for (int r = 0; r < 2; ++r) {
      const T* d = r == 0 ? e.df : e.dg;
      jac[2 * i + r] = {d[0], d[1], T(0.0), T(0.0)};
      jac[2 * i + r][2 + i] = d[2];
    }
  }
}

inline Eigen::Matrix4d to_matrix(const std::array<std::array<double, 4>, 4>& a) {
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m(r, c) = a[r][c];
  return m;
}

inline std::array<double, 4> centre(const Box& x) {
  std::array<double, 4> y{};
  for (int k = 0; k < 4; ++k) y[k] = 0.5 * (x[k].inf() + x[k].sup());
  return y;
}

/// Y = J(y)^-1 in doubles (any approximate inverse keeps the interval tests valid); none if singular.
inline std::optional<Eigen::Matrix4d> inverse_jacobian(const Problem& pr, const std::array<double, 4>& y) {
  std::array<double, 4> f{};
  std::array<std::array<double, 4>, 4> jac{};
  equations(pr, y, pr.n_value, f, jac, true);
  const Eigen::FullPivLU<Eigen::Matrix4d> lu(to_matrix(jac));
  if (!lu.isInvertible()) return std::nullopt;
  return Eigen::Matrix4d(lu.inverse());
}

/// Outcome of the Krawczyk test on a box.
enum class KrawczykOutcome { unique_root, no_root, undecided };

inline double scaled_width(const Problem& pr, const Box& x, int k) {
  const double w = x[k].sup() - x[k].inf();
  return k >= 2 ? w * pr.delta_scale : w;
}

/// K(X) = y - Y F(y) + (I - Y J(X)) (X - y) with y the centre of X and Y ~ J(y)^-1 (see header).
/// On `undecided` x is narrowed to X intersected with K(X).
inline KrawczykOutcome krawczyk(const Problem& pr, Box& x) {
  const std::array<double, 4> y = centre(x);
  const auto inverse = inverse_jacobian(pr, y);
  if (!inverse) return KrawczykOutcome::undecided;
  const Eigen::Matrix4d& inv = *inverse;
  std::array<Interval, 4> yi{}, fy{}, fx{};
  std::array<std::array<Interval, 4>, 4> jx{}, unused{};
  for (int k = 0; k < 4; ++k) yi[k] = Interval(y[k]);
  equations(pr, yi, pr.n_interval, fy, unused, false);
  equations(pr, x, pr.n_interval, fx, jx, true);
  bool inside = true;
  Box k_box;
  for (int r = 0; r < 4; ++r) {
    Interval s(y[r]);
    for (int m = 0; m < 4; ++m) s -= inv(r, m) * fy[m];
    for (int c = 0; c < 4; ++c) {
      Interval a(r == c ? 1.0 : 0.0);
      for (int m = 0; m < 4; ++m) a -= inv(r, m) * jx[m][c];
      s += a * (x[c] - y[c]);
    }
    if (s.sup() < x[r].inf() || s.inf() > x[r].sup()) return KrawczykOutcome::no_root;
    inside = inside && s.inf() > x[r].inf() && s.sup() < x[r].sup();
    k_box[r] = s;
  }
  if (inside) return KrawczykOutcome::unique_root;
  for (int r = 0; r < 4; ++r)
    x[r] = Interval(std::max(x[r].inf(), k_box[r].inf()), std::min(x[r].sup(), k_box[r].sup()));
  return KrawczykOutcome::undecided;
}

/// p^-1 modulo q (gcd(p, q) = 1, q >= 1).
inline std::int64_t inverse_mod(std::int64_t p, std::int64_t q) {
  std::int64_t a = ((p % q) + q) % q, b = q, x0 = 1, x1 = 0;
  while (b != 0) {
    const std::int64_t t = a / b;
    std::swap(a -= t * b, b);
    std::swap(x0 -= t * x1, x1);
  }
  return ((x0 % q) + q) % q;
}

/// One Newton step at y in doubles: the correction J(y)^-1 F(y) (non-finite if J is singular).
inline Eigen::Vector4d newton_step(const Problem& pr, const std::array<double, 4>& y) {
  std::array<double, 4> f{};
  std::array<std::array<double, 4>, 4> jac{};
  equations(pr, y, pr.n_value, f, jac, true);
  return to_matrix(jac).fullPivLu().solve(Eigen::Vector4d(f[0], f[1], f[2], f[3]));
}

/// Newton from the centre of a box holding exactly one root (REQUIRES: Krawczyk said so).
inline std::array<double, 4> polish(const Problem& pr, const Box& x) {
  std::array<double, 4> y = centre(x);
  for (int step = 0; step < 8; ++step) {
    const Eigen::Vector4d dy = newton_step(pr, y);
    if (!dy.allFinite()) break;
    for (int k = 0; k < 4; ++k) y[k] = std::clamp(y[k] - dy(k), x[k].inf(), x[k].sup());
  }
  return y;
}

/// Newton in doubles from the centre of x; its limit if it converged inside x.
inline std::optional<std::array<double, 4>> newton_in(const Problem& pr, const Box& x) {
  std::array<double, 4> y = centre(x);
  for (int step = 0; step < 12; ++step) {
    const Eigen::Vector4d dy = newton_step(pr, y);
    if (!dy.allFinite()) return std::nullopt;
    for (int k = 0; k < 4; ++k) y[k] -= dy(k);
    if (dy.cwiseAbs().maxCoeff() < 1e-13) break;
  }
  for (int k = 0; k < 4; ++k)
    if (!(y[k] >= x[k].inf() && y[k] <= x[k].sup())) return std::nullopt;
  return y;
}

/// Whether ||I - Y J(U)||_inf < 1 with Y = J(y)^-1 (interval J over the box U).
inline bool contraction_holds(const Problem& pr, const std::array<double, 4>& y, const Box& u) {
  const auto inverse = inverse_jacobian(pr, y);
  if (!inverse) return false;
  const Eigen::Matrix4d& inv = *inverse;
  std::array<Interval, 4> fu{};
  std::array<std::array<Interval, 4>, 4> ju{};
  equations(pr, u, pr.n_interval, fu, ju, true);
  for (int r = 0; r < 4; ++r) {
    double row = 0.0;
    for (int c = 0; c < 4; ++c) {
      Interval a(r == c ? 1.0 : 0.0);
      for (int m = 0; m < 4; ++m) a -= inv(r, m) * ju[m][c];
      row += std::max(-a.inf(), a.sup());  // rounding upward: an upper bound of the sum
    }
    if (!(row < 1.0)) return false;
  }
  return true;
}

/// Branch and bound over (a2, theta_1) with, per point, the list of Delta intervals still
/// possible; small boxes go to the Krawczyk test in all four unknowns (see header).
class PointsSolver {
 public:
  PointsSolver(const Problem& problem, const PrecisionPointsOptions& options)
      : pr_(problem), options_(options) {}

  PrecisionPoints run() {
    // theta_1 is periodic: the domain overlaps itself by kTheta1Overlap at both ends, so that a
    // root at theta_1 = 0 (a point at the trace's first sample) lies inside it, not on an edge a
    // box cannot be certified across; its copy at 2 pi is the same train (is_new drops it), and
    // boxes wholly outside [0, 2 pi] are dropped (step()).
    Node all{Interval(kMinCarrierTwist, Constants<double>::pi() - kMinCarrierTwist),
             Interval(-kTheta1Overlap, 2 * Constants<double>::pi() + kTheta1Overlap), {}};
    for (auto& d : all.delta) d.push_back(Interval(0.0, pr_.delta_max));
    std::vector<Node> stack{all};
    {
      const RoundingGuard upward;  // the interval arithmetic's mode; doubles here are estimates only
      while (!stack.empty()) {
        if (over_budget()) {
          result_.undecided += stack.size();
          break;
        }
        Node node = std::move(stack.back());
        stack.pop_back();
        step(std::move(node), stack);
      }
    }
    finish();  // in the caller's rounding mode
    return result_;
  }

 private:
  /// Widths at which the outer loop hands its boxes to the Krawczyk test.
  static constexpr double kIsolateWidth = 1.0 / 64;
  /// How far the theta_1 domain reaches past each end of [0, 2 pi] (see run()).
  static constexpr double kTheta1Overlap = 1.0 / 16;

  struct Node {
    Interval a2, theta1;
    std::vector<Interval> delta[2];
  };

  bool over_budget() const { return result_.boxes >= options_.max_boxes; }

  void step(Node node, std::vector<Node>& stack) {
    // A box wholly outside [0, 2 pi] in theta_1 holds only copies of roots inside it (see run()):
    // dropped, so that a root on the overlap's own edge is never left undecided there.
    if (node.theta1.sup() < 0.0 || node.theta1.inf() > 2 * Constants<double>::pi()) return;
    ++result_.boxes;
    const BoxView view = box_view(pr_, node.a2, node.theta1);
    for (int i = 0; i < 2; ++i) {
      auto& list = node.delta[i];
      list.erase(std::remove_if(list.begin(), list.end(),
                                [&](const Interval& d) { return !point_may_hold(pr_, view, d, i + 1); }),
                 list.end());
      if (list.empty()) return;
    }
    const double wb = std::max(node.a2.sup() - node.a2.inf(), node.theta1.sup() - node.theta1.inf());
    if (split_deltas(node, std::max(wb, kIsolateWidth))) {
      stack.push_back(std::move(node));
    } else if (wb <= kIsolateWidth) {
      for (const Interval& d2 : merge_runs(node.delta[0]))
        for (const Interval& d3 : merge_runs(node.delta[1])) isolate(Box{node.a2, node.theta1, d2, d3});
    } else {
      Node other = node;
      const bool by_a2 = node.a2.sup() - node.a2.inf() >= node.theta1.sup() - node.theta1.inf();
      Interval& mine = by_a2 ? node.a2 : node.theta1;
      Interval& theirs = by_a2 ? other.a2 : other.theta1;
      const double mid = 0.5 * (mine.inf() + mine.sup());
      mine = Interval(mine.inf(), mid);
      theirs = Interval(mid, theirs.sup());
      stack.push_back(std::move(other));
      stack.push_back(std::move(node));
    }
  }

  /// Adjacent intervals (in order, each starting where the last ended) joined into one.
  static std::vector<Interval> merge_runs(const std::vector<Interval>& list) {
    std::vector<Interval> runs;
    for (const Interval& d : list) {
      if (!runs.empty() && runs.back().sup() == d.inf())
        runs.back() = Interval(runs.back().inf(), d.sup());
      else
        runs.push_back(d);
    }
    return runs;
  }

  /// Splits every Delta interval wider (scaled) than `width` into equal pieces no wider.
  bool split_deltas(Node& node, double width) const {
    bool split = false;
    for (auto& list : node.delta) {
      std::vector<Interval> out;
      for (const Interval& d : list) {
        const double w = (d.sup() - d.inf()) * pr_.delta_scale;
        const auto pieces = static_cast<std::size_t>(std::ceil(w / width));
        if (pieces <= 1) {
          out.push_back(d);
          continue;
        }
        split = true;
        const double step = (d.sup() - d.inf()) / static_cast<double>(pieces);
        for (std::size_t k = 0; k < pieces; ++k)
          out.push_back(Interval(k == 0 ? d.inf() : d.inf() + step * static_cast<double>(k),
                                 k + 1 == pieces ? d.sup() : d.inf() + step * static_cast<double>(k + 1)));
      }
      list = std::move(out);
    }
    return split;
  }

  bool excluded(const Box& x) const {
    const BoxView view = box_view(pr_, x[0], x[1]);
    return !point_may_hold(pr_, view, x[2], 1) || !point_may_hold(pr_, view, x[3], 2);
  }

  /// Krawczyk with bisection on one box of all four unknowns. A root found by Newton is
  /// certified in a tiny box, and the largest box around it where ||I - Y J(U)|| < 1 (so that it
  /// is the only root there) is remembered: boxes inside such a region need no more work.
  void isolate(const Box& start) {
    std::vector<Box> stack{start};
    while (!stack.empty()) {
      if (over_budget()) {
        result_.undecided += stack.size();
        return;
      }
      Box x = stack.back();
      stack.pop_back();
      ++result_.boxes;
      if (in_known_region(x) || excluded(x)) continue;
      const KrawczykOutcome outcome = krawczyk(pr_, x);
      if (outcome == KrawczykOutcome::no_root) continue;
      if (outcome == KrawczykOutcome::unique_root) {
        roots_.push_back(x);
        regions_.push_back(x);
        continue;
      }
      if (certify_newton_root(x) && in_known_region(x)) continue;
      bisect(x, stack);
    }
  }

  void bisect(Box x, std::vector<Box>& stack) {
    int widest = 0;
    for (int k = 1; k < 4; ++k)
      if (scaled_width(pr_, x, k) > scaled_width(pr_, x, widest)) widest = k;
    if (scaled_width(pr_, x, widest) < kMinBoxWidth) {
      ++result_.undecided;
      undecided_.push_back(x);
      return;
    }
    Box other = x;
    const double mid = 0.5 * (x[widest].inf() + x[widest].sup());
    x[widest] = Interval(x[widest].inf(), mid);
    other[widest] = Interval(mid, other[widest].sup());
    stack.push_back(other);
    stack.push_back(x);
  }

  bool in_known_region(const Box& x) const {
    for (const Box& u : regions_) {
      bool inside = true;
      for (int k = 0; k < 4 && inside; ++k) inside = x[k].inf() >= u[k].inf() && x[k].sup() <= u[k].sup();
      if (inside) return true;
    }
    return false;
  }

  /// Newton from the centre of x; a limit inside x not yet known is certified (Krawczyk on a box
  /// of 1e-10 around it) and given its uniqueness region. Returns whether a region was added.
  bool certify_newton_root(const Box& x) {
    const auto y = newton_in(pr_, x);
    if (!y) return false;
    Box tiny;
    for (int k = 0; k < 4; ++k) tiny[k] = around(*y, k, 1e-10);
    for (const Box& u : regions_)
      if (contains(u, tiny)) return false;
    if (krawczyk(pr_, tiny) != KrawczykOutcome::unique_root) return false;
    roots_.push_back(tiny);
    regions_.push_back(uniqueness_region(*y, tiny));
    return true;
  }

  Interval around(const std::array<double, 4>& y, int k, double radius) const {
    const double r = k >= 2 ? radius / pr_.delta_scale : radius;
    return Interval(y[k] - r, y[k] + r);
  }

  static bool contains(const Box& outer, const Box& inner) {
    for (int k = 0; k < 4; ++k)
      if (inner[k].inf() < outer[k].inf() || inner[k].sup() > outer[k].sup()) return false;
    return true;
  }

  /// The largest box y +- r (r = 1e-9 2^j <= 0.25, scaled) with ||I - Y J(U)||_inf < 1, Y = J(y)^-1: by the
  /// mean value theorem two roots in U would be equal. At least `tiny`.
  Box uniqueness_region(const std::array<double, 4>& y, const Box& tiny) const {
    Box best = tiny;
    for (double r = 1e-9; r <= 0.25; r *= 2) {
      Box u;
      for (int k = 0; k < 4; ++k) u[k] = around(y, k, r);
      if (!contraction_holds(pr_, y, u)) break;
      best = u;
    }
    return best;
  }

  void finish() {
    for (const Box& x : roots_) add_solution(polish(pr_, x), true);
    for (const Box& x : undecided_) add_solution(polish(pr_, x), false);
    std::sort(result_.solutions.begin(), result_.solutions.end(), [](const auto& a, const auto& b) {
      return std::make_pair(a.train.a2(), a.train.a3()) < std::make_pair(b.train.a2(), b.train.a3());
    });
    result_.certified = result_.undecided == 0;
  }

  /// The train of a root (a3, phase reduced to [0, 2 pi / q), params in [0, 2 pi q)), unless it is
  /// a root of the sign-reversed system, lies outside the a3 range, or repeats a solution.
  void add_solution(const std::array<double, 4>& y, bool isolated) {
    const double two_pi = 2 * Constants<double>::pi();
    const std::int64_t q = pr_.ratio.q();
    const double ca = std::cos(y[0]), sa = std::sin(y[0]);
    const CarrierView<double> q1 = carrier_view(ca, sa, interval_sincos(y[1]), pr_.p[0]);
    for (int i = 0; i < 2; ++i) {
      const auto e = point_equations(ca, sa, q1, interval_sincos(y[1] + y[2 + i]), interval_sincos(pr_.n_value * y[2 + i]),
                                     pr_.n_value, pr_.p[1 + i], false);
      if (!(e.dot > 0.0)) return;
    }
    const double a3 = std::acos(std::clamp(q1.q[2], -1.0, 1.0));
    if (!(a3 >= kMinCarrierTwist && a3 <= Constants<double>::pi() - kMinCarrierTwist)) return;
    const double phase = std::atan2(q1.q[0], -q1.q[1]) - pr_.n_value * y[1];
    const double sector = two_pi / static_cast<double>(q);
    const double m = std::floor(phase / sector);
    const std::int64_t m_mod = static_cast<std::int64_t>(std::fmod(std::fmod(m, double(q)) + double(q), double(q)));
    const std::int64_t k = (m_mod * inverse_mod(pr_.ratio.p(), q)) % q;
    PrecisionSolution s{GearTrain(y[0], a3, pr_.ratio, phase - m * sector), {}, 0.0, isolated};
    const double shift = two_pi * static_cast<double>(k);
    for (const double t : {y[1], y[1] + y[2], y[1] + y[3]}) {
      const double period = two_pi * static_cast<double>(q);
      s.params.push_back(std::fmod(std::fmod(t + shift, period) + period, period));
    }
    const TracerCurve<double> curve(s.train);
    for (int i = 0; i < 3; ++i) s.residual = std::max(s.residual, (curve.point(s.params[i]) - pr_.p[i]).norm());
    if (!is_new(s) || (!isolated && !(s.residual <= kUnisolatedResidual))) return;
    result_.solutions.push_back(std::move(s));
  }

  /// Two roots whose trains agree to 1e-9 (phase modulo 2 pi / q) are one train met twice (a
  /// root on a shared face of two boxes, or a point that is a node of the curve).
  bool is_new(const PrecisionSolution& s) const {
    const double sector = 2 * Constants<double>::pi() / static_cast<double>(pr_.ratio.q());
    for (const auto& t : result_.solutions) {
      const double dp = std::fabs(std::remainder(t.train.phase_given() - s.train.phase_given(), sector));
      if (std::fabs(t.train.a2() - s.train.a2()) < 1e-9 && std::fabs(t.train.a3() - s.train.a3()) < 1e-9 && dp < 1e-9)
        return false;
    }
    return true;
  }

  const Problem& pr_;
  PrecisionPointsOptions options_;
  PrecisionPoints result_;
  std::vector<Box> roots_;    // each holds exactly one root
  std::vector<Box> regions_;  // each holds at most one root, one of roots_
  std::vector<Box> undecided_;  // narrower than kMinBoxWidth, still undecided
};

inline Problem make_problem(const std::vector<Vector3d>& points, const Ratio& n) {
  if (points.size() != 3)
    throw InvalidInput("points", std::to_string(points.size()) + " points", "a fixed-frame problem needs exactly 3",
                       "3 points x,y,z on the unit sphere");
  const Interval n_interval = [&] {
    const RoundingGuard upward;
    return Interval(double(n.p())) / Interval(double(n.q()));
  }();
  Problem pr{{}, n, n_interval, n.value(),
             1.0 + std::fabs(n.value()), 2 * Constants<double>::pi() * double(n.q())};
  for (std::size_t i = 0; i < 3; ++i) {
    const Vector3d& p = points[i];
    const double norm = p.norm();
    if (!std::isfinite(norm) || std::fabs(norm - 1.0) > kPrecisionUnitTolerance)
      throw InvalidInput("points", "point " + std::to_string(i + 1) + " with |P| = " + number_text(norm),
                         "not on the unit sphere", "|P| within 1e-6 of 1");
    pr.p[i] = p / norm;
    for (std::size_t j = 0; j < i; ++j)
      if ((pr.p[i] - pr.p[j]).norm() < kDistinctPoints)
        throw InvalidInput("points", "points " + std::to_string(j + 1) + " and " + std::to_string(i + 1),
                           "the same point twice", "distinct points (chord >= 1e-9)");
  }
  return pr;
}

}  // namespace precision_detail

inline PrecisionPoints precision_points(const std::vector<Vector3d>& points, const Ratio& n,
                                        const PrecisionPointsOptions& options) {
  const precision_detail::Problem problem = precision_detail::make_problem(points, n);
  return precision_detail::PointsSolver(problem, options).run();
}

}  // namespace sphtroch
