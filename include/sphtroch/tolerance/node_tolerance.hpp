// sphtroch/tolerance/node_tolerance.hpp — how far the nodes and cusps of a train move
// when its twists and phase move within a tolerance box: a certified enclosure of each node over
// the box and the first-order sensitivities of its position.
//
//   const sphtroch::Node node = sphtroch::classify(train).nodes.front();   // a node of the train
//   const sphtroch::NodeTolerance t = sphtroch::node_tolerance(train, node, {1e-3, 1e-3, 0.0});
//   t.max_displacement;              // radians on the sphere, proved (nothing if not proved)
//   t.d_da2, t.d_da3, t.d_dphase;    // dX/da2, dX/da3, dX/dphase at the nominal train
//
// Model (Eq. 4): P(s) = Rz(s) Rx(a2) Rz(n s + phase) Rx(a3) z. A crossing node X = P(s) = P(t)
// (s != t: two of its branches, params[0] and params[1]) persists while the census holds; with
// J = [P'(s), -P'(t)] (3 x 2, rank 2 at a crossing) the implicit-function theorem gives
// (ds, dt) = -(J^T J)^-1 J^T (P_a(s) - P_a(t)) and dX/da = P_a(s) + P'(s) ds for a = a2, a3, phase
// (P_a the partial derivative at fixed s). A phase change turns the curve about Z:
// P(s; phase + d) = Rz(-d/n) P(s + d/n; phase), so dX/dphase = -(Z x X)/n for every node and cusp.
// Enclosure: the equations E^T (P(s) - P(t)) = 0, E an orthonormal basis of the tangent plane at
// X, over the box of (a2, a3, phase) in intervals, in the rest (u, v) = (s, t) - (s0, t0) - sigma da
// left by the sensitivities sigma (second order in the box): a Krawczyk test on a square rest box
// (radius (the box's summed widths)^2, grown fourfold to 0.5; krawczyk.hpp's step about the rest 0, Y
// the inverse at the nominal train) proves one solution for every train
// of the box and encloses it; the position follows in mean-value form about the box's centre,
// X(ac) + (dX/da)(a - ac) + P' u, with dX/da enclosed over the box (first-order sharp). Where the
// test fails (a crossing at a small angle, a wide box) the box is halved, up to kNodeBoxCuts times; max_displacement is the largest angle
// from X to P over that enclosure. A cusp (on a pitch cone only) has d_da2, d_da3 undefined: off
// the cone it is no cusp; its enclosure is given for a box that fixes a2 and a3 (a rotation about Z).
// REQUIRES: the train's twists and the box inside (0, pi); throws nothing.
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/tolerance/node_tolerance.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/node.hpp"
#include "sphtroch/core/types.hpp"
#include "sphtroch/interval/krawczyk.hpp"
#include "sphtroch/tolerance/tolerance_types.hpp"

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <optional>

namespace sphtroch {


/// How many times node_tolerance may halve the tolerance box where its test fails (<= 2^6 parts).
constexpr int kNodeBoxCuts = 6;


/// The tolerance of one crossing node (see header).
inline NodeTolerance node_tolerance(const GearTrain& train, const Node& node, const ToleranceBox& box);
/// The tolerance of one cusp (see header).
inline NodeTolerance cusp_tolerance(const GearTrain& train, const Cusp& cusp, const ToleranceBox& box);

// ------------------------------------------------------------------------------------------------

namespace node_tolerance_detail {

/// P at s and its derivatives: by s (total: theta3 = n s + phase), by a2, a3 and phase.
template <typename T>
struct TracerJet {
  std::array<T, 3> p, ds, da2, da3, dphase;
};

template <typename T>
std::array<T, 3> rz(const T& s, const T& c, const std::array<T, 3>& w) {
  return {c * w[0] - s * w[1], s * w[0] + c * w[1], w[2]};
}
template <typename T>
std::array<T, 3> rx(const T& s, const T& c, const std::array<T, 3>& v) {
  return {v[0], c * v[1] - s * v[2], s * v[1] + c * v[2]};
}

/// The jet at parameter s; n as T (a double or its interval enclosure).
template <typename T>
TracerJet<T> tracer_jet(const T& s, const T& a2, const T& a3, const T& phase, const T& n) {
  const auto [ss, cs] = interval_sincos(s);
  const auto [s2, c2] = interval_sincos(a2);
  const auto [s3a, c3a] = interval_sincos(a3);
  const auto [s3, c3] = interval_sincos(n * s + phase);
  const T zero(0);
  const std::array<T, 3> v{s3 * s3a, -c3 * s3a, c3a};            // Rz(theta3) Rx(a3) z
  const std::array<T, 3> v_t{c3 * s3a, s3 * s3a, zero};          // d v / d theta3
  const std::array<T, 3> v_a3{s3 * c3a, -c3 * c3a, -s3a};        // d v / d a3
  const std::array<T, 3> w = rx(s2, c2, v);
  const std::array<T, 3> w_a2{zero, -s2 * v[1] - c2 * v[2], c2 * v[1] - s2 * v[2]};
  TracerJet<T> j;
  j.p = rz(ss, cs, w);
  const std::array<T, 3> turn{-ss * w[0] - cs * w[1], cs * w[0] - ss * w[1], zero};  // d Rz / ds applied to w
  j.dphase = rz(ss, cs, rx(s2, c2, v_t));
  for (int k = 0; k < 3; ++k) j.ds[k] = turn[k] + n * j.dphase[k];
  j.da2 = rz(ss, cs, w_a2);
  j.da3 = rz(ss, cs, rx(s2, c2, v_a3));
  return j;
}

inline Vector3d vec(const std::array<double, 3>& a) { return Vector3d(a[0], a[1], a[2]); }

/// -(Z x X)/n: the velocity of a point of the curve under a phase change.
inline Vector3d phase_rotation(const Vector3d& x, const Ratio& n) {
  return Vector3d(-Vector3d::UnitZ().cross(x) / n.value()) + Vector3d::Zero();  // + 0: no -0 in reports
}

/// The largest angle a turn about Z by at most d moves the unit vector x: 2 asin(sin(colatitude)
/// sin(d/2)) for d <= pi, rounded up (1e-14 relative covers the library's few ulps).
inline double rotation_move(const Vector3d& x, double d) {
  const double pi = Constants<double>::pi();
  const double sine = std::min(1.0, std::sqrt(x.x() * x.x() + x.y() * x.y()));
  const double half = std::min(d, pi) / 2;
  return std::min(pi, 2 * std::asin(std::min(1.0, sine * std::sin(half))) * (1 + 1e-14) + 1e-300);
}

/// The largest angle between the unit vector x and a point of the box b (componentwise), upper bound.
inline double angle_to_box(const Vector3d& x, const std::array<Interval, 3>& b) {
  Interval chord2(0.0);
  for (int k = 0; k < 3; ++k) chord2 += square(b[k] - x[k]);
  const double chord = std::sqrt(chord2.sup()) * (1 + 1e-15);
  return chord >= 2 ? Constants<double>::pi() : 2 * std::asin(std::min(1.0, chord / 2)) * (1 + 1e-15) + 1e-300;
}

/// The node's branch parameters over the box: s = s0 + sigma_s . da + u, t = t0 + sigma_t . da + v
/// (sigma: the implicit-function sensitivities, da = a - a0 over the box of (a2, a3, phase)), with
/// (u, v) the second-order rest that the Krawczyk test encloses.
struct NodeParameters {
  double s0 = 0, t0 = 0;
  Eigen::Matrix<double, 2, 3> sigma = Eigen::Matrix<double, 2, 3>::Zero();
};

/// A part of the tolerance box: its intervals, their offsets from the nominal a0 and from the
/// part's centre ac (the expansion point of the mean-value forms, inside the part).
struct BoxIntervals {
  std::array<Interval, 3> a, da, dc;
  std::array<double, 3> ac{};
  Interval n;
};

/// The part [lo, hi] (per parameter a2, a3, phase) of the box about the nominal train.
inline BoxIntervals box_intervals(const GearTrain& train, const std::array<double, 3>& lo, const std::array<double, 3>& hi) {
  const std::array<double, 3> a0{train.a2(), train.a3(), train.phase()};
  BoxIntervals b;
  for (int k = 0; k < 3; ++k) {
    b.a[k] = Interval(lo[k], hi[k]);
    b.da[k] = b.a[k] - a0[k];
    b.ac[k] = lo[k] + 0.5 * (hi[k] - lo[k]);
    b.dc[k] = b.a[k] - b.ac[k];
  }
  b.n = Interval(static_cast<double>(train.ratio().p())) / static_cast<double>(train.ratio().q());
  return b;
}

/// The predicted branch parameter at the part's centre: s0 + sigma . (ac - a0), as an interval.
inline Interval centre_parameter(double base, const Eigen::Matrix<double, 2, 3>& sigma, int branch, const BoxIntervals& b,
                                 const std::array<double, 3>& a0) {
  Interval r(base);
  for (int k = 0; k < 3; ++k) r += sigma(branch, k) * (Interval(b.ac[k]) - a0[k]);
  return r;
}

/// Over the box and the rest box UV: {s range, t range}.
inline std::array<Interval, 2> parameter_ranges(const NodeParameters& np, const BoxIntervals& b, const std::array<Interval, 2>& uv) {
  std::array<Interval, 2> r{Interval(np.s0) + uv[0], Interval(np.t0) + uv[1]};
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < 3; ++k) r[i] += np.sigma(i, k) * b.da[k];
  return r;
}

/// dX/da along the node (P_s sigma + P_a) from a jet over the ranges, for one branch.
inline std::array<Interval, 3> along(const TracerJet<Interval>& j, const Eigen::Matrix<double, 2, 3>& sigma, int branch, int k) {
  std::array<Interval, 3> d;
  const std::array<Interval, 3>* pa[3] = {&j.da2, &j.da3, &j.dphase};
  for (int c = 0; c < 3; ++c) d[c] = j.ds[c] * sigma(branch, k) + (*pa[k])[c];
  return d;
}

/// The Krawczyk image of the rest box UV (centred at 0); the test passes when it lies inside UV
/// (then UV holds exactly one rest for each train, and the image holds it).
inline std::optional<std::array<Interval, 2>> rest_step(const NodeParameters& np, const BoxIntervals& b, const std::array<Interval, 2>& UV,
                                                       const Eigen::Matrix<double, 3, 2>& E, const Eigen::Matrix2d& Y,
                                                       const std::array<double, 3>& a0) {
  const auto st = parameter_ranges(np, b, UV);
  const auto js = tracer_jet<Interval>(st[0], b.a[0], b.a[1], b.a[2], b.n), jt = tracer_jet<Interval>(st[1], b.a[0], b.a[1], b.a[2], b.n);
  // G at u = v = 0 over the part, in mean-value form about its centre: G(ac) + sum_k dG/da_k (a_k - ac_k).
  const std::array<Interval, 3> ac{Interval(b.ac[0]), Interval(b.ac[1]), Interval(b.ac[2])};
  const auto cs = tracer_jet<Interval>(centre_parameter(np.s0, np.sigma, 0, b, a0), ac[0], ac[1], ac[2], b.n);
  const auto ct = tracer_jet<Interval>(centre_parameter(np.t0, np.sigma, 1, b, a0), ac[0], ac[1], ac[2], b.n);
  std::array<Interval, 2> g;
  for (int i = 0; i < 2; ++i) {
    g[i] = Interval(0.0);
    for (int q = 0; q < 3; ++q) g[i] += E(q, i) * (cs.p[q] - ct.p[q]);
  }
  for (int k = 0; k < 3; ++k) {
    const auto ds = along(js, np.sigma, 0, k), dt = along(jt, np.sigma, 1, k);
    for (int i = 0; i < 2; ++i) {
      Interval c(0.0);
      for (int q = 0; q < 3; ++q) c += E(q, i) * (ds[q] - dt[q]);
      g[i] += c * b.dc[k];
    }
  }
  IntervalMatrix<2> J;
  for (int i = 0; i < 2; ++i) {
    J[i][0] = J[i][1] = Interval(0.0);
    for (int q = 0; q < 3; ++q) {
      J[i][0] += E(q, i) * js.ds[q];
      J[i][1] -= E(q, i) * jt.ds[q];
    }
  }
  // The step about the rest 0 (krawczyk.hpp): g encloses G(0) for every train of the part.
  const KrawczykStep<2> K = krawczyk_step<2>(UV, PointN<2>{0.0, 0.0}, g, J, Y);
  if (K.verdict != KrawczykVerdict::unique) return std::nullopt;
  return K.box;
}

/// The enclosure of X over a part of the box, from the rest box [-r, r]^2: a Krawczyk test, then
/// three more steps on the image (each image still holds the rest); nothing if the test fails.
inline std::optional<std::array<Interval, 3>> enclose(const GearTrain& train, const NodeParameters& np, double r, const BoxIntervals& b,
                                                      const Vector3d& x, const Eigen::Matrix<double, 3, 2>& E, const Eigen::Matrix2d& Y) {
  const std::array<double, 3> a0{train.a2(), train.a3(), train.phase()};
  std::optional<std::array<Interval, 2>> K = rest_step(np, b, {Interval(-r, r), Interval(-r, r)}, E, Y, a0);
  if (!K) return std::nullopt;
  for (int step = 0; step < 3; ++step) {
    const auto next = rest_step(np, b, {Interval(std::min(K->at(0).inf(), 0.0), std::max(K->at(0).sup(), 0.0)),
                                       Interval(std::min(K->at(1).inf(), 0.0), std::max(K->at(1).sup(), 0.0))}, E, Y, a0);
    if (!next) break;
    K = next;
  }
  const auto st = parameter_ranges(np, b, *K);
  const auto js = tracer_jet<Interval>(st[0], b.a[0], b.a[1], b.a[2], b.n), jt = tracer_jet<Interval>(st[1], b.a[0], b.a[1], b.a[2], b.n);
  // G = 0 makes P(s) - P(t) parallel to x; both unit and on x's side, it is then 0 (a node).
  Interval side_s(0.0), side_t(0.0);
  for (int q = 0; q < 3; ++q) {
    side_s += x[q] * js.p[q];
    side_t += x[q] * jt.p[q];
  }
  if (!(side_s.inf() > 0 && side_t.inf() > 0)) return std::nullopt;
  // X = P(s(a); a) over the part, in mean-value form about its centre (s there: the prediction + u).
  const std::array<Interval, 3> ac{Interval(b.ac[0]), Interval(b.ac[1]), Interval(b.ac[2])};
  const auto j0 = tracer_jet<Interval>(centre_parameter(np.s0, np.sigma, 0, b, a0), ac[0], ac[1], ac[2], b.n);
  std::array<Interval, 3> x_box;
  for (int q = 0; q < 3; ++q) x_box[q] = j0.p[q] + js.ds[q] * (*K)[0];
  for (int k = 0; k < 3; ++k) {
    const auto d = along(js, np.sigma, 0, k);
    for (int q = 0; q < 3; ++q) x_box[q] += d[q] * b.dc[k];
  }
  return x_box;
}

/// The largest angle from x over the part [lo, hi], cutting it (the widest parameter in halves)
/// where the test fails, down to `depth` more cuts; nothing if a part stays unproved.
inline std::optional<double> largest_move(const GearTrain& train, const NodeParameters& np, const std::array<double, 3>& lo,
                                          const std::array<double, 3>& hi, const Vector3d& x, const Eigen::Matrix<double, 3, 2>& E,
                                          const Eigen::Matrix2d& Y, int depth) {
  const BoxIntervals b = box_intervals(train, lo, hi);
  const double spread = (hi[0] - lo[0]) + (hi[1] - lo[1]) + (hi[2] - lo[2]);
  for (double radius = spread * spread + 1e-13; radius < 0.5; radius *= 4)
    if (const auto enclosure = enclose(train, np, radius, b, x, E, Y)) return angle_to_box(x, *enclosure);
  if (depth == 0) return std::nullopt;
  int widest = 0;
  for (int k = 1; k < 3; ++k)
    if (hi[k] - lo[k] > hi[widest] - lo[widest]) widest = k;
  std::array<double, 3> mid_hi = hi, mid_lo = lo;
  mid_hi[widest] = mid_lo[widest] = lo[widest] + 0.5 * (hi[widest] - lo[widest]);
  const auto left = largest_move(train, np, lo, mid_hi, x, E, Y, depth - 1);
  if (!left) return std::nullopt;
  const auto right = largest_move(train, np, mid_lo, hi, x, E, Y, depth - 1);
  if (!right) return std::nullopt;
  return std::max(*left, *right);
}

}  // namespace node_tolerance_detail

inline NodeTolerance node_tolerance(const GearTrain& train, const Node& node, const ToleranceBox& box) {
  namespace d = node_tolerance_detail;
  NodeTolerance r;
  r.position = node.position;
  r.d_dphase = d::phase_rotation(node.position, train.ratio());
  // The phase turns the whole curve about Z by at most dphase/|n|: its move adds to that of the
  // (a2, a3) box at the nominal phase (triangle inequality), exactly bounded.
  const double turn = d::rotation_move(node.position, box.dphase / std::fabs(train.n()));
  if (box.da2 == 0 && box.da3 == 0) r.max_displacement = turn;
  if (node.params.size() < 2 || node.kind != NodeKind::crossing) return r;
  d::NodeParameters np;
  np.s0 = node.params[0];
  np.t0 = node.params[1];
  const auto js = d::tracer_jet<double>(np.s0, train.a2(), train.a3(), train.phase(), train.ratio().value());
  const auto jt = d::tracer_jet<double>(np.t0, train.a2(), train.a3(), train.phase(), train.ratio().value());
  Eigen::Matrix<double, 3, 2> J;
  J.col(0) = d::vec(js.ds);
  J.col(1) = -d::vec(jt.ds);
  const Eigen::Matrix2d normal = J.transpose() * J;
  if (!(std::fabs(normal.determinant()) > 1e-24)) return r;
  const Eigen::Matrix2d inverse = normal.inverse();
  const std::array<double, 3>* ps[3] = {&js.da2, &js.da3, &js.dphase};
  const std::array<double, 3>* pt[3] = {&jt.da2, &jt.da3, &jt.dphase};
  for (int k = 0; k < 3; ++k) np.sigma.col(k) = -inverse * J.transpose() * (d::vec(*ps[k]) - d::vec(*pt[k]));
  r.d_da2 = Vector3d(d::vec(js.da2) + d::vec(js.ds) * np.sigma(0, 0));
  r.d_da3 = Vector3d(d::vec(js.da3) + d::vec(js.ds) * np.sigma(0, 1));
  // Tangent basis at X; Y: the inverse of the tangent-plane Jacobian at the nominal train.
  const Vector3d x = node.position.normalized();
  const Vector3d e1 = (std::fabs(x.z()) < 0.9 ? Vector3d::UnitZ() : Vector3d::UnitX()).cross(x).normalized();
  Eigen::Matrix<double, 3, 2> E;
  E.col(0) = e1;
  E.col(1) = x.cross(e1);
  const Eigen::Matrix2d Jt = E.transpose() * J;
  if (!(std::fabs(Jt.determinant()) > 1e-12)) return r;  // a crossing at too small an angle
  const std::optional<Eigen::Matrix2d> Y = midpoint_inverse<2>(Jt);
  if (!Y || (box.da2 == 0 && box.da3 == 0)) return r;
  const RoundingGuard upward;
  const std::array<double, 3> lo{train.a2() - box.da2, train.a3() - box.da3, train.phase()};
  const std::array<double, 3> hi{train.a2() + box.da2, train.a3() + box.da3, train.phase()};
  const std::optional<double> move = d::largest_move(train, np, lo, hi, x, E, *Y, kNodeBoxCuts);
  if (move) r.max_displacement = (Interval(*move) + turn).sup();
  return r;
}

inline NodeTolerance cusp_tolerance(const GearTrain& train, const Cusp& cusp, const ToleranceBox& box) {
  namespace d = node_tolerance_detail;
  NodeTolerance r;
  r.position = cusp.position;
  r.d_dphase = d::phase_rotation(cusp.position, train.ratio());
  if (box.da2 == 0 && box.da3 == 0) r.max_displacement = d::rotation_move(cusp.position, box.dphase / std::fabs(train.n()));
  return r;
}

}  // namespace sphtroch
