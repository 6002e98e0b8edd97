// sphtroch/synthesis/precision_points.hpp — every gear train of ratio n whose tracer passes through
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
// and cos from interval.hpp; the engine is root_isolation.hpp). A box is discarded when
// f, g or the sign condition excludes zero on it (point 2 and point 3 are pruned separately over
// their own Delta). A small box is given to the Krawczyk operator K(X) = y - Y F(y) + (I - Y J(X))
// (X - y): K(X) inside X proves exactly one root in X (it is then polished by Newton); K(X)
// disjoint from X proves none. Near the planet axis (|Q_1z| > kPoleChart over the box) f and g
// carry a factor sin a3 and the test uses x and y of Q_i - W instead (`chart`): every root of
// (f, g) is one of these, and their mirror roots (Q_iz = -W_z) are dropped.
// `certified` means every box ended one of these ways: the solutions are ALL the trains through
// the points with a2, a3 in [1e-6, pi - 1e-6], none twice. Otherwise (a box below kMinBoxWidth
// still undecided — a singular root, e.g. a point exactly at a cusp — or more than max_boxes
// boxes) the solutions found are returned with certified = false and the count of undecided boxes.
// Cost: grows with q (Delta spans 2 pi q); measured in bench/ and the README.
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/synthesis/precision_points.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/core/types.hpp"
#include "sphtroch/interval/interval.hpp"
#include "sphtroch/interval/root_isolation.hpp"
#include "sphtroch/synthesis/precision_solution.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <type_traits>
#include <utility>
#include <string>
#include <vector>

namespace sphtroch {

/// All trains of ratio n through the three points (fixed frame). Throws InvalidInput (field
/// "points") for a count other than 3, non-finite or non-unit points, or two points closer than
/// kDistinctPoints.
inline PrecisionPoints precision_points(const std::vector<Vector3d>& points, const Ratio& n,
                                        const PrecisionPointsOptions& options = {});

// Implementation details follow.
namespace precision_detail {

/// Q = Rx(-a2) Rz(-theta) P and its derivatives by theta and by a2 (P: any x, y, z indexable
/// by [0], [1], [2]; linear in P).
template <typename T>
struct CarrierView {
  T q[3];
  T d_theta[3];  // (r2, -cos a2 r1, sin a2 r1)
  T d_a2[3];     // (0, q_z, -q_y)
};

/// {sin, cos} of one angle (interval.hpp).
template <typename T>
using SinCos = std::pair<T, T>;

template <typename T, typename Point>
CarrierView<T> carrier_view(const T& ca, const T& sa, const SinCos<T>& theta, const Point& p) {
  const T &s = theta.first, &c = theta.second;
  const T r1 = c * p[0] + s * p[1];
  const T r2 = c * p[1] - s * p[0];
  CarrierView<T> v{{r1, ca * r2 + sa * p[2], ca * p[2] - sa * r2},
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
  T dx, dy;            // Q_ix - W_x, Q_iy - W_y: also zero at a root; f and g carry a factor sin a3
  T ddx[3], ddy[3];    // near the planet axis, these do not, so they prune there (may_hold)
};

/// W = Rz(n Delta) Q_1, the right side of the point equation, in x and y.
template <typename T>
std::pair<T, T> turned(const SinCos<T>& n_delta, const T q1[3]) {
  const T &s = n_delta.first, &c = n_delta.second;
  return {c * q1[0] - s * q1[1], s * q1[0] + c * q1[1]};
}

/// theta_i = theta_1 + Delta and n Delta enter through their sines and cosines.
template <typename T, typename Point>
PointEquations<T> point_equations(const T& ca, const T& sa, const CarrierView<T>& q1, const SinCos<T>& theta_i,
                                  const SinCos<T>& n_delta, const T& n, const Point& p, bool jacobian) {
  const CarrierView<T> qi = carrier_view(ca, sa, theta_i, p);
  const T &s = n_delta.first, &c = n_delta.second;
  const auto [wx, wy] = turned(n_delta, q1.q);
  PointEquations<T> e;
  e.f = qi.q[2] - q1.q[2];
  e.g = qi.q[0] * wy - qi.q[1] * wx;
  e.dot = qi.q[0] * wx + qi.q[1] * wy;
  e.dx = qi.q[0] - wx;
  e.dy = qi.q[1] - wy;
  if (!jacobian) return e;
  const T dwx[3] = {-(s * q1.q[2]), c * q1.d_theta[0] - s * q1.d_theta[1], -(n * wy)};
  const T dwy[3] = {c * q1.q[2], s * q1.d_theta[0] + c * q1.d_theta[1], n * wx};
  const T dqx[3] = {T(0.0), qi.d_theta[0], qi.d_theta[0]};
  const T dqy[3] = {qi.q[2], qi.d_theta[1], qi.d_theta[1]};
  e.df[0] = qi.d_a2[2] - q1.d_a2[2];
  e.df[1] = qi.d_theta[2] - q1.d_theta[2];
  e.df[2] = qi.d_theta[2];
  for (int k = 0; k < 3; ++k) {
    e.dg[k] = dqx[k] * wy + qi.q[0] * dwy[k] - dqy[k] * wx - qi.q[1] * dwx[k];
    e.ddx[k] = dqx[k] - dwx[k];
    e.ddy[k] = dqy[k] - dwy[k];
  }
  return e;
}

/// {sin, cos} of x + y from those of x and y (thin intervals stay thin: a few ulps wider).
inline SinCos<Interval> angle_sum(const SinCos<Interval>& x, const SinCos<Interval>& y) {
  return {x.first * y.second + x.second * y.first, x.second * y.second - x.first * y.first};
}

/// {sin, cos} of x + y over boxes X, Y in mean-value form about the sum c of their middles:
/// sin(c) + cos(X + Y) d and cos(c) - sin(X + Y) d, d an enclosure of X + Y - c, clipped to
/// [-1, 1]. The trig of X + Y (wide: angle sums overestimate it) only meets the small d, so the
/// form is first-order sharp, with no library call. boxes, centres: {sin, cos} of X and Y, of
/// their middles.
inline SinCos<Interval> sum_mean_value(const std::array<SinCos<Interval>, 2>& boxes,
                                       const std::array<SinCos<Interval>, 2>& centres, const Interval& d) {
  const SinCos<Interval> wide = angle_sum(boxes[0], boxes[1]), centre = angle_sum(centres[0], centres[1]);
  const auto clip = [](const Interval& v) { return Interval(std::max(v.inf(), -1.0), std::min(v.sup(), 1.0)); };
  return {clip(centre.first + wide.second * d), clip(centre.second - wide.first * d)};
}

/// The combination nu_u u + nu_v v with nu = (dv/dDelta, -du/dDelta) at the box's middle, in
/// mean-value form: its Delta coefficient is O(width), so the Delta interval hardly widens it (u
/// and v vanish at a root for one Delta; tested apart they may vanish for different ones).
inline Interval delta_free_combination(const Interval& u, const Interval& v, const Interval du[3], const Interval dv[3],
                                       const Interval dx[3]) {
  const std::array<double, 2> nu{0.5 * (dv[2].inf() + dv[2].sup()), -0.5 * (du[2].inf() + du[2].sup())};
  return combined_mean_value<2, 3>(nu, {u, v}, {du, dv}, dx);
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

/// How far the theta_1 domain reaches past each end of [0, 2 pi]: a root at theta_1 = 0 (a point
/// at a trace's first sample) lies inside the domain, not on an edge a box cannot be certified
/// across; its copy at 2 pi is the same train (dropped as a repeat), and boxes wholly outside
/// [0, 2 pi] are dropped (so that a root on the overlap's own edge is never left undecided).
constexpr double kTheta1Overlap = 1.0 / 16;

inline Interval theta1_domain() {
  return Interval(-kTheta1Overlap, 2 * Constants<double>::pi() + kTheta1Overlap);
}
inline bool outside_theta1_period(const Interval& theta1) {
  return theta1.sup() < 0.0 || theta1.inf() > 2 * Constants<double>::pi();
}

}  // namespace precision_detail

// Building blocks shared with the free-axis solver (synthesis/free_axis_points.hpp).

/// Points given as unit vectors: checked (count, finite, |P| within kPrecisionUnitTolerance of 1,
/// no two closer than kDistinctPoints) and normalised. Throws InvalidInput (field "points").
inline std::vector<Vector3d> checked_precision_points(const std::vector<Vector3d>& points, std::size_t count,
                                                     const std::string& problem) {
  if (points.size() != count)
    throw InvalidInput("points", std::to_string(points.size()) + " points",
                       problem + " needs exactly " + std::to_string(count),
                       std::to_string(count) + " points x,y,z on the unit sphere (3: sun axis Z; 5: sun axis free)");
  std::vector<Vector3d> out;
  for (std::size_t i = 0; i < count; ++i) {
    const Vector3d& p = points[i];
    const double norm = p.norm();
    if (!std::isfinite(norm) || std::fabs(norm - 1.0) > kPrecisionUnitTolerance)
      throw InvalidInput("points", "point " + std::to_string(i + 1) + " with |P| = " + number_text(norm),
                         "not on the unit sphere", "|P| within 1e-6 of 1");
    out.push_back(p / norm);
    for (std::size_t j = 0; j < i; ++j)
      if ((out[i] - out[j]).norm() < kDistinctPoints)
        throw InvalidInput("points", "points " + std::to_string(j + 1) + " and " + std::to_string(i + 1),
                           "the same point twice", "distinct points (chord >= 1e-9)");
  }
  return out;
}

/// n as a certified interval (p / q rounded outward).
inline Interval ratio_enclosure(const Ratio& n) {
  const RoundingGuard upward;
  return Interval(double(n.p())) / Interval(double(n.q()));
}

/// n in the type of an evaluation: the nearest double, or (Interval) its enclosure.
template <typename T>
T ratio_as(const Ratio& n, const Interval& enclosure) {
  if constexpr (std::is_same_v<T, double>)
    return n.value();
  else
    return enclosure;
}

/// The train of a root given the carrier twist, point 1 seen from the carrier (Q_1) and the
/// carrier angle of every point (theta_1 first): a3 = acos(Q_1z), theta_p = atan2(Q_1x, -Q_1y) -
/// n theta_1, the phase reduced to [0, 2 pi / q) and the angles shifted by the matching 2 pi k
/// into [0, 2 pi q). None when a3 is outside [kMinCarrierTwist, pi - kMinCarrierTwist].
namespace precision_detail {

/// (m, r) with phase = m sector + r and r in [0, sector), to rounding: phase / sector may round to
/// an integer m from either side, leaving phase - m sector a few ulp below 0 (then r = 0: the
/// curve moves by that much) or at sector (then m + 1). REQUIRES sector > 0, phase finite.
inline std::pair<double, double> reduce_to_sector(double phase, double sector) {
  double m = std::floor(phase / sector), r = phase - m * sector;
  if (r >= sector) {
    m += 1;
    r -= sector;
  }
  return {m, std::clamp(r, 0.0, std::nextafter(sector, 0.0))};
}

}  // namespace precision_detail

inline std::optional<PrecisionSolution> train_through_points(const Ratio& ratio, double a2, const double q1[3],
                                                             const std::vector<double>& thetas, bool isolated) {
  const double two_pi = 2 * Constants<double>::pi();
  const std::int64_t q = ratio.q();
  const double a3 = std::acos(std::clamp(q1[2], -1.0, 1.0));
  if (!(a3 >= kMinCarrierTwist && a3 <= Constants<double>::pi() - kMinCarrierTwist)) return std::nullopt;
  const double phase = std::atan2(q1[0], -q1[1]) - ratio.value() * thetas[0];
  const double sector = two_pi / static_cast<double>(q);
  const auto [m, reduced] = precision_detail::reduce_to_sector(phase, sector);
  const std::int64_t m_mod = static_cast<std::int64_t>(std::fmod(std::fmod(m, double(q)) + double(q), double(q)));
  const std::int64_t k = (m_mod * precision_detail::inverse_mod(ratio.p(), q)) % q;
  PrecisionSolution s{GearTrain(a2, a3, ratio, reduced), {}, 0.0, isolated};
  const double shift = two_pi * static_cast<double>(k), period = two_pi * static_cast<double>(q);
  for (const double t : thetas) s.params.push_back(std::fmod(std::fmod(t + shift, period) + period, period));
  return s;
}

/// Two trains that agree to 1e-9 (a2, a3, phase modulo 2 pi / q) in the same frame.
inline bool same_train_in_frame(const GearTrain& a, const GearTrain& b) {
  const double sector = 2 * Constants<double>::pi() / static_cast<double>(a.ratio().q());
  const double dp = std::fabs(std::remainder(a.phase_given() - b.phase_given(), sector));
  return std::fabs(a.a2() - b.a2()) < 1e-9 && std::fabs(a.a3() - b.a3()) < 1e-9 && dp < 1e-9;
}

/// The fixed-frame system for root_isolation.hpp: outer (a2, theta_1), lists Delta_2, Delta_3.
class FixedFrameSystem {
 public:
  using Solution = PrecisionSolution;
  static constexpr int kOuter = 2, kLists = 2, N = 4;
  static constexpr double kIsolateWidth = 1.0 / 1024;  // outer boxes this narrow go to Krawczyk
  static constexpr double kContractWidth = 1.0 / 64;   // below this, Krawczyk narrows outer boxes
  static constexpr double kListWidth = 1.0;  // list items split to this times the outer width (root_isolation.hpp)
  using Outer = std::array<Interval, kOuter>;

  /// Throws InvalidInput (field "points") as precision_points() does.
  FixedFrameSystem(const std::vector<Vector3d>& points, const Ratio& n)
      : FixedFrameSystem(checked_precision_points(points, 3, "a fixed-frame problem"), n, 0) {}

  std::vector<Outer> domains() const {
    return {{Interval(kMinCarrierTwist, Constants<double>::pi() - kMinCarrierTwist), precision_detail::theta1_domain()}};
  }
  bool outside(const Outer& x) const { return precision_detail::outside_theta1_period(x[1]); }
  double list_max() const { return 2 * Constants<double>::pi() * double(ratio_.q()); }
  double list_scale() const { return 1.0 + std::fabs(ratio_.value()); }  // Delta's widths after this factor

  /// Point 1 seen from the carrier over a box of (a2, theta_1) and at its centre.
  struct View {
    Interval a2, theta1, ca, sa;
    precision_detail::CarrierView<Interval> q1;
    Interval a2_centre, theta1_centre, ca_centre, sa_centre;
    precision_detail::CarrierView<Interval> q1_centre;
    precision_detail::SinCos<Interval> theta1_centre_trig, theta1_trig;
  };

  View view(const Outer& x) const {
    const Interval a2c = centre_of(x[0]), t1c = centre_of(x[1]);
    const auto trig = interval_sincos_all<4>({x[0], x[1], a2c, t1c});
    const Interval &sa = trig[0].first, &ca = trig[0].second, &sac = trig[2].first, &cac = trig[2].second;
    return {x[0], x[1], ca, sa, precision_detail::carrier_view(ca, sa, trig[1], p_[0]),
            a2c, t1c, cac, sac, precision_detail::carrier_view(cac, sac, trig[3], p_[0]), trig[3], trig[1]};
  }

  /// An interval of Delta_(i+2) with {sin, cos} of n Delta over it and at its centre, and of
  /// Delta at its centre, computed once for every outer box it meets.
  struct ListItem {
    Interval d, centre;  // the centre the trig at the middle and the mean-value forms both use
    std::array<precision_detail::SinCos<Interval>, 4> trig;  // n d, n centre, centre, d
  };
  ListItem list_item(const Interval& d, int /*i*/) const {
    const Interval c = centre_of(d);
    return {d, c, interval_sincos_all<4>({n_interval_ * d, n_interval_ * c, c, d})};
  }

  /// Whether point i + 2 may satisfy its equations on (a2, theta_1) x item.d: the plain
  /// enclosure, the mean-value form F(c) + J(X) (X - c), and that form for the combinations of
  /// (f, g) and of (x, y) in which Delta's coefficient vanishes at the centre.
  bool may_hold(const View& v, const ListItem& item, int i) const {
    const Interval& delta = item.d;
    const Interval& dc = item.centre;
    const auto trig = precision_detail::sum_mean_value({v.theta1_trig, item.trig[3]}, {v.theta1_centre_trig, item.trig[2]},
                                                       (v.theta1 - v.theta1_centre) + (delta - dc));
    const auto e = precision_detail::point_equations(v.ca, v.sa, v.q1, trig, item.trig[0], n_interval_, p_[i + 1], true);
    if (!(may_vanish(e.f) && may_vanish(e.g) && may_vanish(e.dx) && may_vanish(e.dy) && e.dot.sup() > 0.0)) return false;
    const auto ec = precision_detail::point_equations(v.ca_centre, v.sa_centre, v.q1_centre,
                                                      precision_detail::angle_sum(v.theta1_centre_trig, item.trig[2]),
                                                      item.trig[1], n_interval_, p_[i + 1], false);
    const Interval dx[3] = {v.a2 - v.a2_centre, v.theta1 - v.theta1_centre, delta - dc};
    if (!(may_vanish(mean_value<3>(ec.f, e.df, dx)) && may_vanish(mean_value<3>(ec.g, e.dg, dx)) &&
          may_vanish(mean_value<3>(ec.dx, e.ddx, dx)) && may_vanish(mean_value<3>(ec.dy, e.ddy, dx))))
      return false;
    return may_vanish(precision_detail::delta_free_combination(ec.f, ec.g, e.df, e.dg, dx)) &&
           may_vanish(precision_detail::delta_free_combination(ec.dx, ec.dy, e.ddx, e.ddy, dx));
  }

  /// The formulation for a box of all unknowns: 1 (x and y of Q_i - W) where point 1 is within
  /// ~41 degrees of the planet axis over the whole box (|Q_1z| > kPoleChart: there f and g carry
  /// a factor sin a3, which the Krawczyk test cannot beat on boxes wider than a3), else 0 (f, g).
  /// Both have every true root; a root of chart 1 with Q_iz = -W_z is dropped by solution().
  template <typename Box>
  int chart(const Box& x) const {
    const auto trig = interval_sincos_all<2>({x[0], x[1]});
    const Interval z = precision_detail::carrier_view(trig[0].second, trig[0].first, trig[1], p_[0]).q[2];
    return z.inf() > kPoleChart || z.sup() < -kPoleChart ? 1 : 0;
  }

  /// F(x) and, if `jac`, J(x) in type T (double at a point, Interval over a box), in `chart`.
  template <typename T>
  void equations(const std::array<T, N>& x, std::array<T, N>& f, std::array<std::array<T, N>, N>* jac, int chart) const {
    const T n = ratio_as<T>(ratio_, n_interval_);
    const auto trig = interval_sincos_all(std::array<T, 6>{x[0], x[1], T(x[1] + x[2]), T(n * x[2]), T(x[1] + x[3]), T(n * x[3])});
    const T &sa = trig[0].first, &ca = trig[0].second;
    const precision_detail::CarrierView<T> q1 = precision_detail::carrier_view(ca, sa, trig[1], p_[0]);
    for (int i = 0; i < 2; ++i) {
      const auto e = precision_detail::point_equations(ca, sa, q1, trig[2 + 2 * i], trig[3 + 2 * i], n, p_[1 + i], jac != nullptr);
      f[2 * i] = chart == 1 ? e.dx : e.f;
      f[2 * i + 1] = chart == 1 ? e.dy : e.g;
      if (!jac) continue;
      for (int r = 0; r < 2; ++r) {
        const T* d = chart == 1 ? (r == 0 ? e.ddx : e.ddy) : (r == 0 ? e.df : e.dg);
        (*jac)[2 * i + r] = {d[0], d[1], T(0.0), T(0.0)};
        (*jac)[2 * i + r][2 + i] = d[2];
      }
    }
  }

  /// The train of a root (see train_through_points), unless it is a root of the sign-reversed system
  /// or lies outside the a3 range.
  std::optional<PrecisionSolution> solution(const std::array<double, N>& y, bool isolated) const {
    const double ca = std::cos(y[0]), sa = std::sin(y[0]);
    const precision_detail::CarrierView<double> q1 = precision_detail::carrier_view(ca, sa, interval_sincos(y[1]), p_[0]);
    for (int i = 0; i < 2; ++i) {
      const auto e = precision_detail::point_equations(ca, sa, q1, interval_sincos(y[1] + y[2 + i]), interval_sincos(ratio_.value() * y[2 + i]),
                                     ratio_.value(), p_[1 + i], false);
      // A mirror root of chart 1 (Q_iz = -W_z, |W_z| > kPoleChart) has |f| > 1.5; a true root,
      // polished or not, |f| < 0.5 (its box is narrower than kIsolateWidth).
      if (!(e.dot > 0.0) || !(std::fabs(e.f) < 0.5)) return std::nullopt;
    }
    auto s = train_through_points(ratio_, y[0], q1.q, {y[1], y[1] + y[2], y[1] + y[3]}, isolated);
    if (!s) return s;
    const TracerCurve<double> curve(s->train);
    for (int i = 0; i < 3; ++i) s->residual = std::max(s->residual, (curve.point(s->params[i]) - p_[i]).norm());
    return s;
  }

  bool same(const PrecisionSolution& a, const PrecisionSolution& b) const { return same_train_in_frame(a.train, b.train); }

 private:
  FixedFrameSystem(const std::vector<Vector3d>& checked, const Ratio& n, int /*checked already*/)
      : p_{checked[0], checked[1], checked[2]}, ratio_(n), n_interval_(ratio_enclosure(n)) {}

  static constexpr double kPoleChart = 0.75;

  Vector3d p_[3];
  Ratio ratio_;
  Interval n_interval_;
};

inline PrecisionPoints precision_points(const std::vector<Vector3d>& points, const Ratio& n,
                                        const PrecisionPointsOptions& options) {
  const FixedFrameSystem system(points, n);  // checks the points
  PrecisionPoints r = RootIsolation<FixedFrameSystem>(system, options.max_boxes).run();
  sort_solutions(r);
  return r;
}

}  // namespace sphtroch
